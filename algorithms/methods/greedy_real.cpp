// A face's re-scan in greedy refinement of a real image (issue 47): real-valued errors of every
// channel's plane against Image::reals, by point evaluation (each pixel on the face that owns it,
// which is how a real model is reconstructed), the pixels without data left out of the sums (they
// are banned, so never candidates). Kept apart from the integer scans, whose code and results it
// leaves as they were.
#include "algorithms/methods/greedy_refiner.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/methods/greedy_scan.h"
#include "kernel/raster_rows.h"

namespace erd {

namespace {

// One span of a gray real image, x0..x1 of a row: s the row's values, ok its valid flags (null: all
// valid). The candidate is the first pixel of largest |error| that is not banned.
template <bool Masked>
inline bool scan_real_span(const double* s, const std::uint8_t* ok, const std::uint8_t* banned, std::int32_t x0,
                           std::int32_t x1, double v, double dv, double* sum, double* best, std::int32_t* bx) {
    double acc = 0.0, b = *best;
    bool moved = false;
    auto visit = [&](std::int32_t x, double vx) {
        if (Masked && !ok[x]) return;
        const double e = s[x] - vx;
        acc += e * e;
        const double a = std::fabs(e);
        if (a > b && !banned[x]) {
            b = a;
            *bx = x;
            moved = true;
        }
    };
    greedy_scan::step_span(x0, x1, v, dv, visit);
    *sum += acc;
    *best = b;
    return moved;
}

}  // namespace

GreedyRefiner::Scanned GreedyRefiner::measure_real(FaceInd f) {
    const int C = channels_;
    SpanPlane planes[kMaxChannels];
    if (C == 1) planes[0] = model_.face_plane(cdt_, f);
    else
        for (int c = 0; c < C; ++c) planes[c] = model_.channel_face_plane(cdt_, f, c);
    const LatticePoint p0 = cdt_.point(cdt_.face_vertex(f, 0)), p1 = cdt_.point(cdt_.face_vertex(f, 1)),
                       p2 = cdt_.point(cdt_.face_vertex(f, 2));
    const std::size_t width = std::size_t(image_.width);
    const double* const reals = image_.reals.data();
    const std::uint8_t* const ok = image_.valid.empty() ? nullptr : image_.valid.data();
    const std::uint8_t* const banned = banned_.data();
    double sum = 0.0, best = -1.0;
    std::int32_t bx = 0, by = 0;
    if (C == 1) {
        const SpanPlane& plane = planes[0];
        const double dv = 2.0 * plane.gx;
        // The owner map's entries of f's pixels: faces own disjoint pixels, so two threads
        // measuring two faces write disjoint entries.
        FaceInd* const owner = by_owner() ? options_.owners->data() : nullptr;
        for_each_owned_row(Lattice::pixels(), domain_, p0, p1, p2, [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            const std::size_t row = std::size_t(j) * width;
            if (owner) std::fill(owner + row + std::size_t(lo), owner + row + std::size_t(hi) + 1, f);
            const double v = plane.at(double(2 * lo), double(2 * j));
            const bool moved = ok ? scan_real_span<true>(reals + row, ok + row, banned + row, lo, hi, v, dv, &sum, &best, &bx)
                                  : scan_real_span<false>(reals + row, nullptr, banned + row, lo, hi, v, dv, &sum, &best, &bx);
            if (moved) by = j;
        });
        return Scanned{sum, best, LatticePoint{2 * bx, 2 * by}, best > 0.0};
    }
    // Colour: a pixel's error is the sum of its squared channel errors; the candidate the pixel
    // of the largest channel error or of the largest sum (GreedyOptions::max_channel_error), as
    // the squares are compared.
    const bool by_max = options_.max_channel_error;
    double best2 = -1.0;
    for_each_owned_row(Lattice::pixels(), domain_, p0, p1, p2, [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
        const std::size_t row = std::size_t(j) * width;
        double v[kMaxChannels], dv[kMaxChannels];
        for (int c = 0; c < C; ++c) {
            v[c] = planes[c].at(double(2 * lo), double(2 * j));
            dv[c] = 2.0 * planes[c].gx;
        }
        for (std::int32_t x = lo; x <= hi; ++x) {
            double e2[kMaxChannels], t = 0.0, m = 0.0;
            const double* s = reals + (row + std::size_t(x)) * std::size_t(C);
            for (int c = 0; c < C; ++c) {
                const double e = s[c] - v[c];
                v[c] += dv[c];
                e2[c] = e * e;
                t += e2[c];
                m = e2[c] > m ? e2[c] : m;
            }
            if (ok && !ok[row + std::size_t(x)]) continue;
            sum += t;
            const double metric = by_max ? m : t;
            if (metric > best2 && !banned[row + std::size_t(x)]) {
                best2 = metric;
                bx = x;
                by = j;
            }
        }
    });
    best = best2 > 0.0 ? std::sqrt(best2) : -1.0;
    return Scanned{sum, best, LatticePoint{2 * bx, 2 * by}, best > 0.0};
}

void GreedyRefiner::rescan_real(FaceInd f) {
    stamp_[f] = generation_;
    total_ -= faces_[f].sum;
    settle(f, measure_real(f));
}

void GreedyRefiner::scan_all_by_owner() {
    const std::size_t F = faces_.size(), W = std::size_t(image_.width), H = std::size_t(image_.height);
    const FaceInd* const owner = options_.owners->data();
    const double* const reals = image_.reals.data();
    const std::uint8_t* const ok = image_.valid.empty() ? nullptr : image_.valid.data();
    const std::uint8_t* const banned = banned_.data();
    std::vector<SpanPlane> planes(F);
    for (FaceInd f = 0; f < F; ++f) planes[f] = model_.face_plane(cdt_, f);
    std::vector<double> sum(F, 0.0), best(F, -1.0);
    std::vector<std::int32_t> bx(F, 0), by(F, 0);
    // A face owns one run of each row it reaches: the span rescan_real would scan, taken left to
    // right, rows top to bottom, so each face's sums and candidate come out as there.
    for (std::size_t j = 0; j < H; ++j) {
        const std::size_t row = j * W;
        for (std::size_t x = 0; x < W;) {
            const FaceInd f = owner[row + x];
            std::size_t x1 = x;
            while (x1 + 1 < W && owner[row + x1 + 1] == f) ++x1;
            if (f < F) {
                const double v = planes[f].at(double(2 * x), double(2 * j)), dv = 2.0 * planes[f].gx;
                const std::int32_t lo = std::int32_t(x), hi = std::int32_t(x1);
                const bool moved = ok ? scan_real_span<true>(reals + row, ok + row, banned + row, lo, hi, v, dv, &sum[f], &best[f], &bx[f])
                                      : scan_real_span<false>(reals + row, nullptr, banned + row, lo, hi, v, dv, &sum[f], &best[f], &bx[f]);
                if (moved) by[f] = std::int32_t(j);
            }
            x = x1 + 1;
        }
    }
    for (FaceInd f = 0; f < F; ++f) {
        stamp_[f] = generation_;
        total_ -= faces_[f].sum;
        if (best[f] > 0.0) faces_[f].cand = LatticePoint{2 * bx[f], 2 * by[f]};
        settle(f, sum[f], best[f]);
    }
}

}  // namespace erd
