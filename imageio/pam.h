// PAM (netpbm pam(5), magic P7) by our own reader: a header of "KEYWORD value" lines (WIDTH,
// HEIGHT, DEPTH, MAXVAL, TUPLTYPE, ENDHDR; '#' comment lines), then the raw raster as in P5/P6.
// DEPTH 1 is gray and 3 RGB; 2 and 4 carry alpha, which is dropped with a warning. The same
// hostile-input rules as PGM/PPM: bounded numbers, sizes checked before any allocation, the
// raster length checked against the file.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

struct PamHeader {
    std::uint64_t w = 0, h = 0, depth = 0, maxval = 0;
    std::size_t raster = 0;  // index of the first raster byte (after "ENDHDR\n")
};

// Parses the header; errors starting "end of file" mean the header is incomplete.
Status pam_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PamHeader* header);

Status decode_pam(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

}  // namespace erd::imageio
