#include "algorithms/error_diffusion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <utility>

namespace erd {

std::size_t diffuse(const Grid<double>& density, double rho, const DiffusionParams& params,
                    std::vector<LatticePoint>* points) {
    const int w = density.width, h = density.height;
    if (points) points->clear();
    if (w <= 0 || h <= 0 || !(rho > 0)) return 0;
    const bool mirror = params.startup == Startup::mirror;
    const int rows = mirror ? 2 * h : h;
    const std::uint8_t* forbidden = params.forbidden ? params.forbidden->data.data() : nullptr;
    // Carried error of the current and the next row, with one spare slot at each end that
    // swallows the error pushed out of the image.
    std::vector<double> cur(std::size_t(w) + 2, 0.0), next(std::size_t(w) + 2, 0.0);
    if (params.startup == Startup::force) {
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) * g;
            cur[std::size_t(x) + 1] = rho * (2.0 * (u - std::floor(u)) - 1.0);
        }
    }
    const double out_level = 2.0 * rho;
    std::size_t count = 0;
    for (int r = 0; r < rows; ++r) {
        const int y = mirror ? (r < h ? h - 1 - r : r - h) : r;
        const bool counted = !mirror || r >= h;
        const double* sig = density.data.data() + std::size_t(y) * std::size_t(w);
        const std::uint8_t* forb = forbidden ? forbidden + std::size_t(y) * std::size_t(w) : nullptr;
        double* c = cur.data() + 1;
        double* n = next.data() + 1;
        const std::size_t row_start = points ? points->size() : 0;
        const bool forward = (r & 1) == 0;
        const int dir = forward ? 1 : -1;
        for (int k = 0; k < w; ++k) {
            const int x = forward ? k : w - 1 - k;
            const double v = sig[x] + c[x];
            double e = v;
            if (v >= rho && !(forb && forb[x])) {
                e = v - out_level;
                if (counted) {
                    ++count;
                    if (points) points->push_back(LatticePoint{std::int32_t(2 * x), std::int32_t(2 * y)});
                }
            }
            c[x + dir] += e * (7.0 / 16.0);
            n[x - dir] += e * (3.0 / 16.0);
            n[x] += e * (5.0 / 16.0);
            n[x + dir] += e * (1.0 / 16.0);
        }
        if (points && !forward) std::reverse(points->begin() + std::ptrdiff_t(row_start), points->end());
        std::swap(cur, next);
        std::fill(next.begin(), next.end(), 0.0);
    }
    return count;
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
    std::vector<LatticePoint> pts;
    std::size_t best_count = 0;
    bool have_best = false;
    auto evaluate = [&](double rho) {
        const std::size_t c = diffuse(density, rho, params, &pts);
        ++result->passes;
        const auto gap = [&](std::size_t a) { return a > count ? a - count : count - a; };
        if (!have_best || gap(c) < gap(best_count) || (gap(c) == gap(best_count) && c < best_count)) {
            have_best = true;
            best_count = c;
            result->rho = rho;
            std::swap(result->points, pts);
        }
        return c;
    };

    // The count is a noisy function of rho: it follows sum / (2 rho) closely, but below relative
    // changes of about 1/K it jumps chaotically by several points either way (lena, K = 2621,
    // mirror: 2607 .. 2638 for rho in [2.80, 2.83], neighbouring values 1e-4 apart differing by
    // up to 8). Bisection therefore closes onto one jump that straddles K and stalls. Instead:
    // step with the model until the count is near K, then sample rho around the model's estimate
    // A / K (A = mean of count * rho over the near passes) on a golden-ratio sequence of relative
    // offsets within +-3/K, where the trend stays within a few points of K and the jitter hits K
    // often (a few passes on the thesis images).
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    const double band = std::max(4.0, 0.002 * k);  // "near": within the jitter of the count
    const double spread = std::min(0.25, 3.0 / k);
    double rho = sum / (2.0 * k);
    double a_sum = 0;
    int near = 0;
    while (result->passes < params.max_passes) {
        const std::size_t c = evaluate(rho);
        if (c == count) break;
        if (c == 0) { rho *= 0.5; continue; }
        const double a = double(c) * rho;
        if (std::fabs(double(c) - k) > band) {
            rho = a / k;  // far: trust the model outright
            continue;
        }
        a_sum += a;
        ++near;
        const double u = double(near) * golden;
        rho = a_sum / double(near) / k * (1.0 + spread * (2.0 * (u - std::floor(u)) - 1.0));
    }
    result->exact = best_count == count;
    return Status::success();
}

Grid<double> ed_density(const Grid<double>& d, double gamma) {
    Grid<double> out(d.width, d.height, 0.0);
    double dmax = 0;
    for (double v : d.data) dmax = std::max(dmax, v);
    if (!(dmax > 0)) return out;
    for (std::size_t i = 0; i < d.data.size(); ++i) {
        const double t = std::max(0.0, d.data[i]) / dmax;
        out.data[i] = gamma == 1.0 ? t : (gamma == 0.5 ? std::sqrt(t) : std::pow(t, gamma));
    }
    return out;
}

Grid<std::uint8_t> edge_pixels(const Grid<std::uint8_t>& half_pixel_edges) {
    const int w = (half_pixel_edges.width + 1) / 2, h = (half_pixel_edges.height + 1) / 2;
    Grid<std::uint8_t> out(w, h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out(x, y) = half_pixel_edges(2 * x, 2 * y) ? 1 : 0;
    return out;
}

}  // namespace erd
