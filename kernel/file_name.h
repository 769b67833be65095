// The one test every room makes on a file name: its extension, which picks a format where the
// content does not (.model / .erd / .tri, .png, .svg / .png, .obj / .ply / .stl).
#pragma once
#include <cstring>
#include <string>

namespace erd {

// True when `name` ends with `ext` (".png", lower case), the name's ASCII letters compared
// without case.
inline bool has_extension(const std::string& name, const char* ext) {
    const std::size_t n = std::strlen(ext);
    if (name.size() < n) return false;
    for (std::size_t i = 0; i < n; ++i) {
        char c = name[name.size() - n + i];
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        if (c != ext[i]) return false;
    }
    return true;
}

}  // namespace erd
