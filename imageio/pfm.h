// PFM (portable float map; issue 47): "Pf" (gray) or "PF" (RGB), the width, the height and a scale
// whose sign gives the byte order (negative: little-endian), then 32-bit floats, rows from the
// BOTTOM up. Our own reader and writer. A NaN sample is nodata; every image read is a real one
// (algorithms/imaging/real_image.h) of type float32.
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

struct PfmHeader {
    int width = 0, height = 0, channels = 1;
    bool little_endian = true;
    std::size_t raster = 0;  // offset of the first sample (of the bottom row)
};

// Parses and checks the header (sizes against the limits). "end of file" messages when the data
// ends inside it (a stream may still bring the rest).
Status pfm_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PfmHeader* out);

// Rows y0 <= y < y1 (top-down numbering) of the raster after the header h, given as the bytes of
// those rows as the file stores them (bottom row first: the rows from H-y1 to H-y0 counted from
// the bottom), into `values` (interleaved, top-down), NaN kept.
void pfm_rows(const PfmHeader& h, const unsigned char* rows, int y0, int y1, double* values);

Status decode_pfm(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

// The PFM writer by rows of imageio/row_writer.h (float32; rows placed from the bottom).
Status open_pfm_row_writer(ByteSink* sink, int w, int h, int channels, std::unique_ptr<RowWriter>* out);

// PFM bytes of an image (any: an integer one's samples as they are), little-endian, nodata as NaN.
Status encode_pfm(const Image& im, std::string* out);

}  // namespace erd::imageio
