#include "algorithms/filters.h"

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
static void convolve_line(const double* in, double* out, int n, std::ptrdiff_t stride, const std::vector<double>& taps,
                          Border border) {
    const int c = int(taps.size() / 2);
    const int m = int(taps.size());
    for (int i = 0; i < n; ++i) {
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

Grid<double> convolve_rows(const Grid<double>& in, const std::vector<double>& taps, Border border) {
    Grid<double> out(in.width, in.height);
    if (taps.empty()) return out;
    for (int y = 0; y < in.height; ++y)
        convolve_line(&in(0, y), &out(0, y), in.width, 1, taps, border);
    return out;
}

Grid<double> convolve_cols(const Grid<double>& in, const std::vector<double>& taps, Border border) {
    Grid<double> out(in.width, in.height);
    if (taps.empty()) return out;
    for (int x = 0; x < in.width; ++x)
        convolve_line(&in(x, 0), &out(x, 0), in.height, in.width, taps, border);
    return out;
}

Grid<double> convolve_separable(const Grid<double>& in, const std::vector<double>& hx, const std::vector<double>& hy,
                                Border border) {
    return convolve_cols(convolve_rows(in, hx, border), hy, border);
}

}  // namespace erd
