// The row scan of `erd tiles --plan` (cli/cmd_tiles.cpp): the raster's rows pass through a ring of
// three, giving the border lines' samples, the crossing bands, the range and each tile's weight.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "algorithms/methods/tiles.h"

namespace erd::cli {

// --plan's one pass over the raster, a row at a time: the border lines' samples (cols: vertical
// line i's column, rows: horizontal line j's row), the range, and each tile's weight, the sum over
// its pixels of |second difference|^(1/2) (the larger of x and y). V is the samples' type in the
// row ring: std::int32_t for an integer raster (exact differences; h^(1/2) from a table of the
// 4 maxval + 1 possible h), double for a real one. Each tile's
// sum is added pixel by pixel in x then y order, so the weights are the doubles of a plain
// per-pixel loop in doubles (plan.txt byte-identical; docs/log/tiles.md has the counts).
struct BorderScan;

// The row loops of --plan's scan, in blocks of a fixed width, which GCC's cheapest vectoriser
// (-O2) takes. Each pixel's differences are its own; the range of an integer row is exact in any
// order, a real row's goes pixel by pixel (a NaN must not change which value is the smallest).
constexpr std::size_t kBlock = 16;

// dst[0..n) = src, *lo and *hi lowered and raised to its range.
template <class V, class S>
void load_row(const S* __restrict src, V* __restrict dst, std::size_t n, V* lo, V* hi) {
    V l = *lo, u = *hi;
    std::size_t x = 0;
    if constexpr (std::is_integral_v<S>) {
        for (; x + kBlock <= n; x += kBlock) {
            V bl = l, bu = u;
            for (std::size_t t = 0; t < kBlock; ++t) {
                const V v = V(src[x + t]);
                dst[x + t] = v;
                bl = std::min(bl, v);
                bu = std::max(bu, v);
            }
            l = bl, u = bu;
        }
    }
    for (; x < n; ++x) {
        const V v = V(src[x]);
        dst[x] = v;
        l = std::min(l, v);
        u = std::max(u, v);
    }
    *lo = l, *hi = u;
}

// h[x] = the larger |second difference| at x of row b (along it, and across rows a, b, c), for
// 0 < x < n - 1.
template <class V>
V larger_second_difference(const V* a, const V* b, const V* c, std::size_t x) {
    const V hx = b[x - 1] - 2 * b[x] + b[x + 1], hy = a[x] - 2 * b[x] + c[x];
    const V ax = hx < 0 ? -hx : hx, ay = hy < 0 ? -hy : hy;
    return ax < ay ? ay : ax;
}

// One block of h[x] for x = 1 .. kBlock (the caller offsets the rows). Not inlined: inlined into
// the row loop, GCC -O2 no longer vectorises it (the restrict pointers are lost).
template <class V>
[[gnu::noinline]] void second_differences_block(const V* __restrict a, const V* __restrict b, const V* __restrict c, V* __restrict h) {
    for (int x = 1; x <= int(kBlock); ++x) h[x] = larger_second_difference(a, b, c, std::size_t(x));
}

template <class V>
void second_differences(const V* a, const V* b, const V* c, V* h, std::size_t n) {
    std::size_t x = 1;
    for (; x + kBlock + 1 <= n; x += kBlock) second_differences_block(a + x - 1, b + x - 1, c + x - 1, h + x - 1);
    for (; x + 1 < n; ++x) h[x] = larger_second_difference(a, b, c, x);
}

template <class V>
struct RowRing {
    std::vector<V> r0, r1, r2;   // rows y - 2, y - 1, y
    std::vector<V> h;            // the row's larger |second difference|
    std::vector<double> root;    // integers: root[h] = h^(1/2)
    V lo = std::numeric_limits<V>::has_infinity ? std::numeric_limits<V>::infinity() : std::numeric_limits<V>::max();
    V hi = std::numeric_limits<V>::has_infinity ? -std::numeric_limits<V>::infinity() : std::numeric_limits<V>::lowest();
    void start(std::uint32_t maxval) {
        root.resize(4 * std::size_t(maxval) + 1);
        for (std::size_t k = 0; k < root.size(); ++k) root[k] = std::sqrt(double(k));
    }
    template <class S>
    void row(const S* src, int y, BorderScan* scan);
};

struct BorderScan {
    TileGrid g;
    int T;
    std::vector<std::vector<double>> cols, rows;
    // ERD: the lines kCrossingBand samples to either side of the inner lines (crossings go on
    // across): near_cols[2 i] and [2 i + 1] beside vertical line i, near_rows likewise.
    bool band = false;
    std::vector<std::vector<double>> near_cols, near_rows;
    std::vector<double> weight;
    RowRing<std::int32_t> ints;
    RowRing<double> reals;
    BorderScan(const TileGrid& grid, int t)
        : g(grid), T(t), cols(std::size_t(g.nx + 1), std::vector<double>(std::size_t(g.height))), rows(std::size_t(g.ny + 1)),
          weight(std::size_t(g.count()), 0.0) {}
};

template <class V>
template <class S>
void RowRing<V>::row(const S* src, int y, BorderScan* scan) {
    const TileGrid& g = scan->g;
    const std::size_t W = std::size_t(g.width);
    std::swap(r0, r1);
    std::swap(r1, r2);
    r2.resize(W);
    load_row(src, r2.data(), W, &lo, &hi);
    for (int i = 0; i <= g.nx; ++i) scan->cols[std::size_t(i)][std::size_t(y)] = double(r2[std::size_t(g.column(i))]);
    for (int j = 0; j <= g.ny; ++j)
        if (g.row(j) == y) scan->rows[std::size_t(j)].assign(r2.begin(), r2.end());
    if (scan->band) {
        for (int i = 1; i < g.nx; ++i)
            for (int s = 0; s < 2; ++s) {
                const int x = std::clamp(g.column(i) + (s ? kCrossingBand : -kCrossingBand), 0, g.width - 1);
                scan->near_cols[std::size_t(2 * i + s)][std::size_t(y)] = double(r2[std::size_t(x)]);
            }
        for (int j = 1; j < g.ny; ++j)
            for (int s = 0; s < 2; ++s)
                if (std::clamp(g.row(j) + (s ? kCrossingBand : -kCrossingBand), 0, g.height - 1) == y)
                    scan->near_rows[std::size_t(2 * j + s)].assign(r2.begin(), r2.end());
    }
    if (y < 2 || W < 3) return;
    // The weight of row y - 1.
    h.resize(W);
    second_differences(r0.data(), r1.data(), r2.data(), h.data(), W);
    double* wrow = &scan->weight[std::size_t(std::min((y - 1) / scan->T, g.ny - 1)) * std::size_t(g.nx)];
    for (int i = 0; i < g.nx; ++i) {
        const std::size_t x0 = std::max<std::size_t>(1, std::size_t(i) * std::size_t(scan->T));
        const std::size_t x1 = i == g.nx - 1 ? W - 1 : std::min(W - 1, std::size_t(i + 1) * std::size_t(scan->T));
        double s = wrow[i];
        if (!root.empty()) {
            for (std::size_t x = x0; x < x1; ++x) s += root[std::size_t(h[x])];
        } else {
            for (std::size_t x = x0; x < x1; ++x) s += std::sqrt(double(h[x]));
        }
        wrow[i] = s;
    }
}

}  // namespace erd::cli
