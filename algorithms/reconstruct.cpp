// Reconstruction by scan conversion (see reconstruct.h).
//
// Supersampling without a supersampled buffer: the 4x4 sub-samples are the lattice
// Lattice::supersample(), whose column index i = 4x + k names pixel x directly, so a span is cut
// into runs of at most four sub-samples of one pixel and each run adds n*v + dv*n(n-1)/2 to that
// pixel's sum (one multiply-add per run, no per-sample work). Sub-samples outside Gamma are
// clamped onto its border; they are the values of the function on the border lines at the
// sub-sample rows (columns), which are themselves lattices of kernel/raster.h:
//     x = 0 and x = W-1 at the sub-sample rows   (weight 2: two sub-samples clamp to each)
//     y = 0 and y = H-1 at the sub-sample columns (weight 2)
//     the four corners                            (weight 4; always vertices)
// Points on discontinuity edges were first evaluated on their owning face; a second pass over
// those edges moves them to the mean of the two faces. Vertices never lie on the sub-sample
// lattice (odd fine coordinates), except the corners, which the border pass takes care of.
#include "algorithms/reconstruct.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/model_topology.h"
#include "kernel/predicates.h"
#include "kernel/raster.h"

namespace erd {
namespace {

Status not_triangulation(const std::string& why) {
    return Status::bad_input("not a triangulation of the image domain: " + why);
}

std::string pt(LatticePoint p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

struct Prepared {
    ModelTopology topo;
    RasterDomain dom;
    std::vector<double> vertex_value;  // the function's value at each vertex (mean of wedges)
    std::vector<SpanPlane> planes;     // per face, through its corner values
};

Status prepare(const Model& m, bool count_pixels, Prepared* p) {
    if (m.width < 2 || m.height < 2 || m.width > kMaxImageSide || m.height > kMaxImageSide)
        return Status::bad_input("image size " + std::to_string(m.width) + " x " + std::to_string(m.height) +
                                 " out of range (2.." + std::to_string(kMaxImageSide) + " a side)");
    if (std::int64_t(m.width) * m.height > kMaxImagePixels)
        return Status::bad_input("image " + std::to_string(m.width) + " x " + std::to_string(m.height) + " is larger than the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    if (m.maxval < 1 || m.maxval > 65535) return Status::bad_input("maxval " + std::to_string(m.maxval) + " out of range (1..65535)");
    const std::size_t nv = m.vertices.size(), nf = m.faces.size();
    if (m.values.size() != nv)
        return Status::bad_input("model has " + std::to_string(m.values.size()) + " values for " + std::to_string(nv) + " vertices");
    const bool erd = m.kind == ModelKind::erd;
    if (erd && m.corner_values.size() != nf)
        return Status::bad_input("ERD model has corner values for " + std::to_string(m.corner_values.size()) + " of " +
                                 std::to_string(nf) + " faces");
    for (double z : m.values)
        if (!std::isfinite(z)) return Status::bad_input("model has a vertex value that is not a finite number");
    if (erd)
        for (const auto& c : m.corner_values)
            for (double z : c)
                if (!std::isfinite(z)) return Status::bad_input("model has a wedge value that is not a finite number");
    const RasterDomain dom{2 * m.width - 2, 2 * m.height - 2};
    p->dom = dom;
    for (std::size_t v = 0; v < nv; ++v) {
        const LatticePoint q = m.vertices[v];
        if (q.x < 0 || q.y < 0 || q.x > dom.max_x || q.y > dom.max_y)
            return not_triangulation("vertex " + std::to_string(v) + " " + pt(q) + " lies outside the domain");
    }
    if (Status s = build_topology(m, &p->topo); !s) return not_triangulation(s.message);
    // Areas (twice, doubled coordinates) must add up to the rectangle's.
    const std::int64_t target = 2 * std::int64_t(dom.max_x) * dom.max_y;
    std::int64_t area = 0;
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m.faces[f];
        const std::int64_t o = orient2d(m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]]);
        if (o <= 0) return not_triangulation("face " + std::to_string(f) + (o == 0 ? " is degenerate" : " is not positively oriented"));
        area += o;
        if (area > target) return not_triangulation("the faces overlap (their areas add up to more than the rectangle)");
    }
    if (area != target) return not_triangulation("the faces leave holes (their areas add up to less than the rectangle)");
    const auto on_border_line = [&](LatticePoint a, LatticePoint b) {
        return (a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) || (a.x == dom.max_x && b.x == dom.max_x) ||
               (a.y == dom.max_y && b.y == dom.max_y);
    };
    for (std::uint32_t h = 0; h < p->topo.twin.size(); ++h) {
        if (p->topo.twin[h] != kNoHalfEdge) continue;
        const std::uint32_t u = m.faces[h / 3][h % 3], w = m.faces[h / 3][(h + 1) % 3];
        if (!on_border_line(m.vertices[u], m.vertices[w]))
            return not_triangulation("edge " + std::to_string(u) + "-" + std::to_string(w) + " of face " + std::to_string(h / 3) +
                                     " has no neighbouring face but is not on the border");
    }
    // Positive faces inside the rectangle, areas adding up to it, edges paired up and unpaired
    // edges on the border: a triangulation, so every lattice point has exactly one owner
    // (kernel/raster.h). check_triangulation() counts the pixels all the same.
    if (count_pixels) {
        std::vector<std::uint8_t> owned(std::size_t(m.width) * std::size_t(m.height), 0);
        std::vector<Span> spans;
        for (const auto& fc : m.faces) {
            scan_triangle(Lattice::pixels(), dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
            for (const Span& s : spans) {
                std::uint8_t* row = owned.data() + std::size_t(s.y) * std::size_t(m.width);
                for (std::int32_t x = s.x_begin; x <= s.x_end; ++x) row[x] = std::uint8_t(std::min(row[x] + 1, 2));
            }
        }
        for (std::size_t i = 0; i < owned.size(); ++i)
            if (owned[i] != 1)
                return not_triangulation("pixel (" + std::to_string(i % std::size_t(m.width)) + ", " +
                                         std::to_string(i / std::size_t(m.width)) + ") is owned by " +
                                         (owned[i] == 0 ? "no face" : "several faces"));
    }
    p->vertex_value.resize(nv);
    for (std::uint32_t v = 0; v < nv; ++v) p->vertex_value[v] = erd ? vertex_wedges(m, p->topo, v).mean : m.values[v];
    p->planes.resize(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m.faces[f];
        const std::uint32_t h = std::uint32_t(3 * f);
        p->planes[f].set(m.vertices[fc[0]], corner_value(m, h), m.vertices[fc[1]], corner_value(m, h + 1), m.vertices[fc[2]],
                         corner_value(m, h + 2));
    }
    return Status::success();
}

// Calls fn(i, j) for every point of lattice l strictly inside segment p-q (doubled coordinates).
template <class Fn>
void for_each_on_segment(const Lattice& l, LatticePoint p, LatticePoint q, Fn fn) {
    const auto mod = [](std::int64_t a, std::int64_t b) { return ((a % b) + b) % b; };
    const auto cdiv = [&](std::int64_t a, std::int64_t b) { return (a - mod(a, b)) / b + (mod(a, b) != 0); };
    const auto fdiv = [&](std::int64_t a, std::int64_t b) { return (a - mod(a, b)) / b; };
    std::int64_t px = std::int64_t(p.x) * l.scale, py = std::int64_t(p.y) * l.scale;
    std::int64_t qx = std::int64_t(q.x) * l.scale, qy = std::int64_t(q.y) * l.scale;
    if (py == qy) {
        if (mod(py - l.phase_y, l.step_y) != 0) return;
        const std::int64_t j = (py - l.phase_y) / l.step_y;
        const std::int64_t lo = std::min(px, qx) + 1, hi = std::max(px, qx) - 1;
        for (std::int64_t i = cdiv(lo - l.phase_x, l.step_x); i <= fdiv(hi - l.phase_x, l.step_x); ++i)
            fn(std::int32_t(i), std::int32_t(j));
        return;
    }
    if (py > qy) {
        std::swap(px, qx);
        std::swap(py, qy);
    }
    const std::int64_t dy = qy - py, dx = qx - px;
    for (std::int64_t j = cdiv(py + 1 - l.phase_y, l.step_y); j <= fdiv(qy - 1 - l.phase_y, l.step_y); ++j) {
        const std::int64_t y = l.fine_y(j);
        const std::int64_t t = dx * (y - py);
        if (t % dy != 0) continue;
        const std::int64_t x = px + t / dy;
        if (mod(x - l.phase_x, l.step_x) != 0) continue;
        fn(std::int32_t((x - l.phase_x) / l.step_x), std::int32_t(j));
    }
}

// Round to nearest (halves up) and clamp; truncation is floor for the positive values left.
std::uint16_t to_sample(double v, double maxval) {
    if (!(v > 0.0)) return 0;  // also NaN
    if (v >= maxval) return std::uint16_t(maxval);
    return std::uint16_t(v + 0.5);
}

// Moves the points of lattice l on discontinuity edges to the mean of the two sides:
// set(i, j, mean, owner_value) is called for each. Along the edge each side is the linear
// interpolation of its corner values at the endpoints, computed from the exact fraction t of the
// way along the edge, so that e.g. sides 73 and 54 give exactly 63.5 (which rounds up).
template <class Set>
void fix_discontinuities(const Model& m, const Prepared& p, const Lattice& l, Set set) {
    if (m.kind != ModelKind::erd) return;
    for (std::uint32_t h = 0; h < p.topo.twin.size(); ++h) {
        const std::uint32_t o = p.topo.twin[h];
        if (o == kNoHalfEdge || o < h || !is_discontinuity(m, p.topo, h)) continue;
        const std::uint32_t f = h / 3;
        const auto& fc = m.faces[f];
        const LatticePoint a = m.vertices[fc[0]], b = m.vertices[fc[1]], c = m.vertices[fc[2]];
        const LatticePoint u = m.vertices[fc[h % 3]], w = m.vertices[fc[(h + 1) % 3]];
        // h runs u->w in face f; its twin o runs w->u in the other face.
        const double fu = corner_value(m, h), fw = corner_value(m, ModelTopology::next(h));
        const double gu = corner_value(m, ModelTopology::next(o)), gw = corner_value(m, o);
        const bool along_y = std::abs(std::int64_t(w.y) - u.y) >= std::abs(std::int64_t(w.x) - u.x);
        const std::int64_t u0 = std::int64_t(along_y ? u.y : u.x) * l.scale;
        const std::int64_t den = std::int64_t(along_y ? w.y : w.x) * l.scale - u0;
        for_each_on_segment(l, u, w, [&](std::int32_t i, std::int32_t j) {
            const std::int64_t num = (along_y ? l.fine_y(j) : l.fine_x(i)) - u0;
            const double r = double(den - num), q = double(num), d = double(den);
            const double vf = (r * fu + q * fw) / d, vg = (r * gu + q * gw) / d;
            const bool f_owns = triangle_owns(l, p.dom, a, b, c, i, j);
            set(i, j, 0.5 * (vf + vg), f_owns ? vf : vg);
        });
    }
}

void point_evaluation(const Model& m, const Prepared& p, Image* out) {
    const std::size_t W = std::size_t(m.width);
    std::vector<double> val(W * std::size_t(m.height), 0.0);
    const Lattice l = Lattice::pixels();
    std::vector<Span> spans;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& fc = m.faces[f];
        scan_triangle(l, p.dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
        const SpanPlane& pl = p.planes[f];
        const double dv = pl.step_x(l);
        for (const Span& s : spans) {
            double* row = val.data() + std::size_t(s.y) * W;
            double v = pl.at(l, s.x_begin, s.y);
            for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += dv) row[x] = v;
        }
    }
    fix_discontinuities(m, p, l, [&](std::int32_t i, std::int32_t j, double mean, double) {
        val[std::size_t(j) * W + std::size_t(i)] = mean;
    });
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if (q.x % 2 == 0 && q.y % 2 == 0) val[std::size_t(q.y / 2) * W + std::size_t(q.x / 2)] = p.vertex_value[v];
    }
    const double maxval = m.maxval;
    for (std::size_t i = 0; i < val.size(); ++i) out->samples[i] = to_sample(val[i], maxval);
}

