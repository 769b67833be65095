// A colour face's re-scan in greedy refinement (issue 17): every channel's plane by point
// evaluation, the pixel's error the sum of its squared channel errors, the candidate by that sum
// or by the largest channel error; 8-bit images in fixed point (colour_scan.h), others in doubles.
#include "algorithms/methods/greedy_refiner.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "algorithms/methods/colour_scan.h"
#include "algorithms/methods/greedy_scan.h"
#include "kernel/raster_rows.h"

namespace erd {

using namespace greedy_scan;

void GreedyRefiner::rescan_colour(FaceInd f) {
    stamp_[f] = generation_;
    total_ -= faces_[f].sum;
    settle(f, measure_colour(f, &spans_));
}

GreedyRefiner::Scanned GreedyRefiner::measure_colour(FaceInd f, std::vector<Span>* spans) {
    const int C = channels_;
    SpanPlane planes[kMaxChannels];
    for (int c = 0; c < C; ++c) planes[c] = model_.channel_face_plane(cdt_, f, c);
    const LatticePoint p0 = cdt_.point(cdt_.face_vertex(f, 0)), p1 = cdt_.point(cdt_.face_vertex(f, 1)),
                       p2 = cdt_.point(cdt_.face_vertex(f, 2));
    const bool round = options_.round_values, by_max = options_.max_channel_error;
    const double maxval = double(image_.maxval);
    const std::size_t width = std::size_t(image_.width);
    double sum = 0.0, best = -1.0;
    std::int32_t bx = 0, by = 0;
    // 8-bit images, rounded, by the largest channel error (the default): the fixed-point scan.
    if (round && by_max && image_.maxval <= 255 && fixed_scan(planes, p0, p1, p2, &sum, &best, &bx, &by))
        return Scanned{sum, best > 0.0 ? std::sqrt(best) : -1.0, LatticePoint{2 * bx, 2 * by}, best >= 0.0};
    // The owned pixels as spans (the ownership rule of OwnedRows, which the gray scan walks).
    scan_triangle(Lattice::pixels(), domain_, p0, p1, p2, spans);
    for (const Span& sp : *spans) {
        const std::int32_t j = sp.y, lo = sp.x_begin, hi = sp.x_end;
        double v[kMaxChannels], dv[kMaxChannels];
        for (int c = 0; c < C; ++c) {
            v[c] = planes[c].at(double(2 * lo), double(2 * j));
            dv[c] = 2.0 * planes[c].gx;
        }
        const std::uint16_t* s = &image_.samples[(std::size_t(j) * width + std::size_t(lo)) * std::size_t(C)];
        const std::uint8_t* banned = &banned_[std::size_t(j) * width];
        const auto scan = round ? (by_max ? scan_colour<true, true> : scan_colour<true, false>)
                                : (by_max ? scan_colour<false, true> : scan_colour<false, false>);
        if (scan(s, banned, lo, hi, v, dv, maxval, &sum, &best, &bx)) by = j;
    }
    return Scanned{sum, best > 0.0 ? std::sqrt(best) : -1.0, LatticePoint{2 * bx, 2 * by}, best > 0.0};
}

bool GreedyRefiner::fixed_scan(const SpanPlane* planes, LatticePoint p0, LatticePoint p1, LatticePoint p2, double* sum,
                               double* best, std::int32_t* bx, std::int32_t* by) {
    constexpr double one = 4294967296.0, offset = 4611686018427387904.0;  // 2^32, 2^62
    // round(x * 2^32) without a libm call: the offset keeps the truncation a floor.
    const auto fixed = [&](double x) { return std::int64_t(std::uint64_t(x * one + offset + 0.5) - std::uint64_t(offset)); };
    constexpr double steep = 16384.0;
    std::int64_t Z[3], GX[3], GY[3];
    std::int32_t dV[3];
    for (int c = 0; c < 3; ++c) {
        const SpanPlane& q = planes[c];
        const double gx = 2.0 * q.gx, gy = 2.0 * q.gy, z = q.at(double(p0.x), double(p0.y)) + 0.5;
        if (!(gx > -steep && gx < steep && gy > -steep && gy < steep && z > -steep && z < steep)) return false;
        Z[c] = fixed(z);
        GX[c] = fixed(gx);
        GY[c] = fixed(gy);
        dV[c] = std::int32_t((GX[c] + 32768) >> 16);
    }
    const std::int64_t i0 = p0.x / 2, j0 = p0.y / 2, top = (std::int64_t(image_.maxval) + 1) << 16, lim = 1 << 30;
    const std::int32_t maxval = std::int32_t(image_.maxval);
    const std::size_t width = std::size_t(image_.width);
    const std::uint16_t *samples = image_.samples.data(), *end = samples + image_.samples.size();
    colour_scan::Steps steps;
    steps.set(dV);
    std::uint64_t isum = 0;
    std::int32_t ibest = -1, cx = 0, cy = 0;
    const auto scan_row = [&](std::int32_t row, std::int32_t x0, std::int32_t x1) {
        const std::int64_t j = row, lo = x0, n = x1 - lo;
        std::int32_t V0[3];
        bool clamp = false;
        for (int c = 0; c < 3; ++c) {
            const std::int64_t a = (Z[c] + (lo - i0) * GX[c] + (j - j0) * GY[c]) >> 16, e = a + n * dV[c];
            if (std::min(a, e) < 0 || std::max(a, e) >= top) {
                // Cannot happen on a basic model's faces (their planes stay within the
                // corner values); kept so that the lanes hold every value exactly.
                if (a < -lim || a > lim || e < -lim || e > lim) return false;
                clamp = true;
            }
            V0[c] = std::int32_t(a);
        }
        const std::size_t at = std::size_t(j) * width;
        const std::uint16_t* s = samples + 3 * (at + std::size_t(lo));
        if (row + 1 < image_.height) {  // the next row's samples (the interleaved image is 6 bytes a pixel)
            __builtin_prefetch(s + 3 * width);
            __builtin_prefetch(s + 3 * width + 3 * n);
        }
        const bool moved =
            clamp ? colour_scan::scan_span<true>(s, end, banned_.data() + at, x0, x1, V0, steps, maxval, &isum, &ibest, &cx)
                  : colour_scan::scan_span<false>(s, end, banned_.data() + at, x0, x1, V0, steps, maxval, &isum, &ibest, &cx);
        if (moved) cy = row;
        return true;
    };
    if (!for_each_owned_row(Lattice::pixels(), domain_, p0, p1, p2, scan_row)) return false;
    *sum = double(isum);
    *best = double(ibest);
    *bx = cx;
    *by = cy;
    return true;
}

}  // namespace erd
