#include "algorithms/wedge_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/raster.h"

namespace erd {

namespace {

// One pixel's row of the system: its sample and the weights of its face's three corners
// (the third weight is 1 - w0 - w1).
struct Row {
    float w0, w1;
    float b;
};

struct FaceRows {
    std::uint32_t entry[3];
    std::size_t begin, end;  // rows [begin, end)
};

}  // namespace

void fit_wedge_values(const Cdt& cdt, const Image& image, int iterations, ErdModel* model, WedgeFitStats* stats) {
    const Lattice lattice = Lattice::pixels();
    const RasterDomain domain{cdt.max_x(), cdt.max_y()};
    std::vector<Row> rows;
    rows.reserve(image.pixels());
    std::vector<FaceRows> faces;
    faces.reserve(cdt.face_count());
    std::vector<Span> spans;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        const EdgeInd e = 3 * f;
        const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
        FaceRows fr{{model->corner_entry(cdt, e), model->corner_entry(cdt, e + 1), model->corner_entry(cdt, e + 2)},
                    rows.size(), rows.size()};
        SpanPlane l0, l1;
        l0.set(p0, 1.0, p1, 0.0, p2, 0.0);
        l1.set(p0, 0.0, p1, 1.0, p2, 0.0);
        scan_triangle(lattice, domain, p0, p1, p2, &spans);
        for (const Span& sp : spans) {
            // SpanPlane::at on the pixel lattice (doubled coordinates 2i, 2y), with the row's
            // y term computed once: the same operations in the same order, without the division
            // by the lattice scale.
            const double Y = double(2 * sp.y);
            const double t0 = l0.gy * (Y - l0.y0), t1 = l1.gy * (Y - l1.y0);
            const std::uint16_t* px = &image.samples[std::size_t(sp.y) * std::size_t(image.width)];
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i) {
                const double X = double(2 * i);
                rows.push_back({float(l0.z0 + l0.gx * (X - l0.x0) + t0), float(l1.z0 + l1.gx * (X - l1.x0) + t1),
                                float(px[i])});
            }
        }
        fr.end = rows.size();
        faces.push_back(fr);
    }

    // Jacobi-preconditioned CGLS: solve for y with x = S y, S = diag(1 / |column of A|), so the
    // values of big and small faces converge at the same rate (10 steps then do what 30 did).
    const std::size_t n = model->entry_count();
    std::vector<double> scale(n, 0.0);
    for (const FaceRows& fr : faces)
        for (std::size_t k = fr.begin; k < fr.end; ++k) {
            const double w0 = rows[k].w0, w1 = rows[k].w1, w2 = 1.0 - w0 - w1;
            scale[fr.entry[0]] += w0 * w0;
            scale[fr.entry[1]] += w1 * w1;
            scale[fr.entry[2]] += w2 * w2;
        }
    for (double& c : scale) c = c > 1e-12 ? 1.0 / std::sqrt(c) : 0.0;
    std::vector<double> x(n), y(n, 0.0), s(n), p(n), ps(n), r(rows.size());
    for (std::size_t i = 0; i < n; ++i) x[i] = model->entry_value(i);
    // The pixel's value under corner values a, b, c: A's row applied to them.
    auto row_value = [](const Row& row, double a, double b, double c) {
        return c + double(row.w0) * (a - c) + double(row.w1) * (b - c);
    };
    // s = S A^T r, accumulated face by face after `update` has brought r[k] up to date, so a CGLS
    // step reads the rows twice (here and for |A S p|^2) instead of four times, and A S p is
    // recomputed rather than stored (8 bytes per pixel less at the same results).
    // update(k, a, b, c) gets the face's three entries of `v`.
    auto apply_t = [&](const std::vector<double>& v, auto update) {
        std::fill(s.begin(), s.end(), 0.0);
        for (const FaceRows& fr : faces) {
            const double va = v[fr.entry[0]], vb = v[fr.entry[1]], vc = v[fr.entry[2]];
            double sa = 0, sb = 0, sc = 0;
            for (std::size_t k = fr.begin; k < fr.end; ++k) {
                update(k, va, vb, vc);
                const double w0 = rows[k].w0, w1 = rows[k].w1;
                sa += w0 * r[k];
                sb += w1 * r[k];
                sc += (1.0 - w0 - w1) * r[k];
            }
            s[fr.entry[0]] += sa;
            s[fr.entry[1]] += sb;
            s[fr.entry[2]] += sc;
        }
        for (std::size_t i = 0; i < n; ++i) s[i] *= scale[i];
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double t = 0;
        for (std::size_t i = 0; i < a.size(); ++i) t += a[i] * b[i];
        return t;
    };

    // Residual of the starting values; the unknown is the correction x - x0 = S y.
    apply_t(x, [&](std::size_t k, double a, double b, double c) { r[k] = double(rows[k].b) - row_value(rows[k], a, b, c); });
    if (stats) stats->sse_before = dot(r, r);
    p = s;
    double gamma = dot(s, s);
    int it = 0;
    for (; it < iterations && gamma > 1e-12; ++it) {
        for (std::size_t i = 0; i < n; ++i) ps[i] = scale[i] * p[i];
        // q = A (S p) without the constant part: row_value of a correction is linear.
        double qq = 0;
        for (const FaceRows& fr : faces) {
            const double a = ps[fr.entry[0]], b = ps[fr.entry[1]], c = ps[fr.entry[2]];
            for (std::size_t k = fr.begin; k < fr.end; ++k) {
                const double q = row_value(rows[k], a, b, c);
                qq += q * q;
            }
        }
        if (qq <= 0) break;
        const double alpha = gamma / qq;
        for (std::size_t i = 0; i < n; ++i) y[i] += alpha * p[i];
        apply_t(ps, [&](std::size_t k, double a, double b, double c) { r[k] -= alpha * row_value(rows[k], a, b, c); });
        const double g2 = dot(s, s);
        const double beta = g2 / gamma;
        gamma = g2;
        for (std::size_t i = 0; i < n; ++i) p[i] = s[i] + beta * p[i];
    }
    for (std::size_t i = 0; i < n; ++i) x[i] += scale[i] * y[i];
    const double hi = double(image.maxval);
    for (std::size_t i = 0; i < n; ++i) model->set_entry_value(i, x[i] < 0 ? 0.0 : (x[i] > hi ? hi : x[i]));
    if (stats) {
        stats->iterations = it;
        double sse = 0;
        for (const FaceRows& fr : faces)
            for (std::size_t k = fr.begin; k < fr.end; ++k) {
                const double z = row_value(rows[k], model->entry_value(fr.entry[0]), model->entry_value(fr.entry[1]),
                                           model->entry_value(fr.entry[2])) - double(rows[k].b);
                sse += z * z;
            }
        stats->sse_after = sse;
    }
}

}  // namespace erd
