// The rounded approximation the straightforward way, for the reference tests of greedy
// refinement and reconstruction: round half up of the plane through integer corner values by
// exact integer division (no doubles at all), or, for other values, the real plane stepped along
// the span as reconstruction steps it, clamped and rounded with std::floor.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "algorithms/model/model.h"
#include "kernel/predicates.h"

namespace erd_test {

// floor(a / b) for b > 0, in 128 bits so that no test input can overflow it.
inline std::int64_t floor_div128(__int128 a, __int128 b) {
    __int128 q = a / b;
    if (a % b != 0 && a < 0) --q;
    return std::int64_t(q);
}

// round-half-up of the plane through (p[k], z[k]) at doubled point (X, Y): with D = orient2d and
// v = N / D, floor(v + 1/2) = floor((2N + D) / (2D)) (signs normalised so that D > 0).
inline std::int64_t exact_rounded(const erd::LatticePoint p[3], const std::int64_t z[3], std::int64_t X,
                                  std::int64_t Y) {
    __int128 D = erd::orient2d(p[0], p[1], p[2]);
    // N = z0 * orient(p, p1, p2) + z1 * orient(p0, p, p2) + z2 * orient(p0, p1, p) (barycentric).
    auto orient = [](std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
                     std::int64_t cy) { return __int128(bx - ax) * (cy - ay) - __int128(by - ay) * (cx - ax); };
    __int128 N = z[0] * orient(X, Y, p[1].x, p[1].y, p[2].x, p[2].y) +
                 z[1] * orient(p[0].x, p[0].y, X, Y, p[2].x, p[2].y) +
                 z[2] * orient(p[0].x, p[0].y, p[1].x, p[1].y, X, Y);
    if (D < 0) D = -D, N = -N;
    return floor_div128(2 * N + D, 2 * D);
}

// The reference value of a pixel: exact when the corner values are integers (has_integers),
// else from the stepped real value v; both clamped to [0, maxval] as imgsyn does.
inline double reference_rounded(bool has_integers, const erd::LatticePoint p[3], const std::int64_t z[3], std::int32_t x,
                                std::int32_t y, double v, std::uint32_t maxval) {
    const double m = double(maxval);
    if (has_integers) return std::clamp(double(exact_rounded(p, z, 2 * std::int64_t(x), 2 * std::int64_t(y))), 0.0, m);
    return std::floor(std::clamp(v, 0.0, m) + 0.5);
}

}  // namespace erd_test
