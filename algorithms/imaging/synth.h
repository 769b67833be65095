// A deterministic test image: what the methods are made for, in one picture. Smooth gradients
// (a linear ramp and a smooth bump) where a plain triangulation does well, sharp-edged shapes
// (two discs, a triangle, a slanted step) where explicit discontinuities pay, and mild noise.
//
// The same parameters give the same bytes everywhere: geometry in exact integers, shading
// with + - * / only (IEEE-exact), noise from a fixed integer generator (splitmix64), never
// std:: distributions, whose output differs between standard libraries.
#pragma once
#include <cstdint>

#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd {

struct SynthParams {
    int width = 256;
    int height = 256;
    int bits = 8;            // 1..16: maxval = 2^bits - 1
    std::uint64_t seed = 1;  // noise only; the shapes depend on the size alone
    bool noise = true;       // mild noise: +-(maxval/128, at least 1)
};

// Fills *out. Fails (Code::input) on a size outside 1..kMaxImageSide, above kMaxImagePixels,
// or bits outside 1..16.
Status synth(const SynthParams& params, Image* out);

}  // namespace erd
