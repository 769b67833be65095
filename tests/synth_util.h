// The library's synthetic test image (algorithms/imaging/synth.h) for the tests that need a small
// image of smooth parts, sharp edges and mild noise.
#pragma once
#include <catch2/catch.hpp>

#include <cstdint>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/synth.h"

namespace erd_test {

// w x h at `bits` bits per sample, noise from `seed`.
inline erd::Image synth_image(int w, int h, int bits = 8, std::uint64_t seed = 1) {
    erd::SynthParams p;
    p.width = w;
    p.height = h;
    p.bits = bits;
    p.seed = seed;
    erd::Image im;
    REQUIRE(erd::synth(p, &im).ok());
    return im;
}

}  // namespace erd_test
