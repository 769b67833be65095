// Rasters written row by row (issue 47's synthetic elevation model, issue 48's large rasters):
// the rows go out as they are made, so the whole image is never in memory. TIFF (deflate strips,
// as encode_tiff) and PFM (rows placed from the bottom, as the format stores them).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// Where a writer's bytes go: the caller's file (random access: TIFF seeks back for its directory).
class ByteSink {
public:
    virtual ~ByteSink() = default;
    virtual bool write_at(std::uint64_t offset, const void* data, std::size_t n) = 0;
    virtual std::size_t read_at(std::uint64_t offset, void* data, std::size_t n) = 0;
    virtual std::uint64_t size() = 0;
};

class RowWriter {
public:
    virtual ~RowWriter() = default;
    // Row after row from the top: width * channels values, NaN for nodata (written as meta.nodata
    // for an integer type, which then needs one: the smallest of the type when meta has none).
    virtual Status write_row(const double* values) = 0;
    // After the last row: the file complete.
    virtual Status finish() = 0;
};

// A writer of `format` (tiff or pfm) for a w x h raster of `channels` (1 or 3) in meta.type
// (PFM: float32 whatever it says), with meta's georeferencing and nodata (TIFF).
Status open_row_writer(ImageFormat format, ByteSink* sink, int w, int h, int channels, const RasterMeta& meta,
                       std::unique_ptr<RowWriter>* out);

}  // namespace erd::imageio
