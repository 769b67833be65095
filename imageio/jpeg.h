// JPEG input through the fenced stb glue (third_party/stb_glue.h), with the fences of PNG: our
// own walk over the markers first (frame header, components, coding, the end-of-image marker),
// the size checked against the limits and against what the file can hold before any decoding,
// and the decoder's allocations capped. Baseline and progressive Huffman JPEG, 8-bit, gray or
// YCbCr; CMYK, arithmetic coding, 12-bit, lossless and hierarchical JPEG are refused by name.
#pragma once
#include <cstddef>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// What the markers before the image data say.
struct JpegHeader {
    int width = 0, height = 0, components = 0, precision = 0;
    bool progressive = false;
};

// Walks the markers of a JPEG up to its frame header and the end-of-image marker and checks them.
Status jpeg_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, JpegHeader* header);

// Decodes a JPEG: gray stays gray, YCbCr becomes RGB (3 channels; gray when they are equal).
Status decode_jpeg(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                   const ImageLimits& limits = ImageLimits());

}  // namespace erd::imageio
