#include "algorithms/methods/flips.h"

#include <limits>
#include <vector>

#include "kernel/raster.h"

namespace erd {

namespace {

// Squared error of the plane through (p_i, z_i) over the pixels the triangle owns. With a
// `stop`, the sum ends after the first span where base + sum >= stop: the partial sum says all
// a rejected flip needs (sums of squares only grow, and so does a rounded sum), for a fraction
// of the pixels.
class TriangleError {
public:
    TriangleError(const Image& image, const Cdt& cdt) : image_(image), domain_{cdt.max_x(), cdt.max_y()} {}

    double operator()(LatticePoint p0, double z0, LatticePoint p1, double z1, LatticePoint p2, double z2,
                      double base = 0.0, double stop = std::numeric_limits<double>::infinity()) {
        if (scan_triangle(Lattice::pixels(), domain_, p0, p1, p2, &spans_) == 0) return 0.0;
        SpanPlane plane;
        plane.set(p0, z0, p1, z1, p2, z2);
        const double dv = 2.0 * plane.gx;
        double sse = 0.0;
        for (const Span& sp : spans_) {
            const std::uint16_t* px = &image_.samples[std::size_t(sp.y) * std::size_t(image_.width)];
            double v = plane.at(double(2 * sp.x_begin), double(2 * sp.y));
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i, v += dv) {
                const double d = v - double(px[i]);
                sse += d * d;
            }
            if (base + sse >= stop) break;
        }
        return sse;
    }

private:
    const Image& image_;
    RasterDomain domain_;
    std::vector<Span> spans_;
};

}  // namespace

void improve_by_flips(Cdt* cdt, const Image& image, const ErdModel& model, std::size_t max_flips, FlipStats* stats,
                      const std::vector<FaceInd>* seed_faces) {
    FlipStats st;
    TriangleError tri_error(image, *cdt);
    const std::size_t nf = cdt->face_count();
    std::vector<double> face_sse(nf, -1.0);  // < 0: not computed yet
    auto corner = [&](EdgeInd e) { return model.corner_value(*cdt, e); };
    auto sse_of = [&](FaceInd f) {
        if (face_sse[f] < 0) {
            const EdgeInd e = 3 * f;
            face_sse[f] = tri_error(cdt->point(cdt->org(e)), corner(e), cdt->point(cdt->org(e + 1)), corner(e + 1),
                                    cdt->point(cdt->org(e + 2)), corner(e + 2));
        }
        return face_sse[f];
    };
    std::vector<EdgeInd> work;
    std::vector<std::uint8_t> queued(3 * nf, 0);
    auto enqueue = [&](EdgeInd k) {
        const EdgeInd tk = cdt->twin(k);
        if (tk == noEdge || cdt->constrained(k)) return;
        const EdgeInd key = k < tk ? k : tk;
        if (!queued[key]) {
            queued[key] = 1;
            work.push_back(key);
        }
    };
    if (seed_faces) {
        for (FaceInd f : *seed_faces)
            for (EdgeInd k = 3 * f; k < 3 * f + 3; ++k) enqueue(k);
    } else {
        for (EdgeInd e = 3 * EdgeInd(nf); e-- > 0;) enqueue(e);
    }
    while (!work.empty() && st.flips < max_flips) {
        const EdgeInd e = work.back();
        work.pop_back();
        queued[e] = 0;
        if (!cdt->can_flip(e)) continue;
        const EdgeInd t = cdt->twin(e);
        // Faces (a,b,c) and (b,a,d) -> (c,a,d) and (d,b,c) (kernel/cdt.h).
        const EdgeInd ea = e, eb = next_edge(e), ec = prev_edge(e), ed = prev_edge(t);
        const LatticePoint a = cdt->point(cdt->org(ea)), b = cdt->point(cdt->org(eb));
        const LatticePoint c = cdt->point(cdt->org(ec)), d = cdt->point(cdt->org(ed));
        const double za = corner(ea), zb = corner(eb), zc = corner(ec), zd = corner(ed);
        const double before = sse_of(face_of(e)) + sse_of(face_of(t));
        // A flip must win by more than rounding: the squared error then falls at every flip and
        // no edge flips back and forth. A sum cut short at the limit is at least the limit, and
        // so is the whole one: the same verdict; an accepted flip has both sums whole.
        const double limit = before - 1e-9 * (before + 1.0);
        ++st.tested;
        const double s1 = tri_error(c, zc, a, za, d, zd, 0.0, limit);
        if (!(s1 < limit)) continue;
        const double s2 = tri_error(d, zd, b, zb, c, zc, s1, limit);
        if (!(s1 + s2 < limit)) continue;
        const EdgeInd diag = cdt->flip_edge(e);
        if (diag == noEdge) continue;
        ++st.flips;
        st.sse_before += before;
        st.sse_after += s1 + s2;
        const FaceInd f1 = face_of(diag), f2 = face_of(cdt->twin(diag));
        face_sse[f1] = s1;  // f1 = (c,a,d), f2 = (d,b,c)
        face_sse[f2] = s2;
        st.changed.push_back(f1);
        st.changed.push_back(f2);
        for (FaceInd f : {f1, f2})
            for (EdgeInd k = 3 * f; k < 3 * f + 3; ++k)
                if (k != diag && cdt->twin(k) != diag) enqueue(k);
    }
    if (stats) *stats = st;
}

}  // namespace erd
