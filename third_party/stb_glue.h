// The only door to Debian's stb_image / stb_image_write (package libstb-dev, header only).
// stb_image is compiled here alone, fenced: PNG only, small maximum dimensions, and every
// allocation charged against a byte budget (see ../shared/spec/INPUTS.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace erd::stb {

struct PngImage {
    int width = 0, height = 0, channels = 0, bits = 8;  // channels as stored in the file
    std::vector<std::uint16_t> gray;                    // luma (BT.601 when colour), row-major
};

// Reads width, height, channels and bit depth without decoding. False with *why on failure.
bool png_info(const unsigned char* data, std::size_t size, int* w, int* h, int* channels, bool* is16, std::string* why);

// Decodes to gray; allocations above budget_bytes fail the decode instead of the process.
// Thread-safe: calls are serialised (stb keeps its failure reason in a global).
bool png_decode(const unsigned char* data, std::size_t size, std::size_t budget_bytes, PngImage* out, std::string* why);

// Encodes 8-bit gray (channels = 1) or RGB (channels = 3) into PNG bytes.
bool png_encode(const unsigned char* pixels, int w, int h, int channels, std::vector<unsigned char>* out);

}  // namespace erd::stb
