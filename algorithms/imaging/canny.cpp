#include "algorithms/imaging/canny.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "algorithms/imaging/edge_linking.h"
#include "algorithms/imaging/float_bins.h"
#include "algorithms/imaging/gradient_rows.h"
#include "algorithms/imaging/point_rings.h"
#include "algorithms/imaging/raw_array.h"
#include "algorithms/imaging/thinning.h"

namespace erd {

using namespace edge_flags;
using namespace canny_detail;

namespace {

// The gradient rows of step 1 (gradient_rows.h) from the image behind `sample`: a gray image's
// sample(x, y), or a colour image's channels combined (ColourSample).
struct ColourSample {
    const Image* im;
    ColourGradient how;
};

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

// Points of the half-pixel grid in a plane with a one-point frame: index (Y + 1) * stride + X + 1.
struct Plane {
    int w = 0, h = 0, stride = 0;
    Plane() = default;
    Plane(int width, int height) : w(width), h(height), stride(round8(width + 2) + 8) {}
    std::size_t cells() const { return std::size_t(stride) * std::size_t(h + 2); }
    std::ptrdiff_t at(int X, int Y) const { return std::ptrdiff_t(Y + 1) * stride + X + 1; }
};

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

// How many of p[0..8) are >= low: a count rather than a flag, so that -O2 vectorises it.
inline int count_at_least8(const float* p, float low) {
    int n = 0;
    for (int j = 0; j < 8; ++j) n += p[j] >= low;
    return n;
}

// Calls fn(k) for each k in [0, n) with v[k] >= low, in increasing order, skipping blocks of eight
// below low with one vectorised test (most of a magnitude row is below every bound).
template <class Fn>
void for_each_at_least(const float* v, std::size_t n, float low, Fn fn) {
    std::size_t k = 0;
    for (; k + 8 <= n; k += 8)
        if (count_at_least8(v + k, low))
            for (std::size_t j = k; j < k + 8; ++j)
                if (v[j] >= low) fn(j);
    for (; k < n; ++k)
        if (v[k] >= low) fn(k);
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

Status check_params(const CannyParams& params) {
    if (!(params.beta > 0.0 && params.beta <= 1.0)) return Status::bad_input("edge detection: beta must lie in (0, 1]");
    if (!(params.r >= 0.0 && params.r <= 1.0)) return Status::bad_input("edge detection: r must lie in [0, 1]");
    if (params.smoothing_order < 1 || params.smoothing_order % 2 == 0 || params.smoothing_order > 51)
        return Status::bad_input("edge detection: smoothing order must be odd, 1 to 51");
    if (params.max_link < 0 || params.max_link > 250) return Status::bad_input("edge detection: max_link must lie in [0, 250]");
    return Status::success();
}

}  // namespace

// Steps 1 and 3 for one image: for the points above a lower bound of tau_low, their magnitude and
// their non-maxima flags, and the histogram of the large magnitudes. Flags depend on the gradient
// alone, not on the thresholds, so steps 2 to 6 read the pass without changing it and it serves
// several detections.
struct EdgeDetector::Pass {
    Plane pl;  // index space of the points (never allocated)
    int smoothing_order = 0;
    Border border = Border::replicate;
    // While the pass runs: the kept points as one bit per plane cell, and in row-major order
    // their g and step 3's kCandidate | kSecondary, in raw arrays, because it makes room for a
    // row before it appends to them.
    std::vector<std::uint64_t> cells;
    RawArray<float> mag;
    RawArray<std::uint8_t> flag;
    std::size_t n_kept = 0, capacity = 0;
    // After it: the points at or above the final bound as a set of cells, linked once for every
    // detection, and the same arrays cut to them: g and the flag bytes (edge_linking.h: the pass's
    // flags in the pass bits, one detection's in the others).
    PointBits kept;
    std::vector<std::size_t> hist;          // bins hist_base.. (exact for the bins >= floor_bin)
    std::uint32_t hist_base = 0;            // 0 while the pass runs, floor_bin after (trim_hist)
    std::uint32_t floor_bin = 0;            // bin of the k-th largest (0 until k values)
    std::size_t at_or_above_floor = 0;      // values in the bins >= floor_bin
    float low = 0.0f;                       // the last (largest) bound points were kept above

