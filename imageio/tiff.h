// TIFF and GeoTIFF (issue 47): read and written through libtiff (Debian libtiff-dev), behind the
// fences of the other decoders: the directory's sizes, sample layout and block sizes are checked
// against the limits before any pixel is decoded, and libtiff's own allocations are capped.
//
// Read: unsigned 8/16/32-bit, signed 16/32-bit and IEEE float 32/64-bit samples; 1 or 3 samples a
// pixel (2 and 4: the extra one, alpha, dropped with a warning; 8-bit palettes become RGB);
// strips or tiles, contiguous or planar; any compression this libtiff decodes. GeoTIFF's tags
// (ModelPixelScale, ModelTiepoint, ModelTransformation, GeoKeyDirectory, GeoDoubleParams,
// GeoAsciiParams) and GDAL_NODATA (42113) land in Image::meta. An unsigned 8- or 16-bit image
// without nodata pixels is an integer Image (maxval 255 or 65535), any other a real one
// (algorithms/imaging/real_image.h): NaN samples and those equal to GDAL_NODATA are nodata.
//
// Windows (issue 48): TiffReader reads any rectangle of the raster, decoding only the strips or
// tiles it meets, from memory or from a file it reads as it goes.
//
// Written: a real image in its meta.type (integers rounded and clamped to the type), nodata pixels
// as meta.nodata with the GDAL_NODATA tag (NaN for float types without a value), the GeoTIFF tags
// of meta.geo as they are; an integer image as 8- or 16-bit. Deflate with a predictor, strips.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "imageio/row_writer.h"
#include "kernel/status.h"

namespace erd::imageio {

// What the first image of a TIFF holds, from its directory (nothing decoded yet).
struct TiffInfo {
    int width = 0, height = 0;
    int channels = 1;           // 1 or 3 as read (alpha dropped, palettes expanded)
    int file_samples = 1;       // samples per pixel in the file (2 and 4: with alpha)
    int bits = 8;               // bits per sample
    bool tiled = false;         // tiles, else strips
    bool planar = false;        // one plane per sample (PlanarConfiguration 2)
    bool palette = false;       // 8-bit palette: indices into a colour map
    bool min_is_white = false;  // unsigned samples, 0 is white
    std::uint32_t block_width = 0, block_height = 0;  // a tile, or a strip (the width x rows per strip)
    std::uint16_t compression = 1;
    RasterMeta meta;            // the sample type, GDAL_NODATA, the GeoTIFF tags
};

class TiffReader {
public:
    TiffReader();
    ~TiffReader();
    TiffReader(const TiffReader&) = delete;
    TiffReader& operator=(const TiffReader&) = delete;

    // Opens a TIFF in memory (the bytes must outlive the reader) and checks its first directory.
    Status open(const unsigned char* data, std::size_t size, const ImageLimits& limits = ImageLimits());
    // The same for a file, read only as far as the windows asked for need.
    Status open_file(const std::string& path, const ImageLimits& limits = ImageLimits());

    const TiffInfo& info() const;

    // The window x0 <= x < x1, y0 <= y < y1 as an Image (integer or real as the header says; nodata
    // as meta says), decoding only the strips or tiles it meets. Warnings (dropped alpha) are
    // appended to *warning (may be null).
    Status read(int x0, int y0, int x1, int y1, Image* out, std::string* warning = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The whole first image of a TIFF in memory.
Status decode_tiff(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                   const ImageLimits& limits = ImageLimits());

// TIFF bytes of an image (see the header comment).
Status encode_tiff(const Image& im, std::string* out);

// The TIFF writer by rows of imageio/row_writer.h.
Status open_tiff_row_writer(ByteSink* sink, int w, int h, int channels, const RasterMeta& meta, std::unique_ptr<RowWriter>* out);

}  // namespace erd::imageio
