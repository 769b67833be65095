// TIFF through libtiff, the part the reader (tiff.cpp) and the writer (tiff_write.cpp) share: the
// GeoTIFF and GDAL tags, the byte stream libtiff reads and writes (memory, a file, the caller's
// sink), and libtiff's messages for one handle.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include <tiffio.h>

#include "algorithms/imaging/image.h"
#include "imageio/row_writer.h"

namespace erd::imageio::tiff_io {

// The GeoTIFF tags and GDAL's nodata tag, which libtiff does not know: registered on a handle that
// writes them (a reader sees them as libtiff's anonymous fields, which read the same way).
inline constexpr ttag_t kPixelScale = 33550, kTiepoint = 33922, kTransform = 34264, kGeoKeys = 34735, kGeoDoubles = 34736,
                 kGeoAscii = 34737, kGdalNodata = 42113;
inline const TIFFFieldInfo kGeoFields[] = {
    {kPixelScale, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelPixelScaleTag")},
    {kTiepoint, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelTiepointTag")},
    {kTransform, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelTransformationTag")},
    {kGeoKeys, -1, -1, TIFF_SHORT, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoKeyDirectoryTag")},
    {kGeoDoubles, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoDoubleParamsTag")},
    {kGeoAscii, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GeoAsciiParamsTag")},
    {kGdalNodata, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDAL_NODATA")},
};

// The bytes libtiff reads from or writes to: memory, a file, or the caller's sink.
struct Stream {
    const unsigned char* data = nullptr;  // reading memory
    std::uint64_t size = 0;
    std::string* out = nullptr;           // writing memory
    std::FILE* file = nullptr;            // reading a file
    ByteSink* sink = nullptr;             // writing (and reading back) the caller's file
    std::uint64_t pos = 0;
};

// libtiff's messages for one handle: the first error kept (one line), warnings dropped (unknown
// tags, such as the GeoTIFF ones, are warnings).
struct Messages {
    std::string error;
};

// A libtiff handle on s (mode "r" or "w"), its errors to *msg, single allocations capped at
// max_alloc bytes (0: libtiff's own cap); nullptr when libtiff refuses.
TIFF* open_stream(Stream* s, const char* mode, Messages* msg, std::uint64_t max_alloc);

// The first error libtiff reported, else fallback.
std::string why(const Messages& m, const std::string& fallback);

// Bytes of one sample of type t.
int bytes_of(SampleType t);

}  // namespace erd::imageio::tiff_io
