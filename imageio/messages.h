// What the decoders of imageio/ share to word their one-line messages (internal to imageio/).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd::imageio {

// pnm(5) whitespace: space, TAB, LF, VT, FF, CR.
inline bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
inline bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }

// A few bytes from data[i] for a message: printable ASCII as is, others as \xNN; stops at
// whitespace or '#' and says "..." when cut in the middle of a token.
std::string show(const unsigned char* data, std::size_t size, std::size_t i, std::size_t max_chars = 12);

// stb's reasons may quote raw bytes (an unknown chunk's name): keep messages one printable line.
std::string printable(const std::string& why);

// "(x, y)".
std::string at(long long x, long long y);

// A side of `what` (e.g. "PNG width") between 1 and limits.max_side.
Status check_side(const char* what, std::uint64_t v, const ImageLimits& limits);

// w x h within limits.max_pixels; `what` starts the message ("PNG", "JPEG", "").
Status check_pixels(const std::string& what, std::uint64_t w, std::uint64_t h, const ImageLimits& limits);

// Why a file that is not an image erd reads is not: the formats people most often pass by
// mistake, named.
std::string wrong_magic(const unsigned char* d, std::size_t n);

}  // namespace erd::imageio
