#include "algorithms/imaging/filters.h"

#include <algorithm>
#include <cstddef>

namespace erd {

std::vector<double> binomial_taps(int order) {
    if (order < 1 || order % 2 == 0) return {};
    // Row order-1 of Pascal's triangle in integers (exact as doubles far beyond any useful order),
    // then one division by 2^(order-1), which is exact too.
    std::vector<double> row(std::size_t(order), 0.0);
    row[0] = 1.0;
    for (int i = 1; i < order; ++i)
        for (int j = i; j > 0; --j) row[std::size_t(j)] += row[std::size_t(j - 1)];
    double scale = 1.0;
    for (int i = 1; i < order; ++i) scale *= 2.0;
    for (double& t : row) t /= scale;
    return row;
}

std::vector<double> derivative1_taps() { return {0.5, 0.0, -0.5}; }

std::vector<double> derivative2_taps() { return {1.0, -2.0, 1.0}; }

std::vector<double> compose_taps(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.empty() || b.empty()) return {};
    std::vector<double> out(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
    return out;
}

// Convolves n samples spaced `stride` apart starting at in[0] into out (same layout). For a
// convolution y[i] = sum_n h[n] x[i-n] with taps stored h[-c..c], tap k multiplies x[i + c - k].
// Only the outputs in [i0, i1) are written (the border zones; the interior has fast loops below).
static void convolve_line(const double* in, double* out, int n, std::ptrdiff_t stride, const std::vector<double>& taps,
                          Border border, int i0, int i1) {
    const int c = int(taps.size() / 2);
    const int m = int(taps.size());
    for (int i = i0; i < i1; ++i) {
        double acc = 0.0;
        for (int k = 0; k < m; ++k) {
            int j = i + c - k;
            if (j < 0 || j >= n) {
                if (border == Border::zero) continue;
                j = j < 0 ? 0 : n - 1;
            }
            acc += taps[std::size_t(k)] * in[std::ptrdiff_t(j) * stride];
        }
        out[std::ptrdiff_t(i) * stride] = acc;
    }
}

namespace {

// The interior (every tap inside the line) sums the same products in the same order as
// convolve_line, so results are bit-identical; M fixed lets the compiler keep the taps in
// registers. rows: out[i] = sum_k t[k] * in[i + c - k]; cols: the same down a column, computed a
// whole row at a time so memory is read in order.
template <int M>
void rows_interior(const double* in, double* out, int i0, int i1, int c, const double* t) {
    double tt[M];
    for (int k = 0; k < M; ++k) tt[k] = t[k];
    for (int i = i0; i < i1; ++i) {
        const double* p = in + (i + c);
        double acc = 0.0;
        for (int k = 0; k < M; ++k) acc += tt[k] * p[-k];
        out[i] = acc;
    }
}

void rows_interior_any(const double* in, double* out, int i0, int i1, int c, const double* t, int m) {
    for (int i = i0; i < i1; ++i) {
        const double* p = in + (i + c);
        double acc = 0.0;
        for (int k = 0; k < m; ++k) acc += t[k] * p[-k];
        out[i] = acc;
    }
}

// Blocks of outputs in a local array (which no source row can alias) let the compiler vectorise
// without runtime alias checks; M > 0 fixes the tap count so the taps stay in registers.
template <int M>
void weighted_rows_fixed(const double* const* src, const double* t, int m, double* out, int w) {
    constexpr int block = 64;
    const int n = M > 0 ? M : m;
    int x = 0;
    for (; x + block <= w; x += block) {
        double acc[block] = {};
        for (int k = 0; k < n; ++k) {
            const double tk = t[k];
            const double* s = src[k] + x;
            for (int j = 0; j < block; ++j) acc[j] += tk * s[j];
        }
        std::copy(acc, acc + block, out + x);
    }
    for (; x < w; ++x) {
        double acc = 0.0;
        for (int k = 0; k < n; ++k) acc += t[k] * src[k][x];
        out[x] = acc;
    }
}

}  // namespace

void weighted_rows(const double* const* rows, const double* t, int m, double* out, int w) {
    switch (m) {
        case 3: weighted_rows_fixed<3>(rows, t, m, out, w); break;
        case 4: weighted_rows_fixed<4>(rows, t, m, out, w); break;
        case 5: weighted_rows_fixed<5>(rows, t, m, out, w); break;
        case 6: weighted_rows_fixed<6>(rows, t, m, out, w); break;
        case 7: weighted_rows_fixed<7>(rows, t, m, out, w); break;
        default: weighted_rows_fixed<0>(rows, t, m, out, w); break;
    }
}

Grid<double> convolve_rows(const Grid<double>& in, const std::vector<double>& taps, Border border) {
    Grid<double> out(in.width, in.height);
    if (taps.empty()) return out;
    const int n = in.width, m = int(taps.size()), c = m / 2;
    // Output i reads inputs i + c - (m - 1) .. i + c.
    const int lo = std::min(n, std::max(0, m - 1 - c)), hi = std::max(lo, n - c);
    const double* t = taps.data();
    for (int y = 0; y < in.height; ++y) {
        const double* src = &in(0, y);
        double* dst = &out(0, y);
        convolve_line(src, dst, n, 1, taps, border, 0, lo);
        switch (m) {
            case 3: rows_interior<3>(src, dst, lo, hi, c, t); break;
            case 5: rows_interior<5>(src, dst, lo, hi, c, t); break;
            case 7: rows_interior<7>(src, dst, lo, hi, c, t); break;
            default: rows_interior_any(src, dst, lo, hi, c, t, m); break;
        }
        convolve_line(src, dst, n, 1, taps, border, hi, n);
    }
    return out;
}

Grid<double> convolve_cols(const Grid<double>& in, const std::vector<double>& taps, Border border) {
    Grid<double> out(in.width, in.height);
    if (taps.empty()) return out;
    const int n = in.height, w = in.width, m = int(taps.size()), c = m / 2;
    const int lo = std::min(n, std::max(0, m - 1 - c)), hi = std::max(lo, n - c);
    for (int x = 0; x < w; ++x) {
        convolve_line(&in(x, 0), &out(x, 0), n, w, taps, border, 0, lo);
        convolve_line(&in(x, 0), &out(x, 0), n, w, taps, border, hi, n);
    }
    const double* t = taps.data();
    std::vector<const double*> src(std::size_t(m), nullptr);
    for (int i = lo; i < hi; ++i) {
        for (int k = 0; k < m; ++k) src[std::size_t(k)] = &in(0, i + c - k);
        weighted_rows(src.data(), t, m, &out(0, i), w);
    }
    return out;
}

}  // namespace erd
