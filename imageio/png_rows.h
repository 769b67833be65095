// PNG read by rows (issue 48: `erd tiles` on a PNG larger than memory): the IDAT stream inflated
// through zlib a row at a time and unfiltered against the row before, so a window costs the rows
// up to its last and one row of memory beyond the window. Rows are read forward; a window above
// the last one read starts again from the first IDAT. Gray or RGB, 8 or 16 bits, not interlaced
// (Adam7 rows are not contiguous); other PNGs are read whole (decode_png). Each chunk's CRC is
// checked.
#pragma once
#include <cstdint>
#include <cstdio>
#include <vector>

#include <zlib.h>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

class PngRows {
public:
    PngRows() = default;
    ~PngRows();
    PngRows(const PngRows&) = delete;
    PngRows& operator=(const PngRows&) = delete;

    // Reads the header of the PNG in f (not closed here). Fails (Code::input) for a PNG not read by rows.
    Status open(std::FILE* f, const ImageLimits& limits);
    int width() const { return int(width_); }
    int height() const { return int(height_); }
    int channels() const { return channels_; }

    // Rows y0 <= y < y1, columns x0 <= x < x1 (inside the image) as an 8- or 16-bit image.
    Status read(int x0, int y0, int x1, int y1, Image* out);

private:
    Status restart();
    Status next_row();  // inflates and unfilters row next_ into cur_

    std::FILE* f_ = nullptr;
    std::uint32_t width_ = 0, height_ = 0;
    int channels_ = 1, bytes_ = 1;  // bytes per sample
    std::size_t row_bytes_ = 0;
    long first_chunk_ = 0;  // file offset of the chunk after IHDR
    z_stream z_{};
    bool z_open_ = false;
    std::uint32_t chunk_left_ = 0;  // bytes of the current IDAT not yet fed
    std::uint32_t chunk_crc_ = 0;
    bool ended_ = false;  // IEND reached
    std::vector<unsigned char> in_, prev_, cur_;
    std::int64_t next_ = 0;  // the row next_row() makes
};

}  // namespace erd::imageio
