// Image files for applications that link liberd_imageio: whole-file reading and writing with the
// C library, the decoders and encoders of imageio/image_format.h in between. (The erd program has
// its own file handling, cli/image_io.h: standard input, streams, atomic replacement.)
#pragma once
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// Files larger than this are refused before reading (the largest image of the limits as 16-bit
// PPM is 1.5 GiB).
constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t(1) << 31;

// Reads and decodes an image file of any supported format. Messages start with the path.
Status read_image_file(const std::string& path, Image* out, std::string* warning = nullptr,
                       const ImageLimits& limits = ImageLimits());

// Encodes as the name asks (format_for_name: PNG for ".png", else PGM/PPM raw) and writes.
Status write_image_file(const std::string& path, const Image& im);

}  // namespace erd::imageio