    // The streaming pass. The k-th largest magnitude so far, known to its bin, only grows: so
    // r times that bin's floor is a lower bound of tau_low, and only points at or above it are
    // suppressed and kept; values in bins below the bound's bin cannot decide the quantile, so
    // only the others are counted (they are all >= the bound). Row y is counted and suppressed
    // in one scan once row y + 1 exists, so three rows of g are all the plane there is. The
    // bound then lags one row behind the rows made (a lower bound is still a bound); the final
    // bin, the counts at and above it and the points kept at the end do not depend on when the
    // bound rose.
    // In row order the bound stays low while the pass crosses flat rows (lena: 340K of 539K
    // suppressions were for points below the final bound), so the pass starts from a guess of
    // the final bound made from a sample of the rows (sampled_bound). Every value it skips is below
    // the guess; if the final bound is at or above the guess, the skipped values could neither
    // be kept nor be counted in a bin at or above the final one, so the result is the one
    // without a guess (the final bin can only be reached from below: it is the k-th largest's
    // when every value of the bins above was counted). Otherwise the pass runs again without.
    template <class Sample>
    void run(int width, int height, Sample sample, const CannyParams& params, std::size_t k_high) {
        pl = Plane(2 * width - 1, 2 * height - 1);
        smoothing_order = params.smoothing_order;
        border = params.border;
        std::size_t expected = 0;  // points the guess is expected to keep
        const float guess = sampled_bound(width, sample, params, k_high, &expected);
        // Room for them up front (a quarter more): the store then rarely fills, and a full one
        // is compacted and copied (growing it from empty was a real share of the pass).
        if (expected > 0) {
            capacity = expected + expected / 4 + 2 * std::size_t(pl.w);
            mag.resize(capacity);
            flag.resize(capacity);
        }
        if (!stream(width, sample, params, k_high, guess)) stream(width, sample, params, k_high, 0.0f);
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

    // After the pass only the bins from floor_bin up are read (kth_bin stops at the k-th
    // largest's, which is at or above it; narrow() only raises it), and none above the largest
    // value: the counts keep those (256 KB -> a few hundred bins on a photo).
    void trim_hist() {
        std::size_t top = hist.size();
        while (top > floor_bin && hist[top - 1] == 0) --top;
        std::vector<std::size_t>(hist.begin() + std::ptrdiff_t(floor_bin), hist.begin() + std::ptrdiff_t(top)).swap(hist);
        hist_base = floor_bin;
    }
    std::size_t count(std::uint32_t bin) const { return hist[bin - hist_base]; }

    // The test that keeps stored point k when its g is at least `bound` (remove_bits_unless),
    // moving the g and flags of the points kept down to *n, n + 1, ... in order.
    auto at_least(float bound, std::size_t* n) {
        return [g = mag.data(), f = flag.data(), bound, n](std::uint32_t k, std::uint32_t) {
            if (!(g[k] >= bound)) return false;
            g[*n] = g[k];
            f[*n] = f[k];
            ++*n;
            return true;
        };
    }

    // Drops the stored points with g below `bound`, keeping the order of the others.
    void drop_below(float bound) {
        std::size_t n = 0;
        remove_bits_unless(cells.data(), n_kept, at_least(bound, &n));
        n_kept = n;
    }

    // Keeps only what the detections `widest` covers can use (a beta at most its, its r), as if
    // the pass had been made for it: the bins below its k-th largest's go from the counts, the
    // points below r times that bin's floor from the store.
    void narrow(const CannyParams& widest) {
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

    // One streaming pass from the bound `guess` (0: none); false when the final bound is below
    // the guess (the result is then incomplete). On success `low` is the final bound.
    template <class Sample>
    bool stream(int width, Sample sample, const CannyParams& params, std::size_t k_high, float guess) {
        const int W = pl.w, H = pl.h;
        const std::size_t rs = std::size_t(W) + 2;  // a row of g with its replicated frame columns
        std::vector<float> rows(3 * rs);
        auto row = [&](int Y) { return rows.data() + std::size_t(Y % 3) * rs + 1; };
        hist.assign(kFloatBins, 0);
        hist_base = 0;
        floor_bin = 0;
        at_or_above_floor = 0;
        n_kept = 0;
        cells.assign(pl.cells() / 64 + 2, 0);  // one spare word (PointBits)
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
                c[q >> 6] |= std::uint64_t(1) << (q & 63u);
                g[n] = v;
                f[n] = suppress(up, mid, down, int(X), gx[X], gy[X]);
                ++n;
            });
            n_kept = n;
            at_or_above_floor += counted;
            while (at_or_above_floor - hist[floor_bin] >= k_high) at_or_above_floor -= hist[floor_bin++];
            low = std::max(guess, float(params.r * double(bin_floor(floor_bin))));
        };
        step1_rows(
            width, W, H, 0, H, binomial_taps(params.smoothing_order), params.border, sample, row,
            [&](int y, const float* ax, const float* ay) {
                float* r = row(y);
                r[-1] = r[0];
                r[W] = r[W - 1];
                if (y > 0) finish_row(y - 1, prev_gx, prev_gy);
                if (y == H - 1) finish_row(y, ax, ay);
                prev_gx = ax;
                prev_gy = ay;
            });
        low = float(params.r * double(bin_floor(floor_bin)));
        return !(low < guess);
    }

