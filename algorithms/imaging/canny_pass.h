// The gradient pass of edge detection (canny.h): steps 1 and 3 streamed over the rows of the
// half-pixel grid once per image, kept by EdgeDetector while later detections can use it
// (canny_pass.cpp), and the detection of steps 2 and 4 to 6 read from it (canny_track.cpp).
// Private to canny*.cpp.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/gradient_rows.h"
#include "algorithms/imaging/image.h"
#include "algorithms/imaging/point_rings.h"
#include "algorithms/imaging/raw_array.h"
#include "kernel/row_parallel.h"

namespace erd {
namespace canny_detail {

// Points of the half-pixel grid in a plane with a one-point frame: index (Y + 1) * stride + X + 1.
struct Plane {
    int w = 0, h = 0, stride = 0;
    Plane() = default;
    Plane(int width, int height) : w(width), h(height), stride(round8(width + 2) + 8) {}
    std::size_t cells() const { return std::size_t(stride) * std::size_t(h + 2); }
    std::ptrdiff_t at(int X, int Y) const { return std::ptrdiff_t(Y + 1) * stride + X + 1; }
};

// The image a pass runs on, as sample(x, y): a gray image, a grid of values, or (ColourSample) a
// colour image whose channels' gradients step 1 combines.
struct GraySample {
    const Image* im;
    std::uint16_t operator()(int x, int y) const { return im->at(x, y); }
};
struct GridSample {
    const Grid<double>* im;
    double operator()(int x, int y) const { return (*im)(x, y); }
};
struct ColourSample {
    const Image* im;
    ColourGradient how;
};

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

}  // namespace canny_detail

// Steps 1 and 3 for one image: for the points above a lower bound of tau_low, their magnitude and
// their non-maxima flags, and the histogram of the large magnitudes. Flags depend on the gradient
// alone, not on the thresholds, so steps 2 to 6 read the pass without changing it and it serves
// several detections.
struct EdgeDetector::Pass {
    canny_detail::Plane pl;  // index space of the points (never allocated)
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
    // Sample: GraySample, GridSample or ColourSample (canny_pass.cpp instantiates those).
    template <class Sample>
    void run(int width, int height, Sample sample, const CannyParams& params, std::size_t k_high);

    // After the pass only the bins from floor_bin up are read (kth_bin stops at the k-th
    // largest's, which is at or above it; narrow() only raises it), and none above the largest
    // value: the counts keep those (256 KB -> a few hundred bins on a photo).
    void trim_hist();
    std::size_t count(std::uint32_t bin) const { return hist[bin - hist_base]; }

    // The test that keeps stored point k when its g is at least `bound` (remove_bits_unless),
    // moving the g and flags of the points kept down to *n, n + 1, ... in order.
    auto at_least(float bound, std::size_t* n);

    // Drops the stored points with g below `bound`, keeping the order of the others.
    void drop_below(float bound);

    // Keeps only what the detections `widest` covers can use (a beta at most its, its r), as if
    // the pass had been made for it: the bins below its k-th largest's go from the counts, the
    // points below r times that bin's floor from the store.
    void narrow(const CannyParams& widest);

    // One streaming pass from the bound `guess` (0: none); false when the final bound is below
    // the guess (the result is then incomplete). On success `low` is the final bound. With
    // params.threads > 1 and enough rows, the rows are cut into bands (stream_bands).
    template <class Sample>
    bool stream(int width, Sample sample, const CannyParams& params, std::size_t k_high, float guess,
                std::size_t expected);

    // The streaming pass over rows y0 .. y1 - 1 of the plane alone (their gradient needs rows
    // y0 - 1 and y1 too), its bit plane holding the words from word0 on.
    template <class Sample>
    bool stream_rows(int width, Sample sample, const CannyParams& params, std::size_t k_high, float guess, int y0,
                     int y1, std::size_t word0);

    // The pass in row bands, one thread each, each band a pass of its own over its rows with its
    // own rising bound: a band's k-th largest is at most the whole plane's, so its bound is a
    // lower bound of the final one too, and it counted every bin at or above its own final bin
    // exactly. The final bin is found from the sum of the bands' counts from the highest of their
    // bins up (all exact there), each band drops what is below the final bound, and the bands'
    // points are joined in row order: the points, flags and counts the one-band pass keeps.
    template <class Sample>
    bool stream_bands(const RowParts& parts, int width, Sample sample, const CannyParams& params, std::size_t k_high,
                      float guess, std::size_t expected);

    // A guess of the streaming pass's final bound: r times the magnitude of the same rank among
    // the sampled rows as tau_high has among all, less a margin (kGuessMargin). A sampled run
    // costs about twice as much a row as the stream (its smoothed neighbours are made for it
    // alone): 1.6% of the rows at twice the cost, ~3% of the pass. 0 (no guess) when the sample is too
    // small to rank. *expected: the sample's count at or above the guess, scaled to the grid.
    template <class Sample>
    float sampled_bound(int width, Sample sample, const CannyParams& params, std::size_t k_high,
                        std::size_t* expected, std::size_t* at_estimate = nullptr) const;

    // Room for `more` points: first drop the points the bound has risen past (they can never be
    // strong), then grow if still more than half full.
    void make_room(std::size_t more);

    // The store made up front for the `expected` points the guess keeps (a quarter more): it
    // then rarely fills, and a full one is compacted and copied (growing it from empty was a
    // real share of the pass).
    void make_store(std::size_t expected);

    // Steps 2 and 4 to 6. Returns false, having written nothing, when the pass does not cover the
    // parameters: a different filter, too few values counted for this beta, or a tau_low below
    // the bound. release = the pass is not used again: its arrays go as soon as they are read.
    bool track(const CannyParams& params, bool release, SortedPoints* edges, CannyStats* stats);

    void clear();

    // k = round(beta * M), at least 1 (step 2).
    static std::size_t k_of(double beta, std::size_t M) {
        const double kd = std::nearbyint(beta * double(M));
        return kd < 1.0 ? 1 : (kd > double(M) ? M : std::size_t(kd));
    }
};

}  // namespace erd
