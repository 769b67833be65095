// Doubles to and from their shortest decimal text for the model files. Native builds use
// std::to_chars / std::from_chars. The WebAssembly build (make web, Debian's emscripten 3.1.6,
// whose libc++ has neither for floating point) uses the C library instead: the shortest %.*g
// that reads back to the same double (the same digits as to_chars for the values model files
// hold), and strtod (which also takes hex floats, which from_chars refuses).
#pragma once
#include <charconv>
#include <system_error>

#ifdef __EMSCRIPTEN__
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#endif

namespace erd {

inline char* write_double(char* p, char* end, double v) {
#ifdef __EMSCRIPTEN__
    // Rounding to more digits is never farther from v, so "reads back" is monotone in the digit
    // count (but where v is a power of two, whose lower neighbour is nearer than its upper one):
    // bisection finds the shortest in 4-5 tries instead of trying 1, 2, ... up to 17 (most model
    // values need 15-17). Whatever it returns reads back: hi only ever takes a count that does.
    char buf[40];
    int lo = 1, hi = 17;
    while (v == v && lo < hi) {
        int mid = (lo + hi) / 2;
        std::snprintf(buf, sizeof buf, "%.*g", mid, v);
        if (std::strtod(buf, nullptr) == v) hi = mid;
        else lo = mid + 1;
    }
    std::snprintf(buf, sizeof buf, "%.*g", hi, v);
    std::size_t n = std::strlen(buf);
    if (n > std::size_t(end - p)) n = std::size_t(end - p);
    std::memcpy(p, buf, n);
    return p + n;
#else
    return std::to_chars(p, end, v).ptr;
#endif
}

inline std::from_chars_result read_double(const char* b, const char* e, double* x) {
#ifdef __EMSCRIPTEN__
    std::string s(b, e);
    char* stop = nullptr;
    errno = 0;
    *x = std::strtod(s.c_str(), &stop);
    std::from_chars_result r{b + (stop - s.c_str()), std::errc()};
    if (stop == s.c_str() || (!s.empty() && (s[0] == ' ' || s[0] == '+'))) r = {b, std::errc::invalid_argument};
    else if (errno == ERANGE) r.ec = std::errc::result_out_of_range;
    return r;
#else
    return std::from_chars(b, e, *x);
#endif
}

}  // namespace erd
