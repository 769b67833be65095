#include "algorithms/imaging/error_diffusion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>

#include "kernel/row_parallel.h"

namespace erd {

namespace {

// Four lanes of the diffusion as one value. Written as plain loops over four floats, which the
// compiler turns into single SSE instructions at the x86-64 baseline. Passed by value and kept
// in locals, the carried error of every lane stays in a register across a row (as 16-float
// arrays, the previous form, it went through the stack at every pixel).
struct alignas(16) Quad {
    float v[4];
};

inline Quad splat(float s) { return Quad{{s, s, s, s}}; }
inline Quad load(const float* p) {
    Quad r;
    std::memcpy(r.v, p, sizeof r.v);
    return r;
}
inline void store(float* p, Quad a) { std::memcpy(p, a.v, sizeof a.v); }
inline Quad operator+(Quad a, Quad b) {
    Quad r;
    for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] + b.v[i];
    return r;
}
inline Quad operator-(Quad a, Quad b) {
    Quad r;
    for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] - b.v[i];
    return r;
}
inline Quad operator*(Quad a, float b) {
    Quad r;
    for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] * b;
    return r;
}
inline Quad max(Quad a, Quad b) {
    Quad r;
    for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] < b.v[i] ? b.v[i] : a.v[i];
    return r;
}
// What a lane emits: level where v reaches rho, else 0 (a mask, no branch).
inline Quad emitted(Quad v, Quad rho, Quad level) {
    Quad r;
    for (int i = 0; i < 4; ++i) {
        const float l = level.v[i];  // read unconditionally: the select then needs no branch
        r.v[i] = v.v[i] >= rho.v[i] ? l : 0.0f;
    }
    return r;
}

// Lanes: one sweep over the image runs up to kLanes passes with different thresholds side by
// side, in kGroups quads. A single pass is bound by the latency of its carried error (add,
// compare, subtract, multiply per pixel, each waiting for the previous pixel); independent lanes
// fill that wait. Four quads fit the 16 SSE registers: the carried error of each, the four share
// weights, the pixel's density and temporaries; rho and the emitted level come from memory
// operands. float: the error stays within a few rho of 0 and the density within [0, 1] (ED) or
// a few units, so 24 bits are ample, and a vector holds twice as many as double.
constexpr int kGroups = 4;
constexpr int kLanes = 4 * kGroups;
constexpr int kFirstGroups = 1;  // quads of the count search's first sweep (see select_points)

// State and results of the lanes of one sweep (G quads).
template <int G>
struct Sweep {
    static constexpr int lanes = 4 * G;
    float rho[lanes], level[lanes];
    std::size_t count[lanes] = {};
    std::vector<LatticePoint>* points[lanes] = {};  // null: not recorded
};

// Where a pixel sits in its row, for the shares that would leave the image: an inner pixel
// passes 7/16 ahead, 3/16 behind-below, 5/16 below and 1/16 below-ahead; at an end of the row the
// shares that would fall outside are given to the neighbours inside in proportion to their
// weights, so no error is lost (first: 7/13 ahead, 5/13 below, 1/13 below-ahead; last: 3/8
// behind-below, 5/8 below; a one-pixel row: all below). docs/DECISIONS.md "ERD reproduction".
enum class RowPos { inner, first, last, single };

