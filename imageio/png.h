// PNG: read through the fenced stb glue (third_party/stb_glue.h) after our own checks of the
// header and the palette; written by our own chunk writer over zlib (deflate level 9, a filter
// chosen per row), 8- or 16-bit, gray or RGB.
#pragma once
#include <cstddef>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// Decodes a PNG from memory: 8/16-bit gray kept, RGB kept as 3 channels (gray when the three are
// equal everywhere), alpha dropped with a warning, palette images expanded. The size is checked
// from the header before decoding; the decoder's allocations are capped.
Status decode_png(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

// PNG bytes of a gray or RGB image: 8-bit when maxval <= 255, else 16-bit. Samples are stored as
// they are (not rescaled): a PNG has no maxval, so one written from maxval 100 reads back with
// maxval 255 (16-bit: 65535) and the same sample values (docs/DECISIONS.md, Images).
Status encode_png(const Image& im, std::string* out);

// A palette PNG whose PLTE chunk has fewer entries than its bit depth can index: stb would take
// the colour of a larger index from uninitialised memory. Sets *short_palette and writes to
// *padded a copy whose PLTE has every entry, the missing ones all `fill`, and *entries to the
// count the file had; decode_png decodes it with fill 0 and 255 and refuses the image when the
// two differ (a pixel uses a missing entry). A tRNS longer than the palette is refused here.
Status pad_png_palette(const unsigned char* data, std::size_t size, unsigned char fill, bool* short_palette,
                       std::string* padded, std::size_t* entries);

}  // namespace erd::imageio
