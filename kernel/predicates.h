// Exact geometric predicates on the doubled integer lattice.
//
// Every topological decision of the kernel goes through these functions; none uses floating point.
//
// Sign conventions (the same as Shewchuk's predicates.c): orient2d(a,b,c) > 0 when a, b, c turn
// counter-clockwise with the y axis pointing UP. Image rows grow downward, so on screen a
// "positive" triangle looks clockwise; the code never cares, it only uses the sign.
//   orient2d(a,b,c) = (bx-ax)(cy-ay) - (cx-ax)(by-ay)
//   incircle(a,b,c,d) > 0 when d lies strictly inside the circle through a, b, c, provided that
//   orient2d(a,b,c) > 0 (the sign flips for a negative triangle).
//
// Exactness bound: every coordinate must satisfy 0 <= X, Y < kMaxCoord = 2^24.
//   orient2d: differences < 2^24, products < 2^48, the result < 2^49: exact in int64.
//   incircle: differences < 2^24, lifted terms dx^2+dy^2 < 2^49, 2x2 cofactors < 2^49,
//   each product < 2^98, the sum of three < 2^100: exact in __int128.
// Cdt::reset and Cdt::insert_point check the bound; images are at most 32768 pixels a side
// (algorithms/imaging/image.h), so doubled coordinates stay below 65536, far inside it.
// Small coordinates: when every coordinate is below kSmallCoord = 2^14, differences are below
// 2^14 in magnitude, lifted terms and cofactors below 2^29 (exact in int32), each product below
// 2^58 and the sum of three below 2^60: incircle_small is exact in int64 and saves the three
// 128-bit products. A Cdt whose rectangle is inside that bound (every image up to 8192 pixels a
// side) picks that path once at reset.
//
// Ties. Lattice points are very often cocircular, and then "the" Delaunay triangulation is not
// unique. incircle_perturbed() resolves incircle == 0 by symbolic perturbation: point p is lifted
// to |p|^2 + eps^rank(p), where rank orders points by (Y, X) lexicographically (smallest first,
// the smallest getting the largest perturbation). The rule depends only on the coordinates, so the
// resulting (constrained) Delaunay triangulation depends only on the point and constraint sets,
// never on insertion order, and Lawson flipping terminates (it is a genuine lifting).
#pragma once
#include <cstdint>

#include "kernel/lattice.h"