// One pixel of diffuse_row for all lanes (see there). The first pixel's ahead shares go out
// through e_prev, so it is stored scaled by 16/13 (the next pixel takes 7/16 and 1/16 of it).
template <int G, int Dir, bool Masked, RowPos P>
inline void diffuse_pixel(const double* sig, const std::uint8_t* forb, float* buf, int x, int y, bool counted,
                          Quad* e_prev, const Quad* rho, const Quad* level, Sweep<G>* sw) {
    constexpr int L = 4 * G;
    constexpr float behind_w = P == RowPos::inner ? 3.0f / 16.0f : P == RowPos::last ? 3.0f / 8.0f : 0.0f;
    constexpr float below_w = P == RowPos::inner ? 5.0f / 16.0f
                              : P == RowPos::first ? 5.0f / 13.0f
                              : P == RowPos::last  ? 5.0f / 8.0f
                                                   : 1.0f;
    constexpr float carry = P == RowPos::first ? 16.0f / 13.0f : 1.0f;
    float* cell = buf + std::ptrdiff_t(x) * L;
    float* behind = cell - Dir * L;
    const Quad s = splat(float(sig[x]));
    // A forbidden pixel emits nothing in any lane (level * 0 = +0, so e = v exactly).
    const float allowed = Masked && forb[x] ? 0.0f : 1.0f;
    Quad out[G], any = splat(0.0f);
#pragma GCC unroll 4
    for (int g = 0; g < G; ++g) {  // unrolled, so that e_prev stays in registers
        const Quad v = (s + load(cell + 4 * g)) + e_prev[g] * (7.0f / 16.0f);
        out[g] = emitted(v, rho[g], level[g]);
        if (Masked) out[g] = out[g] * allowed;
        any = max(any, out[g]);
        const Quad e = v - out[g];
        if (P == RowPos::inner || P == RowPos::last) store(behind + 4 * g, load(behind + 4 * g) + e * behind_w);
        store(cell + 4 * g, e_prev[g] * (1.0f / 16.0f) + e * below_w);
        e_prev[g] = P == RowPos::first ? e * carry : e;
    }
    // Rare (about one pixel in four fires in some lane of 16): the emitted levels are 0 or
    // positive, so a sum tells whether any lane (or any lane of a quad) fired.
    if (counted && (any.v[0] + any.v[1]) + (any.v[2] + any.v[3]) > 0.0f)
        for (int g = 0; g < G; ++g) {
            if (!((out[g].v[0] + out[g].v[1]) + (out[g].v[2] + out[g].v[3]) > 0.0f)) continue;
            for (int i = 0; i < 4; ++i) {
                if (!(out[g].v[i] > 0.0f)) continue;
                const int l = 4 * g + i;
                ++sw->count[l];
                if (sw->points[l]) sw->points[l]->push_back(LatticePoint{std::int32_t(2 * x), std::int32_t(2 * y)});
            }
        }
}

// One row of the diffusion for all lanes, in place. buf holds a cell of 4G floats per pixel
// (plus spare cells at -1 and w): cell x holds the error carried into this row until pixel x
// reads it; then it is free and receives that pixel's running sum for the next row, e_prev/16 +
// 5e/16 (shares below-ahead of the previous pixel and straight below), which the next pixel
// completes with its 3/16 behind-below and leaves final. So every cell is written once for the
// next row, in the same order of additions as three separate shares would need, and the only
// state carried from pixel to pixel in registers is e_prev (the rest waits in memory, off the
// chain of dependent operations). The end pixels keep every share inside the row (RowPos).
// Chosen pixels (when `counted`) are counted and recorded in scan order.
// Not inlined: inside select_points the register allocator spilled the share weights (an
// attribute other compilers ignore).
template <int G, int Dir, bool Masked>
[[gnu::noinline]] void diffuse_row(const double* sig, const std::uint8_t* forb, float* buf, int w, int y, bool counted,
                                   Sweep<G>* sw) {
    // e_prev: the previous pixel's error, whose 7/16 is carried ahead and 1/16 goes below-ahead.
    Quad e_prev[G] = {}, rho[G], level[G];
    for (int g = 0; g < G; ++g) {
        rho[g] = load(sw->rho + 4 * g);
        level[g] = load(sw->level + 4 * g);
    }
    const int x0 = Dir > 0 ? 0 : w - 1;
    if (w == 1) {
        diffuse_pixel<G, Dir, Masked, RowPos::single>(sig, forb, buf, x0, y, counted, e_prev, rho, level, sw);
        return;
    }
    diffuse_pixel<G, Dir, Masked, RowPos::first>(sig, forb, buf, x0, y, counted, e_prev, rho, level, sw);
    int x = x0 + Dir;
    for (int k = 1; k < w - 1; ++k, x += Dir)
        diffuse_pixel<G, Dir, Masked, RowPos::inner>(sig, forb, buf, x, y, counted, e_prev, rho, level, sw);
    diffuse_pixel<G, Dir, Masked, RowPos::last>(sig, forb, buf, x, y, counted, e_prev, rho, level, sw);
}

