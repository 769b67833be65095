// A minimal PNG writer for tests (stored deflate blocks, filter 0), so tests can make PNG kinds
// erd's own writer does not (alpha, palette, 1-bit) and hostile ones (any header).
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace erd_test {

inline std::uint32_t crc32(const std::string& s) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : s) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}
inline std::string be32(std::uint32_t v) {
    return std::string{char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
}
inline std::string chunk(const std::string& type, const std::string& data) {
    return be32(std::uint32_t(data.size())) + type + data + be32(crc32(type + data));
}
// rows: the unfiltered bytes of every row, concatenated (filter byte 0 is added here).
inline std::string make_png(std::uint32_t w, std::uint32_t h, int depth, int ctype, const std::string& rows,
                     const std::string& plte = "") {
    std::string raw;
    std::size_t row_bytes = h ? rows.size() / h : 0;
    for (std::uint32_t y = 0; y < h; ++y) raw += '\0' + rows.substr(y * row_bytes, row_bytes);
    std::string z = "\x78\x01";
    std::size_t i = 0;
    do {
        std::size_t n = std::min<std::size_t>(65535, raw.size() - i);
        bool last = i + n == raw.size();
        z += char(last ? 1 : 0);
        z += char(n & 0xff);
        z += char(n >> 8);
        z += char(~n & 0xff);
        z += char((~n >> 8) & 0xff);
        z += raw.substr(i, n);
        i += n;
    } while (i < raw.size());
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : raw) { a = (a + c) % 65521; b = (b + a) % 65521; }
    z += be32(b << 16 | a);
    std::string ihdr = be32(w) + be32(h) + char(depth) + char(ctype) + std::string("\0\0\0", 3);
    std::string png = "\x89PNG\r\n\x1a\n";
    png += chunk("IHDR", ihdr);
    if (!plte.empty()) png += chunk("PLTE", plte);
    png += chunk("IDAT", z) + chunk("IEND", "");
    return png;
}
inline std::string be16s(std::vector<std::uint16_t> v) {
    std::string s;
    for (auto x : v) { s += char(x >> 8); s += char(x & 0xff); }
    return s;
}

}  // namespace erd_test
