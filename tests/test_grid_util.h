// Small grids for the image-analysis tests: a grid from a function of (x, y), and a
// deterministic pseudo-random sequence for synthetic images and densities.
#pragma once
#include <cstdint>

#include "algorithms/imaging/image.h"

namespace erd_test {

template <class F>
erd::Grid<double> make_grid(int w, int h, F f) {
    erd::Grid<double> g(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) g(x, y) = f(double(x), double(y));
    return g;
}

// A linear congruential generator: values in [0, 1).
struct Lcg {
    std::uint32_t s;
    double next() { s = s * 1664525u + 1013904223u; return double(s >> 8) / double(1u << 24); }
};

}  // namespace erd_test
