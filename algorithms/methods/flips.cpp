#include "algorithms/methods/flips.h"

#include <vector>

#include "kernel/raster.h"

namespace erd {

namespace {

constexpr std::size_t kMaxChannels = 3;

// Squared error of the plane through (p_i, z_i) over the pixels the triangle owns, summed over
// the channels (planes[c] with values z_i[c]; one scan of the triangle for all of them).
class TriangleError {
public:
    TriangleError(const std::vector<const Image*>& planes, const Cdt& cdt)
        : planes_(planes), domain_{cdt.max_x(), cdt.max_y()} {}

    double operator()(LatticePoint p0, const double* z0, LatticePoint p1, const double* z1, LatticePoint p2,
                      const double* z2) {
        if (scan_triangle(Lattice::pixels(), domain_, p0, p1, p2, &spans_) == 0) return 0.0;
        double total = 0.0;
        for (std::size_t c = 0; c < planes_.size(); ++c) {
            const Image& image = *planes_[c];
            SpanPlane plane;
            plane.set(p0, z0[c], p1, z1[c], p2, z2[c]);
            const double dv = 2.0 * plane.gx;
            double sse = 0.0;
            for (const Span& sp : spans_) {
                const std::uint16_t* px = &image.samples[std::size_t(sp.y) * std::size_t(image.width)];
                double v = plane.at(double(2 * sp.x_begin), double(2 * sp.y));
                for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i, v += dv) {
                    const double d = v - double(px[i]);
                    sse += d * d;
                }
            }
            total = c == 0 ? sse : total + sse;
        }
        return total;
    }

private:
    const std::vector<const Image*>& planes_;
    RasterDomain domain_;
    std::vector<Span> spans_;
};

}  // namespace

void improve_by_flips(Cdt* cdt, const Image& image, const ErdModel& model, std::size_t max_flips, FlipStats* stats,
                      const std::vector<FaceInd>* seed_faces) {
    improve_by_flips(cdt, {&image}, {&model}, max_flips, stats, seed_faces);
}

void improve_by_flips(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                      std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces) {
    FlipStats st;
    TriangleError triangle_error(planes, *cdt);
    const std::size_t C = models.size();
    const std::size_t nf = cdt->face_count();
    std::vector<double> face_sse(nf, -1.0);  // < 0: not computed yet
    // The squared error over the triangle of the corners at the origins of e0, e1, e2.
    auto tri_error = [&](EdgeInd e0, EdgeInd e1, EdgeInd e2) {
        double z[3][kMaxChannels];
        const EdgeInd e[3] = {e0, e1, e2};
        for (int i = 0; i < 3; ++i)
            for (std::size_t c = 0; c < C; ++c) z[i][c] = models[c]->corner_value(*cdt, e[i]);
        return triangle_error(cdt->point(cdt->org(e0)), z[0], cdt->point(cdt->org(e1)), z[1], cdt->point(cdt->org(e2)), z[2]);
    };
    auto sse_of = [&](FaceInd f) {
        if (face_sse[f] < 0) {
            const EdgeInd e = 3 * f;
            face_sse[f] = tri_error(e, e + 1, e + 2);
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
        const double before = sse_of(face_of(e)) + sse_of(face_of(t));
        const double s1 = tri_error(ec, ea, ed), s2 = tri_error(ed, eb, ec);
        ++st.tested;
        // A flip must win by more than rounding: the squared error then falls at every flip and
        // no edge flips back and forth.
        if (!(s1 + s2 < before - 1e-9 * (before + 1.0))) continue;
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
