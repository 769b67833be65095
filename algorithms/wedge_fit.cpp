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
        for (const Span& s : spans)
            for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                rows.push_back({float(l0.at(lattice, i, s.y)), float(l1.at(lattice, i, s.y)), float(image.at(i, s.y))});
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
    std::vector<double> x(n), y(n, 0.0), s(n), p(n), ps(n), q(rows.size()), r(rows.size());
    for (std::size_t i = 0; i < n; ++i) x[i] = model->entry_value(i);
    auto apply = [&](const std::vector<double>& v, std::vector<double>* out) {  // out = A v
        for (const FaceRows& fr : faces) {
            const double a = v[fr.entry[0]], b = v[fr.entry[1]], c = v[fr.entry[2]];
            for (std::size_t k = fr.begin; k < fr.end; ++k)
                (*out)[k] = c + double(rows[k].w0) * (a - c) + double(rows[k].w1) * (b - c);
        }
    };
    auto apply_t = [&](const std::vector<double>& w, std::vector<double>* out) {  // out = S A^T w
        std::fill(out->begin(), out->end(), 0.0);
        for (const FaceRows& fr : faces) {
            double sa = 0, sb = 0, sc = 0;
            for (std::size_t k = fr.begin; k < fr.end; ++k) {
                const double w0 = rows[k].w0, w1 = rows[k].w1;
                sa += w0 * w[k];
                sb += w1 * w[k];
                sc += (1.0 - w0 - w1) * w[k];
            }
            (*out)[fr.entry[0]] += sa;
            (*out)[fr.entry[1]] += sb;
            (*out)[fr.entry[2]] += sc;
        }
        for (std::size_t i = 0; i < out->size(); ++i) (*out)[i] *= scale[i];
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double t = 0;
        for (std::size_t i = 0; i < a.size(); ++i) t += a[i] * b[i];
        return t;
    };

    // Residual of the starting values; the unknown is the correction x - x0 = S y.
    apply(x, &r);
    for (std::size_t k = 0; k < rows.size(); ++k) r[k] = double(rows[k].b) - r[k];
    if (stats) stats->sse_before = dot(r, r);
    apply_t(r, &s);
    p = s;
    double gamma = dot(s, s);
    int it = 0;
    for (; it < iterations && gamma > 1e-12; ++it) {
        for (std::size_t i = 0; i < n; ++i) ps[i] = scale[i] * p[i];
        // A (S p) without the constant part: apply() of a correction is linear.
        apply(ps, &q);
        const double qq = dot(q, q);
        if (qq <= 0) break;
        const double alpha = gamma / qq;
        for (std::size_t i = 0; i < n; ++i) y[i] += alpha * p[i];
        for (std::size_t k = 0; k < rows.size(); ++k) r[k] -= alpha * q[k];
        apply_t(r, &s);
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
        apply(x, &q);
        double sse = 0;
        for (const FaceRows& fr : faces)
            for (std::size_t k = fr.begin; k < fr.end; ++k) {
                double a = model->entry_value(fr.entry[0]), b = model->entry_value(fr.entry[1]), c = model->entry_value(fr.entry[2]);
                const double z = c + double(rows[k].w0) * (a - c) + double(rows[k].w1) * (b - c) - double(rows[k].b);
                sse += z * z;
            }
        stats->sse_after = sse;
    }
}

}  // namespace erd
