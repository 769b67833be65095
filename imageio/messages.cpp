#include "imageio/messages.h"

#include <cstring>

namespace erd::imageio {

// c as itself when printable ASCII (space included when `space`), else as \xNN.
static void put_byte(std::string* s, unsigned char c, bool space) {
    static const char hex[] = "0123456789abcdef";
    if (c >= (space ? 0x20 : 0x21) && c < 0x7f) {
        *s += char(c);
        return;
    }
    *s += "\\x";
    *s += hex[c >> 4];
    *s += hex[c & 15];
}

std::string show(const unsigned char* data, std::size_t size, std::size_t i, std::size_t max_chars) {
    std::string s;
    std::size_t k = i;
    for (; k < size && k - i < max_chars; ++k) {
        unsigned char c = data[k];
        if (k > i && (is_space(c) || c == '#')) return s;
        put_byte(&s, c, false);
    }
    // Cut short in the middle of a token: say so.
    if (k < size && !is_space(data[k]) && data[k] != '#') s += "...";
    return s;
}

std::string printable(const std::string& why) {
    std::string out;
    for (unsigned char c : why) put_byte(&out, c, true);
    return out;
}

std::string at(long long x, long long y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

Status check_side(const char* what, std::uint64_t v, const ImageLimits& limits) {
    if (v == 0) return Status::bad_input(std::string(what) + " is 0");
    if (v > std::uint64_t(limits.max_side))
        return Status::bad_input(std::string(what) + " " + std::to_string(v) + " is above the limit of " +
                                 std::to_string(limits.max_side) +
                                 " pixels (the bound under which the mesh arithmetic is exact; see docs/manual.md)");
    return Status::success();
}

Status check_pixels(const std::string& what, std::uint64_t w, std::uint64_t h, const ImageLimits& limits) {
    const std::uint64_t pixels = w * h;  // both sides already within max_side
    if (std::int64_t(pixels) > limits.max_pixels)
        return Status::bad_input(what + std::to_string(w) + " x " + std::to_string(h) + " = " + std::to_string(pixels) +
                                 " pixels is above the limit of " + std::to_string(limits.max_pixels) + " pixels (memory)");
    return Status::success();
}

static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::string wrong_magic(const unsigned char* d, std::size_t n) {
    static const char* kReads = "erd reads PGM (P2, P5), PPM (P3, P6), PAM (P7), PNG, JPEG, TIFF and PFM";
    if (n == 0) return "empty file";
    if (n == 1) return "file too short (1 byte) to be an image";
    const char* what = nullptr;
    if (d[0] == 'P') {
        switch (d[1]) {
            case '1': what = "a PBM bitmap (P1, plain)"; break;
            case '4': what = "a PBM bitmap (P4, raw)"; break;
            default: break;
        }
        if (what) return std::string(what) + ": " + kReads + "; convert it first";
        return "unknown netpbm magic '" + show(d, n, 0, 2) + "' (a PGM starts with P2 or P5, a PPM with P3 or P6)";
    }
    if (d[0] == 'p' && (d[1] == '2' || d[1] == '3' || d[1] == '5' || d[1] == '6'))
        return std::string("magic 'p") + char(d[1]) + "' is lower case: a netpbm file starts with 'P" + char(d[1]) + "'";
    if (d[0] == 'p' && d[1] >= '1' && d[1] <= '7')
        return std::string("magic 'p") + char(d[1]) + "' is not a netpbm magic (PGM is 'P2' or 'P5', PPM 'P3' or 'P6', upper case)";
    if (n >= 8 && std::memcmp(d, kPngSignature, 8) == 0) what = "a PNG file";
    else if (n >= 2 && d[0] == 0xff && d[1] == 0xd8) what = "a damaged JPEG file (FF D8 not followed by a marker)";
    else if (n >= 4 && std::memcmp(d, "GIF8", 4) == 0) what = "a GIF file";
    else if (n >= 2 && d[0] == 'B' && d[1] == 'M') what = "a BMP file";
    else if (n >= 4 && d[0] == 0x89 && d[1] == 'P' && d[2] == 'N' && d[3] == 'G') what = "a damaged PNG file (bad signature)";
    if (what) return std::string(what) + ": " + kReads;
    return "not an image erd reads (it starts with '" + show(d, n, 0, 8) + "'; " + kReads + ")";
}

}  // namespace erd::imageio
