// A gray face's re-scan in greedy refinement: the pixels it owns, row by row in the walk of
// kernel/raster_rows.h, against the model's plane (exactly rounded, rounded and clamped, real, or
// the supersampled approximation), giving its squared-error sum and candidate.
#include "algorithms/methods/greedy_refiner.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "algorithms/methods/greedy_scan.h"
#include "kernel/raster_rows.h"

namespace erd {

using namespace greedy_scan;

void GreedyRefiner::rescan(FaceInd f) {
    if (channels_ > 1) return rescan_colour(f);
    stamp_[f] = generation_;
    total_ -= faces_[f].sum;
    settle(f, measure(f));
}

GreedyRefiner::Scanned GreedyRefiner::measure(FaceInd f) {
    const LatticePoint p[3] = {cdt_.point(cdt_.face_vertex(f, 0)), cdt_.point(cdt_.face_vertex(f, 1)),
                               cdt_.point(cdt_.face_vertex(f, 2))};
    // Rounded scans of a face with integer corner values in [0, maxval] round exactly (as
    // reconstruction does for such a face); the others step the model's plane.
    std::int64_t z[3];
    RoundedPlane exact;
    const bool is_exact = options_.round_values && !options_.supersampled && model_.integer_values(cdt_, f, z) &&
                          exact.set(p[0], z[0], p[1], z[1], p[2], z[2], image_.maxval);
    const SpanPlane plane = is_exact ? SpanPlane() : model_.face_plane(cdt_, f);
    const double dv = 2.0 * plane.gx;
    // Row j of the pixel lattice, columns lo..hi: the row's samples and ban flags, and the
    // plane at its first pixel (with_value; the exact scan does not need it).
    // Pixel (i, j) is doubled point (2i, 2j): the same values as
    // plane.at(Lattice::pixels(), i, j) and step_x (which divide by the lattice's scale 1)
    // without two divisions per row.
    const std::uint16_t* const samples = image_.samples.data();
    const std::uint8_t* const banned = banned_.data();
    const std::size_t width = std::size_t(image_.width);
    auto walk = [&](auto with_value, auto&& scan_row) {
        for_each_owned_row(Lattice::pixels(), domain_, p[0], p[1], p[2], [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            const std::size_t row = std::size_t(j) * width;
            if constexpr (decltype(with_value)::value)
                scan_row(samples + row, banned + row, j, lo, hi, plane.at(double(2 * lo), double(2 * j)));
            else
                scan_row(samples + row, banned + row, j, lo, hi);
        });
    };
    double sum = 0.0, best = -1.0;
    std::int32_t bx = 0, by = 0;
    if (options_.supersampled) {
        std::int64_t isum = 0, ibest_sq = -1;
        walk(std::false_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                    std::int32_t lo, std::int32_t hi) {
            FaceInd* own = &owner_[std::size_t(j) * width];
            for (std::int32_t x = lo; x <= hi; ++x) {
                own[x] = f;
                const std::int64_t e = std::int64_t(srow[x]) - supersampled_value(x, j);
                isum += e * e;
                if (e * e > ibest_sq && !brow[x]) {
                    ibest_sq = e * e;
                    bx = x;
                    by = j;
                }
            }
        });
        sum = double(isum);
        best = ibest_sq < 0 ? -1.0 : std::sqrt(double(ibest_sq));
    } else if (options_.round_values) {
        std::int64_t isum = 0, ibest_sq = -1;
        if (is_exact) {
            walk(std::false_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                        std::int32_t lo, std::int32_t hi) {
                if (scan_exact(srow, brow, j, lo, hi, exact, &isum, &ibest_sq, &bx)) by = j;
            });
        } else {
            const double maxval = double(image_.maxval);
            walk(std::true_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                       std::int32_t lo, std::int32_t hi, double v) {
                if (scan_rounded<Rounding::clamp>(srow, brow, lo, hi, v, dv, maxval, &isum, &ibest_sq, &bx)) by = j;
            });
        }
        sum = double(isum);
        best = ibest_sq < 0 ? -1.0 : std::sqrt(double(ibest_sq));  // exact: a perfect square
    } else {
        double best2 = -1.0;
        walk(std::true_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                   std::int32_t lo, std::int32_t hi, double v) {
            if (scan_real(srow, as_double_.data(), brow, lo, hi, v, dv, &sum, &best, &best2, &bx)) by = j;
        });
    }
    return Scanned{sum, best, LatticePoint{2 * bx, 2 * by}, best > 0.0};
}

}  // namespace erd
