// The only door to Debian's stb_image (package libstb-dev, header only). stb_image is compiled
// here alone, fenced: PNG and baseline/progressive JPEG only, small maximum dimensions, and every
// allocation charged against a byte budget (see ../shared/spec/INPUTS.md). Used by imageio/ only.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace erd::stb {

struct Decoded {
    int width = 0, height = 0, bits = 8;
    int file_channels = 0;               // as stored: 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA
    int channels = 0;                    // kept: 1 (gray) or 3 (RGB); alpha is dropped
    std::vector<std::uint16_t> samples;  // interleaved, row-major
};

// Reads width, height, channels and bit depth of a PNG or JPEG without decoding. False with
// *why on failure.
bool info(const unsigned char* data, std::size_t size, int* w, int* h, int* channels, bool* is16, std::string* why);

// Decodes a PNG or JPEG; allocations above budget_bytes fail the decode instead of the process.
// Thread-safe: calls are serialised (stb keeps its failure reason in a global).
bool decode(const unsigned char* data, std::size_t size, std::size_t budget_bytes, Decoded* out, std::string* why);

}  // namespace erd::stb
