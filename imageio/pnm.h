// Netpbm images by our own reader and writer: PGM (P2 plain, P5 raw) and PPM (P3 plain, P6 raw),
// 8- and 16-bit (big-endian), maxval kept exactly, with the hostile-input rules of docs/HOSTILE.md:
// every header number checked against the limits before any allocation, the raster read only as
// far as the header declares.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// The header of a PGM or PPM: magic, width, height, maxval (each checked against the limits) and
// the index of the one whitespace byte that ends it (the raster starts after it).
struct PnmHeader {
    bool plain = false;
    int channels = 1;  // 1 for PGM, 3 for PPM
    std::uint64_t w = 0, h = 0, maxval = 0;
    std::size_t sep = 0;
};
Status pnm_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PnmHeader* header);

// Decodes a PGM or PPM from memory. *warning receives non-fatal remarks (e.g. a CR before an LF
// after maxval); it may be null. A PPM whose three channels are equal everywhere comes back gray.
Status decode_pnm(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

// PGM (gray) or PPM (colour) bytes: raw (P5, P6) or plain (P2, P3, at most 70 characters a
// line). maxval kept, 16-bit big-endian. The image must be valid: not rechecked.
std::string encode_pnm(const Image& im, bool plain);

}  // namespace erd::imageio