    // A guess of the streaming pass's final bound: r times the magnitude of the same rank among
    // the sampled rows as tau_high has among all, less a margin (kGuessMargin). A sampled run
    // costs about twice as much a row as the stream (its smoothed neighbours are made for it
    // alone): 1.6% of the rows at twice the cost, ~3% of the pass. 0 (no guess) when the sample is too
    // small to rank. *expected: the sample's count at or above the guess, scaled to the grid.
    template <class Sample>
    float sampled_bound(int width, Sample sample, const CannyParams& params, std::size_t k_high,
                        std::size_t* expected, std::size_t* at_estimate = nullptr) const {
        *expected = 0;
        const int W = pl.w, H = pl.h;
        const std::size_t blocks = std::size_t(H / kSampleStride), n = blocks * kSampleRun * std::size_t(W);
        const double rank = double(k_high) * double(n) / (double(W) * double(H));
        if (blocks < 8 || rank < 64.0) return 0.0f;
        std::vector<float> g(n);
        const std::vector<double> taps = binomial_taps(params.smoothing_order);
        for (std::size_t i = 0; i < blocks; ++i) {
            const int y = int(i) * kSampleStride + kSampleStride / 2;
            step1_rows(
                width, W, H, y, y + int(kSampleRun), taps, params.border, sample,
                [&](int Y) { return g.data() + (i * kSampleRun + std::size_t(Y - y)) * std::size_t(W); },
                [](int, const float*, const float*) {});
        }
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

    // Room for `more` points: first drop the points the bound has risen past (they can never be
    // strong), then grow if still more than half full.
    void make_room(std::size_t more) {
        drop_below(low);
        if (capacity < 2 * (n_kept + more)) {
            capacity = 4 * (n_kept + more);
            mag.resize(capacity);
            flag.resize(capacity);
        }
    }

    // Steps 2 and 4 to 6. Returns false, having written nothing, when the pass does not cover the
    // parameters: a different filter, too few values counted for this beta, or a tau_low below
    // the bound. release = the pass is not used again: its arrays go as soon as they are read.
    bool track(const CannyParams& params, bool release, SortedPoints* edges, CannyStats* stats) {
        if (params.smoothing_order != smoothing_order || params.border != border) return false;
        const std::size_t M = std::size_t(pl.w) * std::size_t(pl.h);
        const std::size_t k_high = k_of(params.beta, M);
        if (at_or_above_floor < k_high) return false;  // the k-th largest is below the counted bins

        // 2. Thresholds: the bin of the k-th largest, then selection inside it. Every value in that
        // bin was at or above the bound of its time, so the kept points hold them all; bin 0 aside,
        // where only g = 0 is missing (never kept) and hist counts all of the bin.
        std::size_t above = 0, above_high = 0;
        const std::uint32_t bin = kth_bin(hist.data(), hist.size(), k_high, &above, hist_base);
        std::vector<float> in_bin;
        in_bin.reserve(count(bin));
        const std::size_t n = kept.size();
        const float* g = mag.data();
        for_each_at_least(g, n, bin_floor(bin), [&](std::size_t k) {
            if (float_bin(g[k]) == bin) in_bin.push_back(g[k]);
        });
        if (bin == 0) in_bin.resize(count(0), 0.0f);
        const double tau_high = select_in_bin(&in_bin, k_high, above, &above_high);
        const double tau_low = params.r * tau_high;
        std::vector<float>().swap(in_bin);
        const float th = float(tau_high), tl = float(tau_low);
        if (tl < low) return false;  // strong points may be missing

        // The kept points with g >= tau_low are the strong points, with the pass's flags this
        // detection uses; the others have none. Every point loses the last detection's flags.
        StrongPoints sp(kept);
        sp.mag = g;
        sp.flag = flag.data();
        const std::uint8_t used = params.modified ? std::uint8_t(kCandidate | kSecondary) : std::uint8_t(kCandidate);
        std::uint8_t* f = flag.data();
        std::size_t flagged = 0;
        kept.for_each([&](std::uint32_t k, std::uint32_t p) {
            std::uint8_t fk = std::uint8_t(f[k] & kPassFlags);
            if (g[k] >= tl) {
                fk = std::uint8_t(fk | ((fk >> kPassShift) & used));
                flagged += (fk & used) != 0;
                if ((fk & kCandidate) && g[k] >= th) sp.seeds.push_back(p);
            }
            f[k] = fk;
        });

        // 4, 5. The search's queue holds every point it labels: the flagged points at most (room
        // for them up front: no copy while it grows; pages it never fills cost nothing).
        const bool join = params.modified && params.max_link > 0;
        if (join) sp.mains.reserve(flagged);
        const std::size_t main_points = hysteresis(&sp);
        const std::size_t added = join ? join_components(&sp, params.max_link, tl) : 0;

        // 6. The main points, in row-major order, thinned as a sparse set.
        const std::size_t main_count = main_points + added;
        sp = StrongPoints(kept);  // the search's queue goes before the list is made
        SortedPoints mains;
        mains.stride = pl.stride;
        mains.at.reserve(main_count);
        kept.for_each([&](std::uint32_t k, std::uint32_t p) {
            if (f[k] & kMain) mains.at.push_back(p);
        });
        if (release) clear();
        if (params.thin) {
            std::vector<std::uint8_t> alive(mains.size(), 1);
            mains.link_rows();
            thin_points(mains, &alive);
            std::size_t kept_n = 0;  // the survivors, in place: not a second list beside the first
            for (std::size_t k = 0; k < mains.size(); ++k)
                if (alive[k]) mains.at[kept_n++] = mains.at[k];
            mains.at.resize(kept_n);
        }
        *edges = SortedPoints();
        edges->stride = pl.stride;
        edges->at = std::move(mains.at);
        const std::size_t edge_points = edges->size();
        if (stats) {
            stats->tau_high = tau_high;
            stats->tau_low = tau_low;
            stats->above_high = above_high;
            stats->main_points = main_points;
            stats->added_points = added;
            stats->edge_points = edge_points;
        }
        return true;
    }

    void clear() {
        kept.clear();
        mag.reset();
        flag.reset();
    }

    // k = round(beta * M), at least 1 (step 2).
    static std::size_t k_of(double beta, std::size_t M) {
        const double kd = std::nearbyint(beta * double(M));
        return kd < 1.0 ? 1 : (kd > double(M) ? M : std::size_t(kd));
    }
};

namespace {

template <class Sample>
Status detect_once(int width, int height, Sample sample, const CannyParams& params, Grid<std::uint8_t>* edges,
                   CannyStats* stats) {
    if (width <= 0 || height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(params);
    if (!st) return st;
    EdgeDetector::Pass pass;
    pass.run(width, height, sample, params, EdgeDetector::Pass::k_of(params.beta, std::size_t(2 * width - 1) * std::size_t(2 * height - 1)));
    SortedPoints points;
    pass.track(params, true, &points, stats);  // a pass covers the parameters it was made with
    *edges = edge_map(points, 2 * width - 1, 2 * height - 1);
    return Status::success();
}

}  // namespace

std::size_t estimated_kept_points(const Image& im, const CannyParams& params) {
    if (im.width <= 0 || im.height <= 0 || !check_params(params)) return 0;
    EdgeDetector::Pass pass;
    pass.pl = Plane(2 * im.width - 1, 2 * im.height - 1);
    const std::size_t M = std::size_t(pass.pl.w) * std::size_t(pass.pl.h);
    std::size_t expected = 0, at_estimate = M;  // too few rows to sample: the whole grid bounds it
    pass.sampled_bound(im.width, [&](int x, int y) { return im.at(x, y); }, params,
                       EdgeDetector::Pass::k_of(params.beta, M), &expected, &at_estimate);
    return std::min(at_estimate, M);
}

EdgeDetector::EdgeDetector(const Image& im, ColourGradient colour) : im_(im), colour_(colour) {}
EdgeDetector::~EdgeDetector() = default;

Status EdgeDetector::detect(const CannyParams& params, SortedPoints* edges, CannyStats* stats) {
    if (im_.width <= 0 || im_.height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(params);
    if (!st) return st;
    if (pass_ && narrowing_) pass_->narrow(narrow_);
    narrowing_ = false;
    if (pass_ && pass_->track(params, false, edges, stats)) return Status::success();
    make_pass(params);
    pass_->track(params, false, edges, stats);
    return Status::success();
}

Status EdgeDetector::prepare(const CannyParams& widest) {
    if (im_.width <= 0 || im_.height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(widest);
    if (st && !pass_) make_pass(widest);
    return st;
}

void EdgeDetector::narrow(const CannyParams& widest) {
    narrowing_ = pass_ && widest.smoothing_order == pass_->smoothing_order && widest.border == pass_->border;
    narrow_ = widest;
}

std::size_t EdgeDetector::pass_points() const { return pass_ ? pass_->kept.size() : 0; }

void EdgeDetector::make_pass(const CannyParams& params) {
    pass_.reset();  // the old pass goes before the new one is made
    pass_.reset(new Pass);
    const std::size_t M = std::size_t(2 * im_.width - 1) * std::size_t(2 * im_.height - 1);
    if (im_.channels == 3 && colour_ != ColourGradient::luma)
        pass_->run(im_.width, im_.height, ColourSample{&im_, colour_}, params, Pass::k_of(params.beta, M));
    else
        pass_->run(im_.width, im_.height, [&](int x, int y) { return im_.at(x, y); }, params, Pass::k_of(params.beta, M));
}

Status EdgeDetector::detect(const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    SortedPoints points;
    Status st = detect(params, &points, stats);
    if (st) *edges = edge_map(points, 2 * im_.width - 1, 2 * im_.height - 1);
    return st;
}

Grid<std::uint8_t> edge_map(const SortedPoints& points, int width, int height) {
    Grid<std::uint8_t> map(width, height, 0);
    const std::uint32_t s = std::uint32_t(points.stride);
    for (const std::uint32_t i : points.at) map(int(i % s) - 1, int(i / s) - 1) = 1;
    return map;
}

void EdgeDetector::release() {
    pass_.reset();
    narrowing_ = false;
}

void canny_gradient(const Grid<double>& f, int smoothing_order, Border border, Grid<float>* gx, Grid<float>* gy) {
    std::vector<double> b = binomial_taps(smoothing_order);
    if (b.empty()) b = {1.0};
    if (f.width <= 0 || f.height <= 0) { *gx = Grid<float>(); *gy = Grid<float>(); return; }
    *gx = Grid<float>(f.width, f.height);
    *gy = Grid<float>(f.width, f.height);
    std::vector<float> mag(std::size_t(f.width));
    gradient_rows(
        f.width, f.height, 0, f.height, b, border,
        [&](int y, float* r) {
            for (int x = 0; x < f.width; ++x) r[x] = float(f(x, y));
        },
        [&](int) { return mag.data(); },
        [&](int y, const float* ax, const float* ay) {
            std::copy(ax, ax + f.width, &(*gx)(0, y));
            std::copy(ay, ay + f.width, &(*gy)(0, y));
        });
}

double beta_quantile(const float* values, std::size_t n, double beta) {
    if (n == 0) return 0.0;
    const double kd = std::nearbyint(beta * double(n));
    const std::size_t k = kd < 1.0 ? 1 : (kd > double(n) ? n : std::size_t(kd));
    std::vector<std::size_t> hist(kFloatBins, 0);
    for (std::size_t i = 0; i < n; ++i) ++hist[float_bin(values[i])];
    std::size_t above = 0, count = 0;
    const std::uint32_t bin = kth_bin(hist.data(), hist.size(), k, &above);
    std::vector<float> in_bin;
    for (std::size_t i = 0; i < n; ++i)
        if (float_bin(values[i]) == bin) in_bin.push_back(values[i]);
    return double(select_in_bin(&in_bin, k, above, &count));
}

Status detect_edges(const Image& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    return detect_once(im.width, im.height, [&](int x, int y) { return im.at(x, y); }, params, edges, stats);
}

Status detect_edges(const Grid<double>& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    return detect_once(im.width, im.height, [&](int x, int y) { return im(x, y); }, params, edges, stats);
}

}  // namespace erd