void supersampling(const Model& m, const Prepared& p, Image* out) {
    const std::size_t W = std::size_t(m.width), H = std::size_t(m.height);
    std::vector<double> acc(W * H, 0.0);  // sum of the 16 sub-samples of each pixel
    const Lattice l = Lattice::supersample();
    std::vector<Span> spans;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& fc = m.faces[f];
        scan_triangle(l, p.dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
        // The plane in fine units (scale 4 is a power of two: no rounding is added).
        const SpanPlane& pl = p.planes[f];
        const double gx = pl.gx / l.scale, gy = pl.gy / l.scale, x0 = pl.x0 * l.scale, y0 = pl.y0 * l.scale;
        const double dv = gx * l.step_x, six = 6.0 * dv, four = 4.0 * dv;
        for (const Span& s : spans) {
            double* row = acc.data() + std::size_t(s.y >> 2) * W;
            double v = pl.z0 + gx * (double(l.fine_x(s.x_begin)) - x0) + gy * (double(l.fine_y(s.y)) - y0);
            std::int32_t i = s.x_begin;
            // A partial pixel at each end, whole pixels (4 sub-samples: 4v + 6dv) between.
            const auto partial = [&](std::int32_t e) {
                const double n = double(e - i + 1);
                row[i >> 2] += n * v + dv * (n * (n - 1.0) * 0.5);
                v += dv * n;
                i = e + 1;
            };
            if ((i & 3) != 0) partial(std::min(s.x_end, i | 3));
            const std::int32_t whole = (s.x_end + 1 - i) >> 2;
            double* px = row + (i >> 2);
            for (std::int32_t k = 0; k < whole; ++k, v += four) px[k] += 4.0 * v + six;
            i += whole << 2;
            if (i <= s.x_end) partial(s.x_end);
        }
    }
    // Clamped sub-samples on the border lines.
    const std::int32_t mx = p.dom.max_x, my = p.dom.max_y;
    const Lattice cols{4, 4 * mx, 2, 0, -3}, rows{4, 2, 4 * my, -3, 0};
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& fc = m.faces[f];
        const LatticePoint a = m.vertices[fc[0]], b = m.vertices[fc[1]], c = m.vertices[fc[2]];
        const auto touches_x = [&](std::int32_t x) { return a.x == x || b.x == x || c.x == x; };
        const auto touches_y = [&](std::int32_t y) { return a.y == y || b.y == y || c.y == y; };
        if (touches_x(0) || touches_x(mx)) {
            scan_triangle(cols, p.dom, a, b, c, &spans);
            for (const Span& s : spans)
                for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                    acc[std::size_t(s.y >> 2) * W + (i == 0 ? 0 : W - 1)] += 2.0 * p.planes[f].at(cols, i, s.y);
        }
        if (touches_y(0) || touches_y(my)) {
            scan_triangle(rows, p.dom, a, b, c, &spans);
            for (const Span& s : spans)
                for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                    acc[(s.y == 0 ? 0 : H - 1) * W + std::size_t(i >> 2)] += 2.0 * p.planes[f].at(rows, i, s.y);
        }
    }
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if ((q.x == 0 || q.x == mx) && (q.y == 0 || q.y == my))
            acc[(q.y == 0 ? 0 : H - 1) * W + (q.x == 0 ? 0 : W - 1)] += 4.0 * p.vertex_value[v];
    }
    fix_discontinuities(m, p, l, [&](std::int32_t i, std::int32_t j, double mean, double owner) {
        acc[std::size_t(j >> 2) * W + std::size_t(i >> 2)] += mean - owner;
    });
    const double maxval = m.maxval;
    for (std::size_t i = 0; i < acc.size(); ++i) out->samples[i] = to_sample(acc[i] * (1.0 / 16.0), maxval);
}

}  // namespace

Status check_triangulation(const Model& m) {
    Prepared p;
    return prepare(m, true, &p);
}

Status reconstruct(const Model& m, bool supersample, Image* out) {
    Prepared p;
    if (Status s = prepare(m, false, &p); !s) return s;
    Image im(m.width, m.height, m.maxval);
    if (supersample) supersampling(m, p, &im);
    else point_evaluation(m, p, &im);
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd
