#include "algorithms/methods/wedge_fit.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/raster.h"

namespace erd {

namespace {

// One face's share of the normal equations. With w = (w0, w1, w2) the weights of the face's
// corners at a pixel (w2 = 1 - w0 - w1) and b the pixel's sample, summed over the face's pixels:
// g = sum w w^T (symmetric: g00 g01 g02 g11 g12 g22), h = sum b w, bb = sum b^2.
struct FaceSystem {
    std::uint32_t entry[3];
    double g[6];
    double h[3];
    double bb;

    // (G v)_i for the face's values v = (a, b, c).
    void gram_times(double a, double b, double c, double out[3]) const {
        out[0] = g[0] * a + g[1] * b + g[2] * c;
        out[1] = g[1] * a + g[3] * b + g[4] * c;
        out[2] = g[2] * a + g[4] * b + g[5] * c;
    }
    // sum over the face's pixels of (approximation - b)^2 = v^T G v - 2 h.v + bb.
    double sse(double a, double b, double c) const {
        double gv[3];
        gram_times(a, b, c, gv);
        return (a * gv[0] + b * gv[1] + c * gv[2]) - 2.0 * (a * h[0] + b * h[1] + c * h[2]) + bb;
    }
};

// Assembles the face systems of every face that owns at least one pixel.
std::vector<FaceSystem> face_systems(const Cdt& cdt, const Image& image, const ErdModel& model) {
    const Lattice lattice = Lattice::pixels();
    const RasterDomain domain{cdt.max_x(), cdt.max_y()};
    std::vector<FaceSystem> faces;
    faces.reserve(cdt.face_count());
    std::vector<Span> spans;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        const EdgeInd e = 3 * f;
        const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
        if (scan_triangle(lattice, domain, p0, p1, p2, &spans) == 0) continue;
        SpanPlane l0, l1;  // the weights of corners 0 and 1 as planes
        l0.set(p0, 1.0, p1, 0.0, p2, 0.0);
        l1.set(p0, 0.0, p1, 1.0, p2, 0.0);
        // The weights are l.at(X, Y) = (z0 + gx (X - x0)) + gy (Y - y0) with z0 = 1 for l0 and 0
        // for l1, computed below with the same roundings in the same order: X - x0 is an exact
        // small integer stepped by 2, and dropping l1's "0 +" changes at most the sign of a zero
        // weight, which no sum below can see (the sums start at +0, and +0 + -0 = +0).
        const double gx0 = l0.gx, gx1 = l1.gx;
        double g00 = 0, g01 = 0, g02 = 0, g11 = 0, g12 = 0, g22 = 0, h0 = 0, h1 = 0, h2 = 0;
        std::uint64_t bb = 0;  // sum b^2 in integers: exact, and what the double sum gave while exact
        for (const Span& sp : spans) {
            const double Y = double(2 * sp.y);
            const double t0 = l0.gy * (Y - l0.y0), t1 = l1.gy * (Y - l1.y0);
            const std::uint16_t* px = &image.samples[std::size_t(sp.y) * std::size_t(image.width)];
            double a = double(2 * sp.x_begin) - l0.x0;
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i, a += 2.0) {
                const double w0 = (1.0 + gx0 * a) + t0, w1 = gx1 * a + t1;
                const double w2 = 1.0 - w0 - w1, b = double(px[i]);
                g00 += w0 * w0;
                g01 += w0 * w1;
                g02 += w0 * w2;
                g11 += w1 * w1;
                g12 += w1 * w2;
                g22 += w2 * w2;
                h0 += b * w0;
                h1 += b * w1;
                h2 += b * w2;
                bb += std::uint64_t(px[i]) * px[i];
            }
        }
        faces.push_back({{model.corner_entry(cdt, e), model.corner_entry(cdt, e + 1), model.corner_entry(cdt, e + 2)},
                         {g00, g01, g02, g11, g12, g22},
                         {h0, h1, h2},
                         double(bb)});
    }
    return faces;
}

double total_sse(const std::vector<FaceSystem>& faces, const std::vector<double>& x) {
    double sse = 0;
    for (const FaceSystem& fs : faces) sse += fs.sse(x[fs.entry[0]], x[fs.entry[1]], x[fs.entry[2]]);
    return sse > 0 ? sse : 0.0;  // an exact fit can leave a rounding residue below zero
}

}  // namespace

void fit_wedge_values(const Cdt& cdt, const Image& image, int iterations, ErdModel* model, WedgeFitStats* stats,
                      ProgressHook progress) {
    progress("wedge refit", 0.0);
    const std::vector<FaceSystem> faces = face_systems(cdt, image, *model);
    progress("wedge refit", 0.5);
    const std::size_t n = model->entry_count();

    // out = A^T A v, assembled from the face Gram matrices.
    auto normal_times = [&](const std::vector<double>& v, std::vector<double>* out) {
        std::fill(out->begin(), out->end(), 0.0);
        for (const FaceSystem& fs : faces) {
            double gv[3];
            fs.gram_times(v[fs.entry[0]], v[fs.entry[1]], v[fs.entry[2]], gv);
            for (int j = 0; j < 3; ++j) (*out)[fs.entry[j]] += gv[j];
        }
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double t = 0;
        for (std::size_t i = 0; i < a.size(); ++i) t += a[i] * b[i];
        return t;
    };

    // Jacobi preconditioning: solve for y with x = x0 + S y, S = diag(1 / |column of A|), so the
    // values of big and small faces converge at the same rate (10 steps then do what 30 did).
    std::vector<double> scale(n, 0.0);
    for (const FaceSystem& fs : faces)
        for (int j = 0; j < 3; ++j) scale[fs.entry[j]] += fs.g[j == 0 ? 0 : j == 1 ? 3 : 5];
    for (double& c : scale) c = c > 1e-12 ? 1.0 / std::sqrt(c) : 0.0;

    std::vector<double> x(n), y(n, 0.0), s(n), p(n), ps(n), q(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = model->entry_value(i);
    if (stats) stats->sse_before = total_sse(faces, x);
    // s = S A^T (b - A x0), the residual of the preconditioned normal equations at y = 0.
    normal_times(x, &q);
    std::fill(s.begin(), s.end(), 0.0);
    for (const FaceSystem& fs : faces)
        for (int j = 0; j < 3; ++j) s[fs.entry[j]] += fs.h[j];
    for (std::size_t i = 0; i < n; ++i) s[i] = scale[i] * (s[i] - q[i]);
    p = s;
    double gamma = dot(s, s);
    int it = 0;
    for (; it < iterations && gamma > 1e-12; ++it) {
        progress("wedge refit", 0.5 + 0.5 * double(it) / double(iterations));
        for (std::size_t i = 0; i < n; ++i) ps[i] = scale[i] * p[i];
        normal_times(ps, &q);
        const double pq = dot(ps, q);  // |A S p|^2
        if (pq <= 0) break;
        const double alpha = gamma / pq;
        for (std::size_t i = 0; i < n; ++i) {
            y[i] += alpha * p[i];
            s[i] -= alpha * scale[i] * q[i];
        }
        const double g2 = dot(s, s);
        const double beta = g2 / gamma;
        gamma = g2;
        for (std::size_t i = 0; i < n; ++i) p[i] = s[i] + beta * p[i];
    }
    const double hi = double(image.maxval);
    for (std::size_t i = 0; i < n; ++i) {
        const double v = x[i] + scale[i] * y[i];
        x[i] = v < 0 ? 0.0 : (v > hi ? hi : v);
        model->set_entry_value(i, x[i]);
    }
    if (stats) {
        stats->iterations = it;
        stats->sse_after = total_sse(faces, x);
    }
}

}  // namespace erd
