// splitmix64 (Steele, Lea, Flood 2014): a full-period 64-bit generator, fixed by its seed, for the
// deterministic test images (synth.h, drawings.h): the same numbers on every machine, unlike the
// standard library's distributions.
#pragma once
#include <cstdint>

namespace erd {

struct SplitMix {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, n) from the top bits (n > 0; a slight bias for n not a power of two).
    std::int64_t below(std::int64_t n) { return std::int64_t((next() >> 11) % std::uint64_t(n)); }
};

}  // namespace erd
