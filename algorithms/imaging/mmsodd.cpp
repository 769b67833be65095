#include "algorithms/imaging/mmsodd.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "kernel/row_parallel.h"

namespace erd {

double mmsodd_value(double fxx, double fyy, double fxy) {
    const double l1 = 0.5 * (fxx + fyy);
    const double half_diff = 0.5 * (fxx - fyy);
    const double l2 = std::sqrt(half_diff * half_diff + fxy * fxy);
    // max(|l1 + l2|, |l1 - l2|) with l2 >= 0 is |l1| + l2, and rounding is monotone and
    // symmetric, so the rounded forms agree too: the larger of the two rounded magnitudes is
    // always the rounded |l1| + l2.
    return std::fabs(l1) + l2;
}

namespace {

// The zero-border MMSODD of a w x h row-major array of samples (double or 16-bit integers),
// sample (x, y) at samples[(y*w + x) * stride] (stride > 1: one channel of interleaved samples).
//
// Output rows y0 .. y1 - 1 only (the sweep starts c + 2 input rows above y0): each S row is made
// from the input alone, so a band's rows are the bits of a whole-image sweep, and the bands of
// mmsodd_zero's threads can run side by side.
template <class T>
void mmsodd_zero_rows(const T* samples, int w, int h, const std::vector<double>& b, std::size_t stride, int y0, int y1,
                      MmsoddInto into, Grid<double>* grid) {
    Grid<double>& out = *grid;

    // Noise removal first, then the derivatives, as two filtering passes that each extend their
    // input by zeros (docs/DECISIONS.md "ERD reproduction"): S = b_x b_y f on the image, zero
    // outside it; fxx = [1 -2 1]_x S, fyy = [1 -2 1]_y S, fxy = [1/2 0 -1/2]_x [1/2 0 -1/2]_y S.
    // For integer samples (every method's input) below 2^16 and orders up to 17 every product
    // is an integer times a dyadic tap and every sum stays far inside 53 bits, so any order of
    // the additions gives the same bits (tested against mmsodd_separable); for other samples the
    // two agree to rounding.
    //
    // One sweep down the image: each input row is smoothed along x into a ring of the last
    // 2c+1 such rows (c = order / 2); each S row is their weighted sum; each output row needs
    // the S rows above, at and below it, kept in a ring of three.
    const int c = int(b.size() / 2), span = 2 * c + 1;
    const std::size_t ew = std::size_t(w) + 2;  // S and the x-smoothed rows cover x = -1 .. w
    std::vector<double> padded(ew + 2 * std::size_t(c), 0.0);  // padded[x + c + 1] = f(x, r)
    std::vector<double> hring(std::size_t(span) * ew), sring(3 * ew), zeros(ew, 0.0);
    auto hrow = [&](int r) { return hring.data() + std::size_t(r % span) * ew; };
    auto srow = [&](int j) { return sring.data() + std::size_t((j + 3) % 3) * ew; };
    std::vector<const double*> src(std::size_t(span), nullptr);
    int next = std::max(0, y0 - 1 - c);  // the next input row to smooth along x
    for (int j = y0 - 1; j <= y1; ++j) {
        for (; next < h && next <= j + c; ++next) {
            const T* row = samples + std::size_t(next) * std::size_t(w) * stride;
            if (stride == 1) std::copy(row, row + w, padded.begin() + c + 1);
            else for (int x = 0; x < w; ++x) padded[std::size_t(x + c + 1)] = double(row[std::size_t(x) * stride]);
            // Smoothed sample x - 1 = sum_k b[k] f(x - 1 + c - k) = sum_k b[k] padded[x + 2c - k].
            for (int k = 0; k < span; ++k) src[std::size_t(k)] = padded.data() + 2 * c - k;
            weighted_rows(src.data(), b.data(), span, hrow(next), int(ew));
        }
        for (int k = 0; k < span; ++k) {
            const int r = j + c - k;
            src[std::size_t(k)] = r >= 0 && r < h ? hrow(r) : zeros.data();
        }
        weighted_rows(src.data(), b.data(), span, srow(j), int(ew));
        // The derivatives see S zero-extended in turn (two filtering passes, each with zero
        // extension): S is kept only on the image, not one sample beyond it.
        double* const sr = srow(j);
        if (j < 0 || j >= h) std::fill(sr, sr + ew, 0.0);
        sr[0] = 0.0;
        sr[ew - 1] = 0.0;
        const int y = j - 1;
        if (y < y0) continue;
        // S rows y-1, y, y+1 are complete; index x + 1 holds sample x.
        const double* up = srow(y - 1);
        const double* mid = srow(y);
        const double* down = srow(y + 1);
        double* o = &out(0, y);
        for (int x = 0; x < w; ++x) {
            const double fxx = (mid[x + 2] + mid[x]) - 2.0 * mid[x + 1];
            const double fyy = (down[x + 1] + up[x + 1]) - 2.0 * mid[x + 1];
            const double fxy = 0.25 * ((down[x + 2] - down[x]) - (up[x + 2] - up[x]));
            const double v = mmsodd_value(fxx, fyy, fxy);
            o[x] = into == MmsoddInto::store ? v : into == MmsoddInto::add ? o[x] + v : std::max(o[x], v);
        }
    }
}

// One band per thread, each of 2^15 pixels at least (~0.3 ms) and 16 rows: a band smooths again
// the c + 2 rows above it that the band before it smoothed too, a cost only a band that short
// would notice.
template <class T>
void mmsodd_zero_into(const T* samples, int w, int h, const std::vector<double>& b, int threads, std::size_t stride,
                      MmsoddInto into, Grid<double>* out) {
    if (w <= 0 || h <= 0) return;
    parallel_rows(0, std::size_t(h), threads, std::max<std::size_t>(16, rows_for(std::size_t(1) << 15, std::size_t(w))), [&](std::size_t y0, std::size_t y1) {
        mmsodd_zero_rows(samples, w, h, b, stride, int(y0), int(y1), into, out);
    });
}

template <class T>
Grid<double> mmsodd_zero(const T* samples, int w, int h, const std::vector<double>& b, int threads, std::size_t stride = 1) {
    Grid<double> out(w, h);
    mmsodd_zero_into(samples, w, h, b, threads, stride, MmsoddInto::store, &out);
    return out;
}

std::vector<double> smoothing_taps(int order) {
    std::vector<double> b = binomial_taps(order);
    if (b.empty()) b = {1.0};
    return b;
}

}  // namespace

Grid<double> mmsodd_separable(const Grid<double>& im, int smoothing_order, Border border) {
    const std::vector<double> b = smoothing_taps(smoothing_order);
    const Grid<double> smooth = convolve_cols(convolve_rows(im, b, border), b, border);
    const Grid<double> fxx = convolve_rows(smooth, derivative2_taps(), border);
    const Grid<double> fyy = convolve_cols(smooth, derivative2_taps(), border);
    const Grid<double> fxy = convolve_cols(convolve_rows(smooth, derivative1_taps(), border), derivative1_taps(), border);
    Grid<double> out(im.width, im.height);
    for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = mmsodd_value(fxx.data[i], fyy.data[i], fxy.data[i]);
    return out;
}

Grid<double> mmsodd(const Grid<double>& im, int smoothing_order, Border border, int threads) {
    // Replication is not used by the methods; the general filters serve it.
    if (border != Border::zero) return mmsodd_separable(im, smoothing_order, border);
    return mmsodd_zero(im.data.data(), im.width, im.height, smoothing_taps(smoothing_order), threads);
}

Grid<double> mmsodd(const Image& im, int smoothing_order, int threads) {
    return mmsodd_zero(im.samples.data(), im.width, im.height, smoothing_taps(smoothing_order), threads);
}

Grid<double> mmsodd_channel(const Image& im, int channel, int smoothing_order, int threads) {
    return mmsodd_zero(im.samples.data() + channel, im.width, im.height, smoothing_taps(smoothing_order), threads,
                       std::size_t(im.channels));
}

void mmsodd_channel_into(const Image& im, int channel, int smoothing_order, MmsoddInto into, Grid<double>* out,
                         int threads) {
    mmsodd_zero_into(im.samples.data() + channel, im.width, im.height, smoothing_taps(smoothing_order), threads,
                     std::size_t(im.channels), into, out);
}

}  // namespace erd
