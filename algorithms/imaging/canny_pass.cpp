// The gradient pass of edge detection (canny_pass.h): steps 1 (gradient) and 3 (non-maxima
// suppression) streamed over the rows of the half-pixel grid, keeping the points above a rising
// lower bound of tau_low and the histogram of the large magnitudes.
#include "algorithms/imaging/canny_pass.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "algorithms/imaging/edge_linking.h"
#include "algorithms/imaging/float_bins.h"

namespace erd {

using namespace edge_flags;
using namespace canny_detail;

namespace {

// The gradient rows of step 1 (gradient_rows.h) from the image behind `sample`: a gray image's
// sample(x, y), or a colour image's channels combined (ColourSample).
template <class Sample, class MagRow, class Emit>
void step1_rows(int width, int W, int H, int y_begin, int y_end, const std::vector<double>& taps, Border border,
                const Sample& sample, MagRow mag_row, Emit emit) {
    gradient_rows(
        W, H, y_begin, y_end, taps, border, [&](int Y, float* r) { half_pixel_row(width, Y, sample, r); }, mag_row,
        emit);
}

template <class MagRow, class Emit>
void step1_rows(int width, int W, int H, int y_begin, int y_end, const std::vector<double>& taps, Border border,
                const ColourSample& colour, MagRow mag_row, Emit emit) {
    const Image& im = *colour.im;
    colour_gradient_rows(
        W, H, y_begin, y_end, taps, border, colour.how,
        [&](int c, int Y, float* r) { half_pixel_row(width, Y, [&](int x, int y) { return im.at(x, y, c); }, r); },
        mag_row, emit);
}

// Step 3 at point X of row `mid` of the magnitude plane (rows up and down are its neighbours, all
// three with the replicated frame column on either side) with gradient (ux, uy): g is compared with
// g linearly interpolated where the gradient line crosses the 3x3 ring, ahead and behind. Returns
// kCandidate and kSecondary (a maximum in any of the four directions, step 5).
inline std::uint8_t suppress(const float* up, const float* mid, const float* down, int X, float ux, float uy) {
    const float m = mid[X];
    const float aux = std::fabs(ux), auy = std::fabs(uy);
    const int sx = ux > 0 ? 1 : -1;
    const float* fwd = uy > 0 ? down : up;  // the row on the side uy points to (uy = 0: up)
    const float* bwd = uy > 0 ? up : down;
    float ahead, behind;
    if (aux >= auy) {
        const float w = auy / aux;
        ahead = (1.0f - w) * mid[X + sx] + w * fwd[X + sx];
        behind = (1.0f - w) * mid[X - sx] + w * bwd[X - sx];
    } else {
        const float w = aux / auy;
        ahead = (1.0f - w) * fwd[X] + w * fwd[X + sx];
        behind = (1.0f - w) * bwd[X] + w * bwd[X - sx];
    }
    std::uint8_t fl = (m > ahead && m >= behind) ? kCandidate : kNone;
    if ((m > mid[X - 1] && m > mid[X + 1]) || (m > up[X] && m > down[X]) || (m > up[X - 1] && m > down[X + 1]) ||
        (m > up[X + 1] && m > down[X - 1]))
        fl |= kSecondary;
    return fl;
}

// How many of v[0..n) are >= low.
inline std::size_t count_at_least(const float* v, std::size_t n, float low) {
    std::size_t c = 0, k = 0;
    for (; k + 8 <= n; k += 8) c += std::size_t(count_at_least8(v + k, low));
    for (; k < n; ++k) c += v[k] >= low;
    return c;
}

// The streaming pass's guess of its final bound (EdgeDetector::Pass::sampled_bound): runs of
// kSampleRun rows of the half-pixel grid, one every kSampleStride rows, are sampled (runs
// rather than single rows: a run's rows share their smoothed neighbours), and the guess is
// kGuessMargin times the sample's estimate. The estimate was within 0.97-1.09 of the final
// bound on bull, lena, peppers, cameraman, house, phantom and ct_head at beta 0.01, 0.055 and
// 0.2, 1.15 at worst (ct_head, 0.2); a guess above the final bound costs a second pass.
constexpr int kSampleStride = 32;
constexpr std::size_t kSampleRun = 2;
constexpr double kGuessMargin = 0.8;

// A band of the gradient pass holds at least this many points of the plane (lena's 1023^2 grid:
// two bands; a band is a few milliseconds of work, a thread's start tens of microseconds); the
// sample's runs are shared out by a quarter of it.
constexpr std::size_t kMinBandPoints = std::size_t(1) << 18;

}  // namespace

template <class Sample>
void EdgeDetector::Pass::run(int width, int height, Sample sample, const CannyParams& params, std::size_t k_high) {
    pl = Plane(2 * width - 1, 2 * height - 1);
    smoothing_order = params.smoothing_order;
    border = params.border;
    std::size_t expected = 0;  // points the guess is expected to keep
    const float guess = sampled_bound(width, sample, params, k_high, &expected);
    if (!stream(width, sample, params, k_high, guess, expected)) stream(width, sample, params, k_high, 0.0f, expected);
    // Only the points at or above the final bound can be strong in a detection this pass
    // covers; with narrow bins they are hardly more than the first detection's strong points.
    // Compacted in place and cut to size.
    drop_below(low);
    for (std::size_t k = 0; k < n_kept; ++k) flag[k] = std::uint8_t(flag[k] << kPassShift);
    mag.resize(n_kept);
    flag.resize(n_kept);
    kept.adopt(std::move(cells), pl.stride, n_kept);
    n_kept = capacity = 0;
    trim_hist();
}

void EdgeDetector::Pass::trim_hist() {
    std::size_t top = hist.size();
    while (top > floor_bin && hist[top - 1] == 0) --top;
    std::vector<std::size_t>(hist.begin() + std::ptrdiff_t(floor_bin), hist.begin() + std::ptrdiff_t(top)).swap(hist);
    hist_base = floor_bin;
}

auto EdgeDetector::Pass::at_least(float bound, std::size_t* n) {
    return [g = mag.data(), f = flag.data(), bound, n](std::uint32_t k, std::uint32_t) {
        if (!(g[k] >= bound)) return false;
        g[*n] = g[k];
        f[*n] = f[k];
        ++*n;
        return true;
    };
}

void EdgeDetector::Pass::drop_below(float bound) {
    std::size_t n = 0;
    remove_bits_unless(cells.data(), n_kept, at_least(bound, &n));
    n_kept = n;
}

void EdgeDetector::Pass::narrow(const CannyParams& widest) {
    const std::size_t k = k_of(widest.beta, std::size_t(pl.w) * std::size_t(pl.h));
    if (at_or_above_floor < k) return;  // no such detection is covered
    while (at_or_above_floor - count(floor_bin) >= k) at_or_above_floor -= count(floor_bin++);
    const float bound = float(widest.r * double(bin_floor(floor_bin)));
    if (!(bound > low)) return;
    low = bound;
    std::size_t n = 0;
    kept.remove_unless(at_least(bound, &n));
    mag.resize(n);
    flag.resize(n);
}

namespace {
// The row bands of a plane of w x h points at `threads` threads.
RowParts band_parts(int w, int h, int threads) {
    return RowParts(0, std::size_t(h), threads, rows_for(kMinBandPoints, std::size_t(w)));
}
}  // namespace

std::size_t gradient_pass_bands(int width, int height, int threads) {
    if (width < 1 || height < 1) return 1;
    return band_parts(2 * width - 1, 2 * height - 1, threads).count;
}

void EdgeDetector::Pass::make_store(std::size_t expected) {
    capacity = expected + expected / 4 + 2 * std::size_t(pl.w);
    mag.resize(capacity);
    flag.resize(capacity);
}

template <class Sample>
bool EdgeDetector::Pass::stream(int width, Sample sample, const CannyParams& params, std::size_t k_high, float guess,
                                std::size_t expected) {
    const RowParts parts = band_parts(pl.w, pl.h, params.threads);
    if (parts.count > 1) return stream_bands(parts, width, sample, params, k_high, guess, expected);
    if (expected > 0 && capacity == 0) make_store(expected);
    return stream_rows(width, sample, params, k_high, guess, 0, pl.h, 0);
}

template <class Sample>
bool EdgeDetector::Pass::stream_bands(const RowParts& parts, int width, Sample sample, const CannyParams& params,
                                      std::size_t k_high, float guess, std::size_t expected) {
    const std::size_t nb = parts.count;
    std::vector<Pass> bands(nb);
    const std::size_t words = pl.cells() / 64 + 2;
    // Band 0's bit plane is the whole plane's (from word 0): the pass takes it over, with its
    // arrays and counts, and the other bands are added to them.
    auto word0 = [&](std::size_t k) { return k == 0 ? 0 : std::size_t(pl.at(0, int(parts.part_begin(k)))) >> 6; };
    run_parts(parts, [&](std::size_t k, std::size_t y0, std::size_t y1) {
        Pass& b = bands[k];
        b.pl = pl;
        if (expected > 0) b.make_store(std::size_t(double(expected) * double(y1 - y0) / double(pl.h)));
        b.stream_rows(width, sample, params, k_high, guess, int(y0), int(y1), word0(k));
    });
    // The counts from the highest band bin up, then the final bin as one pass finds it.
    std::uint32_t top = 0;
    for (const Pass& b : bands) top = std::max(top, b.floor_bin);
    hist = std::move(bands[0].hist);
    hist_base = 0;
    at_or_above_floor = 0;
    for (std::size_t bin = top; bin < kFloatBins; ++bin) {
        for (std::size_t k = 1; k < nb; ++k) hist[bin] += bands[k].hist[bin];
        at_or_above_floor += hist[bin];
    }
    floor_bin = top;
    while (at_or_above_floor - hist[floor_bin] >= k_high) at_or_above_floor -= hist[floor_bin++];
    low = float(params.r * double(bin_floor(floor_bin)));
    if (low < guess) return false;
    // Each band keeps what is at or above the final bound (its own bound is at most that), and
    // the bands are joined in row order.
    std::size_t total = 0;
    for (Pass& b : bands) {
        b.drop_below(low);
        total += b.n_kept;
    }
    std::size_t at = bands[0].n_kept;
    mag = std::move(bands[0].mag);
    flag = std::move(bands[0].flag);
    cells = std::move(bands[0].cells);
    capacity = n_kept = total;
    mag.resize(total);
    flag.resize(total);
    for (std::size_t k = 1; k < nb; ++k) {
        Pass& b = bands[k];
        std::copy(b.mag.data(), b.mag.data() + b.n_kept, mag.data() + at);
        std::copy(b.flag.data(), b.flag.data() + b.n_kept, flag.data() + at);
        at += b.n_kept;
        const std::size_t w0 = word0(k);
        for (std::size_t w = 0; w < b.cells.size() && w0 + w < words; ++w) cells[w0 + w] |= b.cells[w];
        b.clear();
    }
    return true;
}

template <class Sample>
bool EdgeDetector::Pass::stream_rows(int width, Sample sample, const CannyParams& params, std::size_t k_high,
                                     float guess, int y0, int y1, std::size_t word0) {
    const int W = pl.w, H = pl.h;
    const std::size_t rs = std::size_t(W) + 2;  // a row of g with its replicated frame columns
    std::vector<float> rows(3 * rs);
    auto row = [&](int Y) { return rows.data() + std::size_t(Y % 3) * rs + 1; };
    hist.assign(kFloatBins, 0);
    hist_base = 0;
    floor_bin = 0;
    at_or_above_floor = 0;
    n_kept = 0;
    // The words of rows y0 .. y1 - 1 from word0 on, and one spare word (PointBits).
    const std::size_t last = y1 > y0 ? std::size_t(pl.at(W - 1, y1 - 1)) >> 6 : word0;
    cells.assign(word0 == 0 ? pl.cells() / 64 + 2 : last - word0 + 2, 0);
    low = guess;
    const float* prev_gx = nullptr;  // components of the row before the last one emitted
    const float* prev_gy = nullptr;
    // Counts row y's magnitudes at or above the bound, suppresses and keeps its points, then
    // raises the bound.
    auto finish_row = [&](int y, const float* gx, const float* gy) {
        if (capacity < n_kept + std::size_t(W)) make_room(std::size_t(W));
        const float* up = row(y > 0 ? y - 1 : 0);
        const float* mid = row(y);
        const float* down = row(y + 1 < H ? y + 1 : y);
        const std::uint32_t base = std::uint32_t(pl.at(0, y));
        std::uint64_t* c = cells.data();
        float* g = mag.data();
        std::uint8_t* f = flag.data();
        std::size_t n = n_kept, counted = 0;
        for_each_at_least(mid, std::size_t(W), low, [&](std::size_t X) {
            const float v = mid[X];
            const std::uint32_t b = float_bin(v);
            if (b >= floor_bin) {
                ++hist[b];
                ++counted;
            }
            if (v <= 0.0f) return;
            const std::uint32_t q = base + std::uint32_t(X);
            c[(q >> 6) - word0] |= std::uint64_t(1) << (q & 63u);
            g[n] = v;
            f[n] = suppress(up, mid, down, int(X), gx[X], gy[X]);
            ++n;
        });
        n_kept = n;
        at_or_above_floor += counted;
        while (at_or_above_floor - hist[floor_bin] >= k_high) at_or_above_floor -= hist[floor_bin++];
        low = std::max(guess, float(params.r * double(bin_floor(floor_bin))));
    };
    // Rows y0 - 1 and y1 are made for their neighbours' suppression only.
    step1_rows(
        width, W, H, std::max(0, y0 - 1), std::min(H, y1 + 1), binomial_taps(params.smoothing_order), params.border,
        sample, row, [&](int y, const float* ax, const float* ay) {
            float* r = row(y);
            r[-1] = r[0];
            r[W] = r[W - 1];
            if (y - 1 >= y0) finish_row(y - 1, prev_gx, prev_gy);
            if (y == H - 1 && y < y1) finish_row(y, ax, ay);
            prev_gx = ax;
            prev_gy = ay;
        });
    low = float(params.r * double(bin_floor(floor_bin)));
    return !(low < guess);
}

template <class Sample>
float EdgeDetector::Pass::sampled_bound(int width, Sample sample, const CannyParams& params, std::size_t k_high,
                                        std::size_t* expected, std::size_t* at_estimate) const {
    *expected = 0;
    const int W = pl.w, H = pl.h;
    const std::size_t blocks = std::size_t(H / kSampleStride), n = blocks * kSampleRun * std::size_t(W);
    const double rank = double(k_high) * double(n) / (double(W) * double(H));
    if (blocks < 8 || rank < 64.0) return 0.0f;
    std::vector<float> g(n);
    const std::vector<double> taps = binomial_taps(params.smoothing_order);
    // The runs on the pass's threads, each into its own rows of g.
    parallel_rows(0, blocks, params.threads, rows_for(kMinBandPoints / 4, kSampleRun * std::size_t(W)),
                  [&](std::size_t b0, std::size_t b1) {
                      for (std::size_t i = b0; i < b1; ++i) {
                          const int y = int(i) * kSampleStride + kSampleStride / 2;
                          step1_rows(
                              width, W, H, y, y + int(kSampleRun), taps, params.border, sample,
                              [&](int Y) { return g.data() + (i * kSampleRun + std::size_t(Y - y)) * std::size_t(W); },
                              [](int, const float*, const float*) {});
                      }
                  });
    const std::size_t k = std::size_t(rank) - 1;  // the rank-th largest
    std::nth_element(g.begin(), g.begin() + std::ptrdiff_t(k), g.end(), std::greater<float>());
    const float guess = float(kGuessMargin * params.r * double(g[k]));
    const double scale = double(W) * double(H) / double(n);
    *expected = std::size_t(double(count_at_least(g.data(), n, guess)) * scale);
    if (at_estimate) {
        // The pass keeps no zero magnitude (a flat image keeps nothing).
        const float bound = std::max(float(params.r * double(g[k])), std::nextafter(0.0f, 1.0f));
        *at_estimate = std::size_t(double(count_at_least(g.data(), n, bound)) * scale);
    }
    return guess;
}

void EdgeDetector::Pass::make_room(std::size_t more) {
    drop_below(low);
    if (capacity < 2 * (n_kept + more)) {
        capacity = 4 * (n_kept + more);
        mag.resize(capacity);
        flag.resize(capacity);
    }
}

// The images a pass runs on (canny.cpp).
template void EdgeDetector::Pass::run(int, int, GraySample, const CannyParams&, std::size_t);
template void EdgeDetector::Pass::run(int, int, GridSample, const CannyParams&, std::size_t);
template void EdgeDetector::Pass::run(int, int, ColourSample, const CannyParams&, std::size_t);
template float EdgeDetector::Pass::sampled_bound(int, GraySample, const CannyParams&, std::size_t, std::size_t*,
                                                 std::size_t*) const;

}  // namespace erd