// Runs the 4G passes of sw (rho > 0 each) over the density.
template <int G>
void run_sweep(const Grid<double>& density, const DiffusionParams& params, Sweep<G>* sw) {
    constexpr int L = 4 * G;
    const int w = density.width, h = density.height;
    const bool mirror = params.startup == Startup::mirror;
    const int rows = mirror ? 2 * h : h;
    const std::uint8_t* forbidden = params.forbidden ? params.forbidden->data.data() : nullptr;
    std::vector<float> cells(std::size_t(w + 2) * L, 0.0f);
    float* buf = cells.data() + L;  // cell -1 and cell w are spare
    for (int l = 0; l < L; ++l) {
        sw->level[l] = 2.0f * sw->rho[l];
        sw->count[l] = 0;
        if (sw->points[l]) sw->points[l]->clear();
    }
    if (params.startup == Startup::force) {
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) * g;
            for (int l = 0; l < L; ++l)
                buf[std::size_t(x) * L + std::size_t(l)] = float(sw->rho[l] * (2.0 * (u - std::floor(u)) - 1.0));
        }
    }
    for (int r = 0; r < rows; ++r) {
        const int y = mirror ? (r < h ? h - 1 - r : r - h) : r;
        const bool counted = !mirror || r >= h;
        const double* sig = density.data.data() + std::size_t(y) * std::size_t(w);
        // Rows without a forbidden pixel (all but two in ED) take the loop without the mask.
        const std::uint8_t* forb = forbidden ? forbidden + std::size_t(y) * std::size_t(w) : nullptr;
        if (forb && std::all_of(forb, forb + w, [](std::uint8_t b) { return b == 0; })) forb = nullptr;
        std::size_t row_start[L];
        for (int l = 0; l < L; ++l) row_start[l] = sw->points[l] ? sw->points[l]->size() : 0;
        if ((r & 1) == 0) {
            if (forb) diffuse_row<G, 1, true>(sig, forb, buf, w, y, counted, sw);
            else diffuse_row<G, 1, false>(sig, forb, buf, w, y, counted, sw);
        } else {
            if (forb) diffuse_row<G, -1, true>(sig, forb, buf, w, y, counted, sw);
            else diffuse_row<G, -1, false>(sig, forb, buf, w, y, counted, sw);
            for (int l = 0; l < L; ++l)  // right-to-left rows: restore row-major order
                if (sw->points[l])
                    std::reverse(sw->points[l]->begin() + std::ptrdiff_t(row_start[l]), sw->points[l]->end());
        }
    }
}

// The count search's sweep of kLanes lanes, on two threads when asked (threads >= 2): each runs
// half of the lanes over the image. Every operation of a lane is its own (the quads are
// element-wise; `any` only skips work), so each lane's count and points are the same bits as in
// one sweep of all of them; a thread's half fills the latency of the carried error with two
// quads instead of four.
void run_search_sweep(const Grid<double>& density, const DiffusionParams& params, Sweep<kGroups>* sw) {
    constexpr int half = kLanes / 2;
    if (resolve_threads(params.threads) < 2 || std::size_t(density.width) * std::size_t(density.height) < (std::size_t(1) << 16)) {
        run_sweep(density, params, sw);
        return;
    }
    Sweep<kGroups / 2> parts[2];
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < half; ++l) {
            parts[k].rho[l] = sw->rho[k * half + l];
            parts[k].points[l] = sw->points[k * half + l];
        }
    run_parts(RowParts(0, 2, 2), [&](std::size_t k, std::size_t, std::size_t) { run_sweep(density, params, &parts[k]); });
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < half; ++l) {
            sw->level[k * half + l] = parts[k].level[l];
            sw->count[k * half + l] = parts[k].count[l];
        }
}

}  // namespace

std::size_t diffuse(const Grid<double>& density, double rho, const DiffusionParams& params,
                    std::vector<LatticePoint>* points) {
    if (points) points->clear();
    if (density.width <= 0 || density.height <= 0 || !(rho > 0)) return 0;
    Sweep<1> sw;  // one quad with the same threshold in every lane; lane 0 is the pass
    std::fill(sw.rho, sw.rho + 4, float(rho));
    sw.points[0] = points;
    run_sweep(density, params, &sw);
    return sw.count[0];
}

