#include "algorithms/imaging/bilinear.h"

#include <cmath>
#include <cstddef>

namespace erd {

namespace {

// One implementation for both sample types: sample(x, y) returns the sample as a double.
template <class Sample>
double bilinear_of(int width, int height, const Sample& sample, double x, double y) {
    if (width <= 0 || height <= 0) return 0.0;
    const double max_x = width - 1, max_y = height - 1;
    // Clamp onto Gamma; NaN falls to 0 (the comparisons fail both ways).
    x = x > 0 ? (x < max_x ? x : max_x) : 0.0;
    y = y > 0 ? (y < max_y ? y : max_y) : 0.0;
    int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    if (x0 > width - 2) x0 = width > 1 ? width - 2 : 0;
    if (y0 > height - 2) y0 = height > 1 ? height - 2 : 0;
    const int x1 = width > 1 ? x0 + 1 : x0, y1 = height > 1 ? y0 + 1 : y0;
    const double fx = x - x0, fy = y - y0;
    // Weighted form, so the result is exact at grid points (weights exactly 0 and 1) on either
    // side of a cell, including the last row and column.
    const double top = (1.0 - fx) * sample(x0, y0) + fx * sample(x1, y0);
    const double bottom = (1.0 - fx) * sample(x0, y1) + fx * sample(x1, y1);
    return (1.0 - fy) * top + fy * bottom;
}

template <class Sample>
double bilinear_doubled_of(const Sample& sample, int X, int Y) {
    const int x0 = X >> 1, y0 = Y >> 1;
    const int x1 = (X & 1) ? x0 + 1 : x0, y1 = (Y & 1) ? y0 + 1 : y0;
    if (x0 == x1 && y0 == y1) return sample(x0, y0);
    if (y0 == y1) return 0.5 * (sample(x0, y0) + sample(x1, y0));
    if (x0 == x1) return 0.5 * (sample(x0, y0) + sample(x0, y1));
    return 0.25 * (sample(x0, y0) + sample(x1, y0) + sample(x0, y1) + sample(x1, y1));
}

}  // namespace

double bilinear(const Grid<double>& im, double x, double y) {
    return bilinear_of(im.width, im.height, [&im](int u, int v) { return im(u, v); }, x, y);
}

double bilinear(const Image& im, double x, double y) {
    if (im.real()) {
        const std::size_t w = std::size_t(im.width);
        return bilinear_of(im.width, im.height, [&im, w](int u, int v) { return im.reals[std::size_t(v) * w + std::size_t(u)]; }, x, y);
    }
    return bilinear_of(im.width, im.height, [&im](int u, int v) { return double(im.at(u, v)); }, x, y);
}

double bilinear_doubled(const Grid<double>& im, int X, int Y) {
    return bilinear_doubled_of([&im](int u, int v) { return im(u, v); }, X, Y);
}

double bilinear_doubled(const Image& im, int X, int Y) {
    if (im.real()) {
        const std::size_t w = std::size_t(im.width);
        return bilinear_doubled_of([&im, w](int u, int v) { return im.reals[std::size_t(v) * w + std::size_t(u)]; }, X, Y);
    }
    return bilinear_doubled_of([&im](int u, int v) { return double(im.at(u, v)); }, X, Y);
}

Grid<double> half_pixel(const Grid<double>& im) {
    if (im.width <= 0 || im.height <= 0) return Grid<double>();
    Grid<double> out(2 * im.width - 1, 2 * im.height - 1);
    for (int Y = 0; Y < out.height; ++Y)
        for (int X = 0; X < out.width; ++X) out(X, Y) = bilinear_doubled(im, X, Y);
    return out;
}

}  // namespace erd
