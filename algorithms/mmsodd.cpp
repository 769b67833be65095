#include "algorithms/mmsodd.h"

#include <cmath>
#include <cstddef>

namespace erd {

double mmsodd_value(double fxx, double fyy, double fxy) {
    const double l1 = 0.5 * (fxx + fyy);
    const double half_diff = 0.5 * (fxx - fyy);
    const double l2 = std::sqrt(half_diff * half_diff + fxy * fxy);
    return std::fmax(std::fabs(l1 + l2), std::fabs(l1 - l2));
}

Grid<double> mmsodd(const Grid<double>& im, int smoothing_order, Border border) {
    std::vector<double> b = binomial_taps(smoothing_order);
    if (b.empty()) b = {1.0};
    const std::vector<double> d2 = compose_taps(derivative2_taps(), b);
    const std::vector<double> d1 = compose_taps(derivative1_taps(), b);

    // Each smoothed derivative is one separable filter on the extended image; the row passes that
    // share taps are computed once.
    const Grid<double> rows_b = convolve_rows(im, b, border);
    const Grid<double> rows_d2 = convolve_rows(im, d2, border);
    const Grid<double> rows_d1 = convolve_rows(im, d1, border);
    const Grid<double> fxx = convolve_cols(rows_d2, b, border);
    const Grid<double> fyy = convolve_cols(rows_b, d2, border);
    const Grid<double> fxy = convolve_cols(rows_d1, d1, border);

    Grid<double> out(im.width, im.height);
    for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = mmsodd_value(fxx.data[i], fyy.data[i], fxy.data[i]);
    return out;
}

}  // namespace erd