namespace erd {

// Exclusive upper bound of every doubled coordinate accepted by the kernel.
constexpr std::int32_t kMaxCoord = std::int32_t(1) << 24;

// True when p is inside the exactness bound of the predicates.
inline bool coord_ok(LatticePoint p) { return p.x >= 0 && p.y >= 0 && p.x < kMaxCoord && p.y < kMaxCoord; }

// Twice the signed area of triangle abc; > 0 counter-clockwise (y up). Exact in int64.
inline std::int64_t orient2d(LatticePoint a, LatticePoint b, LatticePoint c) {
    const std::int64_t abx = std::int64_t(b.x) - a.x, aby = std::int64_t(b.y) - a.y;
    const std::int64_t acx = std::int64_t(c.x) - a.x, acy = std::int64_t(c.y) - a.y;
    return abx * acy - acx * aby;
}

// Exclusive bound of the coordinates for which incircle is exact in int64 (see the top).
constexpr std::int32_t kSmallCoord = std::int32_t(1) << 14;

// The in-circle determinant, exact in __int128: > 0 when d is strictly inside the circumcircle
// of the positively oriented triangle abc, 0 when the four points are cocircular.
inline __int128 incircle(LatticePoint a, LatticePoint b, LatticePoint c, LatticePoint d) {
    const std::int64_t adx = std::int64_t(a.x) - d.x, ady = std::int64_t(a.y) - d.y;
    const std::int64_t bdx = std::int64_t(b.x) - d.x, bdy = std::int64_t(b.y) - d.y;
    const std::int64_t cdx = std::int64_t(c.x) - d.x, cdy = std::int64_t(c.y) - d.y;
    const std::int64_t alift = adx * adx + ady * ady;
    const std::int64_t blift = bdx * bdx + bdy * bdy;
    const std::int64_t clift = cdx * cdx + cdy * cdy;
    const std::int64_t ca = bdx * cdy - bdy * cdx;  // orient2d(b, c, d)
    const std::int64_t cb = adx * cdy - ady * cdx;  // orient2d(a, c, d)
    const std::int64_t cc = adx * bdy - ady * bdx;  // orient2d(a, b, d)
    return __int128(alift) * ca - __int128(blift) * cb + __int128(clift) * cc;
}

// The same determinant for points whose coordinates are all below kSmallCoord: differences,
// lifts and cofactors (< 2^29) in int32, the three products and their sum (< 2^60) in int64.
inline std::int64_t incircle_small(LatticePoint a, LatticePoint b, LatticePoint c, LatticePoint d) {
    const std::int32_t adx = a.x - d.x, ady = a.y - d.y;
    const std::int32_t bdx = b.x - d.x, bdy = b.y - d.y;
    const std::int32_t cdx = c.x - d.x, cdy = c.y - d.y;
    const std::int32_t alift = adx * adx + ady * ady;
    const std::int32_t blift = bdx * bdx + bdy * bdy;
    const std::int32_t clift = cdx * cdx + cdy * cdy;
    const std::int32_t ca = bdx * cdy - bdy * cdx;
    const std::int32_t cb = adx * cdy - ady * cdx;
    const std::int32_t cc = adx * bdy - ady * bdx;
    return std::int64_t(alift) * ca - std::int64_t(blift) * cb + std::int64_t(clift) * cc;
}

// The tie-breaking order: (Y, X) lexicographic. Smaller means "perturbed more".
inline bool perturb_before(LatticePoint p, LatticePoint q) { return p.y != q.y ? p.y < q.y : p.x < q.x; }

// The tie case of incircle_perturbed (det == 0), kept out of line so the fast path stays small.
// The lifted determinant is linear in each lift, so its eps-term is
//   d_a*O(b,c,d) - d_b*O(a,c,d) + d_c*O(a,b,d) - d_d*O(a,b,c)
// and the term of the point that comes first in (Y, X) order dominates. Four distinct cocircular
// points never have three collinear, so that term is non-zero.
__attribute__((noinline)) inline int incircle_tie(LatticePoint a, LatticePoint b, LatticePoint c, LatticePoint d) {
    LatticePoint m = a;
    int which = 0;
    if (perturb_before(b, m)) { m = b; which = 1; }
    if (perturb_before(c, m)) { m = c; which = 2; }
    if (perturb_before(d, m)) { m = d; which = 3; }
    std::int64_t term = 0;
    switch (which) {
        case 0: term = orient2d(b, c, d); break;
        case 1: term = -orient2d(a, c, d); break;
        case 2: term = orient2d(a, b, d); break;
        default: term = -orient2d(a, b, c); break;
    }
    return (term > 0) - (term < 0);
}

// Sign (+1 inside, -1 outside) of the in-circle test under the symbolic perturbation described
// at the top; never 0 for four distinct points with orient2d(a,b,c) != 0.
// Out of line: the kernel's hot loops take the int64 path below and must stay small.
__attribute__((noinline)) inline int incircle_perturbed(LatticePoint a, LatticePoint b, LatticePoint c, LatticePoint d) {
    const __int128 det = incircle(a, b, c, d);
    if (det != 0) return det > 0 ? 1 : -1;
    return incircle_tie(a, b, c, d);
}

// The same sign, through incircle_small when `small` says every coordinate is below kSmallCoord.
__attribute__((always_inline)) inline int incircle_perturbed(LatticePoint a, LatticePoint b, LatticePoint c, LatticePoint d,
                                                            bool small) {
    if (!small) return incircle_perturbed(a, b, c, d);
    const std::int64_t det = incircle_small(a, b, c, d);
    if (det != 0) return det > 0 ? 1 : -1;
    return incircle_tie(a, b, c, d);
}

}  // namespace erd
