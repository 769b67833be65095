#include "algorithms/error_diffusion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <utility>

namespace erd {

namespace {

// One row of the diffusion. in[x]: error carried into this row; out[x] receives the error for the
// next row, each entry written exactly once: the three shares a pixel sends below are kept in
// two running sums (p0 for the entry behind, p1 for the entry below-ahead) instead of being
// added into memory, so the loop carries no read-modify-write through memory. Shares pushed
// past either end of the row are dropped. Returns the chosen x in order of the scan via fire().
template <int Dir, bool Masked, class Fire>
void diffuse_row(const double* sig, const std::uint8_t* forb, const double* in, double* out, int w, double rho,
                 Fire fire) {
    const double level = 2.0 * rho;
    double carry = 0.0, p0 = 0.0, p1 = 0.0;
    int x = Dir > 0 ? 0 : w - 1;
    for (int k = 0; k < w; ++k, x += Dir) {
        const double v = sig[x] + in[x] + carry;
        double e = v;
        if (v >= rho && !(Masked && forb[x])) {
            e = v - level;
            fire(x);
        }
        carry = e * (7.0 / 16.0);
        if (k > 0) out[x - Dir] = p0 + e * (3.0 / 16.0);
        p0 = p1 + e * (5.0 / 16.0);
        p1 = e * (1.0 / 16.0);
    }
    out[x - Dir] = p0;  // the last pixel's share straight below
}

}  // namespace

std::size_t diffuse(const Grid<double>& density, double rho, const DiffusionParams& params,
                    std::vector<LatticePoint>* points) {
    const int w = density.width, h = density.height;
    if (points) points->clear();
    if (w <= 0 || h <= 0 || !(rho > 0)) return 0;
    const bool mirror = params.startup == Startup::mirror;
    const int rows = mirror ? 2 * h : h;
    const std::uint8_t* forbidden = params.forbidden ? params.forbidden->data.data() : nullptr;
    std::vector<double> cur(std::size_t(w), 0.0), next(std::size_t(w), 0.0);
    if (params.startup == Startup::force) {
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) * g;
            cur[std::size_t(x)] = rho * (2.0 * (u - std::floor(u)) - 1.0);
        }
    }
    std::size_t count = 0;
    for (int r = 0; r < rows; ++r) {
        const int y = mirror ? (r < h ? h - 1 - r : r - h) : r;
        const bool counted = !mirror || r >= h;
        const double* sig = density.data.data() + std::size_t(y) * std::size_t(w);
        const std::uint8_t* forb = forbidden ? forbidden + std::size_t(y) * std::size_t(w) : nullptr;
        const std::size_t row_start = points ? points->size() : 0;
        auto fire = [&](int x) {
            if (!counted) return;
            ++count;
            if (points) points->push_back(LatticePoint{std::int32_t(2 * x), std::int32_t(2 * y)});
        };
        const bool forward = (r & 1) == 0;
        if (forward) {
            if (forb) diffuse_row<1, true>(sig, forb, cur.data(), next.data(), w, rho, fire);
            else diffuse_row<1, false>(sig, forb, cur.data(), next.data(), w, rho, fire);
        } else {
            if (forb) diffuse_row<-1, true>(sig, forb, cur.data(), next.data(), w, rho, fire);
            else diffuse_row<-1, false>(sig, forb, cur.data(), next.data(), w, rho, fire);
            if (points) std::reverse(points->begin() + std::ptrdiff_t(row_start), points->end());
        }
        std::swap(cur, next);
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

    // The count is a noisy function of rho: it falls roughly like sum / (2 rho) (much faster on
    // small images, where error leaves through the border), but below relative changes of about
    // 1/K it jumps chaotically by several points either way (bull, K = 7864: 7828 .. 7889 for rho
    // in [0.826, 0.832], neighbours 1e-4 apart differing by up to 11). Plain bisection closes onto
    // one jump across K and stalls. So: keep the bracket lo (largest rho seen with too many
    // points) / hi (smallest with too few) and interpolate in 1/rho while it is wider than the
    // jitter; inside the jitter, fit count = a + b / rho by least squares to the passes near K and
    // sample rho on a golden-ratio sequence within +-2/K (relative) of where the fit gives K.
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    const double near_band = std::max(8.0, 0.01 * k);
    const double spread = std::min(0.25, 2.0 / k);
    double rho = sum / (2.0 * k);
    double lo = 0, hi = 0;
    std::size_t c_lo = 0, c_hi = 0;
    bool have_lo = false, have_hi = false;
    double s1 = 0, su = 0, sc = 0, suu = 0, suc = 0;  // sums over near passes, u = 1 / rho
    for (int j = 1; result->passes < params.max_passes; ++j) {
        const std::size_t c = evaluate(rho);
        if (c == count) break;
        if (c > count && (!have_lo || rho > lo)) { lo = rho; c_lo = c; have_lo = true; }
        if (c < count && (!have_hi || rho < hi)) { hi = rho; c_hi = c; have_hi = true; }
        if (std::fabs(double(c) - k) <= near_band) {
            const double uu = 1.0 / rho;
            s1 += 1; su += uu; sc += double(c); suu += uu * uu; suc += uu * double(c);
        }
        const double g = double(j) * golden - std::floor(double(j) * golden);
        const bool wide = have_lo && have_hi && lo < hi && (hi - lo) > lo * 4.0 * spread;
        double next = 0;
        if (wide) {
            const double ulo = 1.0 / lo, uhi = 1.0 / hi;
            next = 1.0 / (ulo + (double(c_lo) - k) * (uhi - ulo) / (double(c_lo) - double(c_hi)));
            const double margin = (hi - lo) * 1e-3;
            if (!(next > lo + margin && next < hi - margin)) next = lo + (0.25 + 0.5 * g) * (hi - lo);
        } else if (s1 >= 1) {
            // Fit through the near passes (the slope alone through their centroid when they are
            // too few or too clustered to fix it).
            const double det = s1 * suu - su * su;
            double b = det > 1e-12 * s1 * suu ? (s1 * suc - su * sc) / det : 0;
            if (!(b > 0)) b = sc / su;  // count proportional to 1 / rho
            const double a = (sc - b * su) / s1;
            const double u_at_k = (k - a) / b;
            const double center = u_at_k > 0 ? 1.0 / u_at_k : rho;
            next = center * (1.0 + spread * (2.0 * g - 1.0));
        } else if (c > 0) {
            next = rho * double(c) / k;
        } else {
            next = have_lo ? std::sqrt(lo * rho) : rho * 0.5;
        }
        rho = next > 0 ? next : rho * 0.5;
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
