#include "algorithms/mmsodd.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace erd {

double mmsodd_value(double fxx, double fyy, double fxy) {
    const double l1 = 0.5 * (fxx + fyy);
    const double half_diff = 0.5 * (fxx - fyy);
    const double l2 = std::sqrt(half_diff * half_diff + fxy * fxy);
    return std::fmax(std::fabs(l1 + l2), std::fabs(l1 - l2));
}

namespace {

// Rows are summed by weighted_rows (filters.h), in convolve_cols's order; sources outside the
// image are rows of zeros: adding t * 0 = +-0 to a sum that starts at +0 never changes it.
// A 1-D filter without its zero taps: t * x = +-0 for finite x leaves the sum unchanged,
// and the derivative filters have 1 or 2 zeros in 5 taps (a quarter of the work).
// Tap taps[k] multiplies the sample at offset ct - k; kept in ascending k.
struct SparseTaps {
    std::vector<double> taps;
    std::vector<int> offsets;
    explicit SparseTaps(const std::vector<double>& all) {
        const int ct = int(all.size() / 2);
        for (std::size_t k = 0; k < all.size(); ++k)
            if (all[k] != 0.0) {
                taps.push_back(all[k]);
                offsets.push_back(ct - int(k));
            }
    }
};

}  // namespace

Grid<double> mmsodd(const Grid<double>& im, int smoothing_order, Border border) {
    std::vector<double> b = binomial_taps(smoothing_order);
    if (b.empty()) b = {1.0};
    const std::vector<double> d2 = compose_taps(derivative2_taps(), b);
    const std::vector<double> d1 = compose_taps(derivative1_taps(), b);
    const std::vector<double>* hx[3] = {&d2, &b, &d1};  // x taps of fxx, fyy, fxy
    const std::vector<double>* hy[3] = {&b, &d2, &d1};  // y taps
    const int w = im.width, h = im.height;
    Grid<double> out(w, h);
    if (w <= 0 || h <= 0) return out;

    if (border != Border::zero) {
        // Replication is not used by the methods; the general filters serve it.
        Grid<double> f[3];
        for (int i = 0; i < 3; ++i)
            f[i] = convolve_cols(convolve_rows(im, *hx[i], border), *hy[i], border);
        for (std::size_t i = 0; i < out.data.size(); ++i)
            out.data[i] = mmsodd_value(f[0].data[i], f[1].data[i], f[2].data[i]);
        return out;
    }

    // One sweep down the image: each input row is filtered along x by the three x filters into a
    // ring of the last `span` filtered rows, and as soon as the rows an output row needs along y
    // are in the ring, its three derivatives and the MMSODD are computed. Nothing image-sized is
    // allocated but the result (the three full derivative grids cost 19 MB on bull before).
    const int c = int(d2.size() / 2);  // the widest half-length (d1 and d2 have b's plus one)
    const int span = 2 * c + 1;
    const std::size_t uw = std::size_t(w);
    std::vector<double> padded(uw + 2 * std::size_t(c), 0.0), zeros(uw, 0.0);
    std::vector<double> ring(3 * std::size_t(span) * uw), deriv(3 * uw);
    auto ring_row = [&](int i, int y) { return ring.data() + (std::size_t(i) * std::size_t(span) + std::size_t(y % span)) * uw; };
    std::vector<SparseTaps> sx, sy;
    for (int i = 0; i < 3; ++i) {
        sx.emplace_back(*hx[i]);
        sy.emplace_back(*hy[i]);
    }
    std::vector<const double*> src(std::size_t(span), nullptr);
    for (int j = 0; j < h + c; ++j) {
        if (j < h) {
            std::copy(&im(0, j), &im(0, j) + w, padded.begin() + c);
            for (int i = 0; i < 3; ++i) {
                const SparseTaps& f = sx[std::size_t(i)];
                for (std::size_t k = 0; k < f.taps.size(); ++k) src[k] = padded.data() + c + f.offsets[k];
                weighted_rows(src.data(), f.taps.data(), int(f.taps.size()), ring_row(i, j), w);
            }
        }
        const int y = j - c;
        if (y < 0) continue;
        for (int i = 0; i < 3; ++i) {
            const SparseTaps& f = sy[std::size_t(i)];
            for (std::size_t k = 0; k < f.taps.size(); ++k) {
                const int r = y + f.offsets[k];
                src[k] = r >= 0 && r < h ? ring_row(i, r) : zeros.data();
            }
            weighted_rows(src.data(), f.taps.data(), int(f.taps.size()), deriv.data() + std::size_t(i) * uw, w);
        }
        double* o = &out(0, y);
        for (int x = 0; x < w; ++x) o[x] = mmsodd_value(deriv[std::size_t(x)], deriv[uw + std::size_t(x)], deriv[2 * uw + std::size_t(x)]);
    }
    return out;
}

}  // namespace erd
