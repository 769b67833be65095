// The span scans of greedy refinement (greedy.h), in a header so that each is inlined into the face
// walk that calls it: greedy_rescan.cpp (a gray face) and greedy_colour.cpp (a colour face, in
// doubles; colour_scan.h has the fixed-point scan of 8-bit RGB).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "kernel/raster.h"

namespace erd {
namespace greedy_scan {

// The inner loops of the face scan, one span at a time: the value v steps by dv per pixel. Each
// adds the squared errors to *sum and moves the candidate (*best, *bx) to the first pixel of
// larger absolute error that is not banned; returns true when it moved.
//
// Rounded: the approximation as imgsyn makes it (algorithms/model/reconstruct.cpp), so errors are
// integers and sums exact. Two ways to get it (see scan_exact and GreedyRefiner::rescan):
//   exact: v is p of kernel/raster.h RoundedPlane, whose truncation IS the rounded value;
//   clamp: v is the real plane, clamped to [0, maxval] and rounded half up as to_sample does.
enum class Rounding { exact, clamp };

template <Rounding R>
inline std::int32_t rounded(double v, double maxval) {
    if (R == Rounding::exact) return std::int32_t(v);
    // Clamp above in double (also keeps the conversion in range), round by truncation, clamp
    // below in integers: any v < 0.5 gives 0 as to_sample does (truncation stands in for
    // std::floor, a libm call without SSE4.1; they agree for v + 0.5 >= 0). Cheaper than a
    // double clamp, which GCC compiles into a 5-instruction blend.
    const double c = v < maxval ? v : maxval;
    const std::int32_t r = std::int32_t(c + 0.5);
    return r < 0 ? 0 : r;
}

// Calls visit(x, v) for x = x0..x1 with the running value v, v + dv, v + dv + dv, ... (the
// serial sum reconstruction steps too). Four pixels per trip; v is updated in place (no copies of
// it are live, which saves a register copy per pixel with two-operand SSE).
template <class Visit>
inline void step_span(std::int32_t x0, std::int32_t x1, double v, double dv, Visit& visit) {
    std::int32_t x = x0;
    for (; x + 3 <= x1; x += 4) {
        visit(x, v);
        v += dv;
        visit(x + 1, v);
        v += dv;
        visit(x + 2, v);
        v += dv;
        visit(x + 3, v);
        v += dv;
    }
    for (; x <= x1; ++x, v += dv) visit(x, v);
}

// The colour scan of one span (GreedyRefiner::rescan_colour), C = 3 channels: the sum of the squared
// channel errors and the candidate by their largest (ByMax) or their sum. Round: values rounded
// and clamped as reconstruction writes them.
template <bool Round, bool ByMax>
inline bool scan_colour(const std::uint16_t* s, const std::uint8_t* banned, std::int32_t x0, std::int32_t x1,
                        const double* v, const double* dv, double maxval, double* sum, double* best, std::int32_t* bx) {
    // The running values in locals (not through v, which the stores to *sum could alias).
    double v0 = v[0], v1 = v[1], v2 = v[2];
    const double d0 = dv[0], d1 = dv[1], d2 = dv[2];
    double acc = 0.0, b = *best;
    bool moved = false;
    const auto sq = [maxval](std::uint16_t sample, double a) {
        const double e = Round ? double(std::int32_t(sample) - rounded<Rounding::clamp>(a, maxval)) : double(sample) - a;
        return e * e;
    };
    for (std::int32_t x = x0; x <= x1; ++x, s += 3) {
        const double e0 = sq(s[0], v0), e1 = sq(s[1], v1), e2 = sq(s[2], v2);
        v0 += d0;
        v1 += d1;
        v2 += d2;
        const double t = (e0 + e1) + e2;
        acc += t;
        const double metric = ByMax ? std::max(std::max(e0, e1), e2) : t;
        if (metric > b && !banned[x]) {
            b = metric;
            *bx = x;
            moved = true;
        }
    }
    *sum += acc;
    *best = b;
    return moved;
}

// Squared errors in 32 bits: |sample - r| <= 65535, and 65535^2 < 2^32.
template <Rounding R>
inline bool scan_rounded(const std::uint16_t* samples, const std::uint8_t* banned, std::int32_t x0, std::int32_t x1,
                         double v, double dv, double maxval, std::int64_t* sum, std::int64_t* best_sq,
                         std::int32_t* bx) {
    std::uint64_t acc = 0;
    std::int64_t b = *best_sq;  // the candidate is compared by squared error: no abs
    bool moved = false;
    auto visit = [&](std::int32_t x, double vx) {
        const std::uint32_t e = std::uint32_t(std::int32_t(samples[x]) - rounded<R>(vx, maxval));
        const std::uint32_t e2 = e * e;
        acc += e2;
        if (std::int64_t(e2) > b && !banned[x]) {
            b = e2;
            *bx = x;
            moved = true;
        }
    };
    step_span(x0, x1, v, dv, visit);
    *sum += std::int64_t(acc);
    *best_sq = b;
    return moved;
}

// Exact rounding of row j, columns x0..x1: p stepped from an exact start value over each piece
// of at most plane.run pixels (kernel/raster.h has the error bound), truncated, no clamp (the
// rounded plane of a face stays in [0, maxval] on the pixels it owns).
inline bool scan_exact(const std::uint16_t* samples, const std::uint8_t* banned, std::int32_t j, std::int32_t x0,
                       std::int32_t x1, const RoundedPlane& plane, std::int64_t* sum, std::int64_t* best_sq,
                       std::int32_t* bx) {
    bool moved = false;
    plane.pieces(x0, x1, j, [&](std::int32_t first, std::int32_t last, double p) {
        moved |= scan_rounded<Rounding::exact>(samples, banned, first, last, p, plane.dp, 0.0, sum, best_sq, bx);
    });
    return moved;
}

// Real-valued: errors against the plane itself. The candidate test |e| > best is screened by
// e^2 >= best^2 (*best2 holds the rounded square of *best, or -1 while there is no candidate): the
// rounded square is monotone in |e|, so every pixel that passes the exact test passes the screen,
// and the screen costs nothing because e^2 is needed for the sum anyway. The sum is accumulated
// pixel by pixel in scan order, as before, so it is the same double.
inline bool scan_real(const std::uint16_t* samples, const double* as_double, const std::uint8_t* banned,
                      std::int32_t x0, std::int32_t x1, double v, double dv, double* sum, double* best,
                      double* best2, std::int32_t* bx) {
    double acc = 0.0, b = *best, b2 = *best2;
    bool moved = false;
    auto visit = [&](std::int32_t x, double vx) {
        const double e = as_double[samples[x]] - vx;
        const double e2 = e * e;
        acc += e2;
        if (e2 >= b2 && std::fabs(e) > b && !banned[x]) {
            b = std::fabs(e);
            b2 = e2;
            *bx = x;
            moved = true;
        }
    };
    step_span(x0, x1, v, dv, visit);
    *sum += acc;
    *best = b;
    *best2 = b2;
    return moved;
}

}  // namespace greedy_scan
}  // namespace erd