Status select_points(const Grid<double>& density, std::size_t count, const DiffusionParams& params,
                     DiffusionResult* result) {
    *result = DiffusionResult();
    if (density.width <= 0 || density.height <= 0 || density.size() != std::size_t(density.width) * std::size_t(density.height))
        return Status::bad_input("error diffusion: empty density");
    if (params.forbidden && (params.forbidden->width != density.width || params.forbidden->height != density.height))
        return Status::bad_input("error diffusion: mask size differs from the density's");
    double sum = 0;
    for (double v : density.data) {
        if (!(v >= 0) || !std::isfinite(v)) return Status::bad_input("error diffusion: density must be finite and >= 0");
        sum += v;
    }
    if (count == 0) { result->exact = true; return Status::success(); }
    if (!(sum > 0)) return Status::success();  // nothing can be chosen: empty, not exact

    const double k = double(count);
    const auto gap = [&](std::size_t a) { return a > count ? a - count : count - a; };
    std::vector<LatticePoint> lane_points[kLanes];
    Sweep<kGroups> sw;
    Sweep<kFirstGroups> first_sw;
    for (int l = 0; l < kLanes; ++l) sw.points[l] = &lane_points[l];
    for (int l = 0; l < 4 * kFirstGroups; ++l) first_sw.points[l] = &lane_points[l];
    std::size_t best_count = 0;
    bool have_best = false;

    // The count is a noisy function of rho: it falls roughly like sum / (2 rho) (less near the
    // border and at low densities: bull 0.125% needs 0.79 times that rho, lena 1% 0.99), but
    // below relative changes of about 1/K it jumps chaotically by several points either way
    // (bull, K = 7864: rho 1e-4 apart (relative) differ by up to 11 points, about 6 typically).
    // So a threshold that gives K exactly is found by sampling near the crossing. The first
    // sweep only locates it (with 16 lanes it hit K in 1 of 90 test cases), so it runs one quad
    // (a quarter of the instructions), at 0.75, 0.88, 0.95 and 0.99 times the model's rho (the
    // found / model ratio was 0.66 .. 0.999 over those cases, most above 0.92). Then each sweep tries
    // kLanes thresholds: it fits count = a + b / rho by least squares to the passes near K and
    // samples rho on a deterministic golden-ratio sequence within +-3/K (relative) of where the
    // fit gives K; with no pass near K yet, the crossing is interpolated (linear in 1 / rho)
    // between the bracket lo (largest rho seen with too many points) / hi (smallest with too
    // few), sampled twice as widely.
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    const double near_band = std::max(8.0, 0.01 * k);
    const double spread = std::min(0.25, 3.0 / k);
    const double rho0 = sum / (2.0 * k);
    double lo = 0, hi = 0;
    bool have_lo = false, have_hi = false;
    std::size_t c_lo = 0, c_hi = 0;
    double s1 = 0, su = 0, sc = 0, suu = 0, suc = 0;  // sums over near passes, u = 1 / rho
    double trials[kLanes];
    static const double first[4 * kFirstGroups] = {0.75, 0.88, 0.95, 0.99};
    for (int l = 0; l < 4 * kFirstGroups; ++l) trials[l] = rho0 * first[l];
    long j = 0;  // position in the golden-ratio sequence
    int lanes = 4 * kFirstGroups;
    while (result->passes + lanes <= std::max(params.max_passes, kLanes)) {
        std::size_t counts[kLanes];
        float rhos[kLanes];
        if (lanes == kLanes) {
            for (int l = 0; l < kLanes; ++l) sw.rho[l] = float(trials[l]);
            run_search_sweep(density, params, &sw);
            std::copy(sw.count, sw.count + kLanes, counts);
            std::copy(sw.rho, sw.rho + kLanes, rhos);
        } else {
            for (int l = 0; l < lanes; ++l) first_sw.rho[l] = float(trials[l]);
            run_sweep(density, params, &first_sw);
            std::copy(first_sw.count, first_sw.count + lanes, counts);
            std::copy(first_sw.rho, first_sw.rho + lanes, rhos);
        }
        result->passes += lanes;
        ++result->sweeps;
        bool exact = false;
        for (int l = 0; l < lanes; ++l) {
            const std::size_t c = counts[l];
            const double rho = double(rhos[l]);
            if (!have_best || gap(c) < gap(best_count) || (gap(c) == gap(best_count) && c < best_count)) {
                have_best = true;
                best_count = c;
                result->rho = rho;
                std::swap(result->points, lane_points[l]);
            }
            exact = exact || c == count;
            if (c > count && (!have_lo || rho > lo)) { lo = rho; c_lo = c; have_lo = true; }
            if (c < count && (!have_hi || rho < hi)) { hi = rho; c_hi = c; have_hi = true; }
            // A pass with no point says nothing about the slope of the model (tiny K only).
            if (c > 0 && std::fabs(double(c) - k) <= near_band) {
                const double uu = 1.0 / rho;
                s1 += 1; su += uu; sc += double(c); suu += uu * uu; suc += uu * double(c);
            }
        }
        if (exact) break;
        lanes = kLanes;
        double center = 0, width = spread;
        if (s1 >= 1) {
            // Fit through the near passes (the slope alone through their centroid when they are
            // too few or too clustered to fix it).
            const double det = s1 * suu - su * su;
            double b = det > 1e-12 * s1 * suu ? (s1 * suc - su * sc) / det : 0;
            if (!(b > 0)) b = sc / su;  // count proportional to 1 / rho
            const double a = (sc - b * su) / s1;
            const double u_at_k = (k - a) / b;
            center = u_at_k > 0 ? 1.0 / u_at_k : 0;
            // A fit that puts the crossing outside the bracket is off (few, clustered passes at
            // tiny K): the bracket's interpolation below is safer.
            if (have_lo && have_hi && lo < hi && !(center > lo && center < hi)) center = 0;
        }
        if (center == 0 && have_lo && have_hi && lo < hi) {
            // Linear in u = 1 / rho between the bracket's ends, where the count nearly is.
            const double ulo = 1.0 / lo, uhi = 1.0 / hi;
            const double t = (double(c_lo) - k) / (double(c_lo) - double(c_hi));
            center = 1.0 / (ulo + (uhi - ulo) * t);
            width = std::min(0.25, 2.0 * spread);
        }
        if (center > 0) {
            // Sampled within the bracket where it is narrower than the window: near the exact
            // count the bands of rho that give it can be far narrower than the window (bull-like
            // densities are smooth, a random one at K = 4 gives a band 0.16% wide).
            double w_lo = center * (1.0 - width), w_hi = center * (1.0 + width);
            if (have_lo && have_hi && lo < hi) {
                w_lo = std::max(w_lo, lo);
                w_hi = std::min(w_hi, hi);
                if (!(w_lo < w_hi)) { w_lo = lo; w_hi = hi; }
            }
            for (int l = 0; l < kLanes; ++l, ++j) {
                const double g = double(j) * golden - std::floor(double(j) * golden);
                trials[l] = w_lo + (w_hi - w_lo) * g;
            }
            continue;
        }
        // Nothing near K yet and no usable bracket: step with the model from the nearest side.
        const double base = have_lo && (!have_hi || c_lo - count < count - c_hi) ? lo * double(c_lo) / k
                            : have_hi && c_hi > 0                               ? hi * double(c_hi) / k
                                                                                : (have_hi ? hi : rho0) * 0.25;
        for (int l = 0; l < kLanes; ++l) trials[l] = base * std::exp((double(l) / (kLanes - 1) - 0.5) * 0.2);
    }
    result->exact = best_count == count;
    return Status::success();
}

