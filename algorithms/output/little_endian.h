// Little-endian uint32 and float32 appended to a byte string, whatever the host's order: the
// binary exports' number format (STL in export.cpp, glTF's GLB in gltf.cpp).
#pragma once
#include <cstdint>
#include <cstring>
#include <string>

namespace erd {

inline void put_u32(std::string* s, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) s->push_back(char((v >> (8 * k)) & 0xFFu));
}

inline void put_f32(std::string* s, float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    put_u32(s, u);
}

}  // namespace erd