Grid<double> ed_density(Grid<double> d, double gamma, int threads) {
    // Bands of rows side by side (kernel/row_parallel.h), 2^18 pixels at least: the maximum of the
    // bands' maxima is the maximum, and each value is mapped alone, so every thread count gives
    // the same bits.
    const std::size_t w = std::size_t(std::max(0, d.width));
    const RowParts parts(0, std::size_t(std::max(0, d.height)), threads, rows_for(std::size_t(1) << 18, w));
    std::vector<double> band_max(parts.count, 0.0);
    run_parts(parts, [&](std::size_t k, std::size_t y0, std::size_t y1) {
        double m = 0;
        for (std::size_t i = y0 * w; i < y1 * w; ++i) m = std::max(m, d.data[i]);
        band_max[k] = m;
    });
    double dmax = 0;
    for (double m : band_max) dmax = std::max(dmax, m);
    if (!(dmax > 0)) {
        std::fill(d.data.begin(), d.data.end(), 0.0);
        return d;
    }
    run_parts(parts, [&](std::size_t, std::size_t y0, std::size_t y1) {
        double* const first = d.data.data() + y0 * w;
        double* const last = d.data.data() + y1 * w;
        // One loop per exponent (not the choice inside the loop, at every pixel).
        if (gamma == 1.0)
            for (double* v = first; v != last; ++v) *v = std::max(0.0, *v) / dmax;
        else if (gamma == 0.5)
            for (double* v = first; v != last; ++v) *v = std::sqrt(std::max(0.0, *v) / dmax);
        else
            for (double* v = first; v != last; ++v) *v = std::pow(std::max(0.0, *v) / dmax, gamma);
    });
    return d;
}

}  // namespace erd
