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
// The sums live for one band of pixel rows at a time (cache-sized), each pixel's additions made
// in the same order as in one whole-image pass, so banding changes no bit (see supersampling()).
#include "algorithms/model/reconstruct.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/model/edge_kinds.h"
#include "algorithms/model/model_topology.h"
#include "kernel/predicates.h"
#include "kernel/raster.h"
#include "kernel/raster_rows.h"
#include "kernel/row_parallel.h"

namespace erd {
namespace {

Status not_triangulation(const std::string& why) {
    return Status::bad_input("not a triangulation of the image domain: " + why);
}

std::string pt(LatticePoint p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

struct Prepared {
    ModelTopology own;                     // built here unless the caller passes one
    const ModelTopology* topo = nullptr;   // own or the caller's
    RasterDomain dom;
    // The function's value at vertex v in channel c (the mean of its wedges), computed where it is
    // used: point evaluation needs it at the vertices on pixels, supersampling at the corners only.
    double vertex_value(const Model& m, std::uint32_t v, std::size_t c) const {
        return m.kind == ModelKind::erd ? vertex_wedges(m, *topo, v, int(c)).mean : m.values[v * std::size_t(m.channels) + c];
    }
    std::vector<SpanPlane> planes;     // per face and channel, through its corner values, [f*C + c]
};

// Checks m as check_triangulation() describes and sets up *p. `given` (may be null) is m's
// adjacency when the caller has it.
Status prepare(const Model& m, bool count_pixels, const ModelTopology* given, Prepared* p) {
    if (m.width < 2 || m.height < 2 || m.width > kMaxImageSide || m.height > kMaxImageSide)
        return Status::bad_input("image size " + std::to_string(m.width) + " x " + std::to_string(m.height) +
                                 " out of range (2.." + std::to_string(kMaxImageSide) + " a side)");
    if (std::int64_t(m.width) * m.height > kMaxImagePixels)
        return Status::bad_input("image " + std::to_string(m.width) + " x " + std::to_string(m.height) + " is larger than the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    if (m.maxval < 1 || m.maxval > 65535) return Status::bad_input("maxval " + std::to_string(m.maxval) + " out of range (1..65535)");
    if (m.channels != 1 && m.channels != 3)
        return Status::bad_input("model has " + std::to_string(m.channels) + " channels (1 or 3)");
    const std::size_t nv = m.vertices.size(), nf = m.faces.size(), C = std::size_t(m.channels);
    if (m.values.size() != nv * C)
        return Status::bad_input("model has " + std::to_string(m.values.size()) + " values for " + std::to_string(nv) + " vertices" +
                                 (C > 1 ? " in " + std::to_string(C) + " channels" : ""));
    const bool erd = m.kind == ModelKind::erd;
    if (erd && m.corner_values.size() != nf * C)
        return Status::bad_input("ERD model has corner values for " + std::to_string(m.corner_values.size()) + " of " +
                                 std::to_string(nf * C) + (C > 1 ? " face channels" : " faces"));
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
    if (given && given->twin.size() == 3 * nf && given->corner_begin.size() == nv + 1) {
        p->topo = given;
    } else {
        if (Status s = build_topology(m, &p->own); !s) return not_triangulation(s.message);
        p->topo = &p->own;
    }
    const ModelTopology& topo = *p->topo;
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
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h) {
        if (topo.twin[h] != kNoHalfEdge) continue;
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
    p->planes.resize(nf * C);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m.faces[f];
        const std::uint32_t h = std::uint32_t(3 * f);
        for (std::size_t c = 0; c < C; ++c) {
            const int k = int(c);
            p->planes[f * C + c].set(m.vertices[fc[0]], corner_value(m, h, k), m.vertices[fc[1]], corner_value(m, h + 1, k),
                                     m.vertices[fc[2]], corner_value(m, h + 2, k));
        }
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

// Round to nearest (halves up) and clamp; truncation is floor for the non-negative values left.
// Selects instead of branches (NaN also gives 0), so the loops applying it can vectorise.
std::uint16_t to_sample(double v, double maxval) {
    const double c = v > 0.0 ? (v < maxval ? v : maxval) : 0.0;
    return std::uint16_t(std::int32_t(c + 0.5));
}

// Moves the points of lattice l on discontinuity edges to the mean of the two sides:
// set(i, j, c, mean, owner_value) is called for each point and channel c. Along the edge each
// side is the linear interpolation of its corner values at the endpoints, computed from the exact
// fraction t of the way along the edge, so that e.g. sides 73 and 54 give exactly 63.5 (which
// rounds up).
template <class Set>
void fix_discontinuities(const Model& m, const Prepared& p, const Lattice& l, Set set) {
    if (m.kind != ModelKind::erd) return;
    for (std::uint32_t h = 0; h < p.topo->twin.size(); ++h) {
        const std::uint32_t o = p.topo->twin[h];
        if (o == kNoHalfEdge || o < h || !is_discontinuity(m, *p.topo, h)) continue;
        const std::uint32_t f = h / 3;
        const auto& fc = m.faces[f];
        const LatticePoint a = m.vertices[fc[0]], b = m.vertices[fc[1]], c = m.vertices[fc[2]];
        const LatticePoint u = m.vertices[fc[h % 3]], w = m.vertices[fc[(h + 1) % 3]];
        // h runs u->w in face f; its twin o runs w->u in the other face.
        double fu[3], fw[3], gu[3], gw[3];
        for (int k = 0; k < m.channels; ++k) {
            fu[k] = corner_value(m, h, k), fw[k] = corner_value(m, ModelTopology::next(h), k);
            gu[k] = corner_value(m, ModelTopology::next(o), k), gw[k] = corner_value(m, o, k);
        }
        const bool along_y = std::abs(std::int64_t(w.y) - u.y) >= std::abs(std::int64_t(w.x) - u.x);
        const std::int64_t u0 = std::int64_t(along_y ? u.y : u.x) * l.scale;
        const std::int64_t den = std::int64_t(along_y ? w.y : w.x) * l.scale - u0;
        for_each_on_segment(l, u, w, [&](std::int32_t i, std::int32_t j) {
            const std::int64_t num = (along_y ? l.fine_y(j) : l.fine_x(i)) - u0;
            const double r = double(den - num), q = double(num), d = double(den);
            const bool f_owns = triangle_owns(l, p.dom, a, b, c, i, j);
            for (int k = 0; k < m.channels; ++k) {
                const double vf = (r * fu[k] + q * fw[k]) / d, vg = (r * gu[k] + q * gw[k]) / d;
                set(i, j, k, 0.5 * (vf + vg), f_owns ? vf : vg);
            }
        });
    }
}

// The exactly rounded plane of face f of a basic model whose corner values are integers in
// [0, maxval] (kernel/raster.h RoundedPlane); false for any other face, which is evaluated in
// doubles. Greedy refinement (algorithms/methods/greedy.cpp) makes the same choice per face, so
// GPI's errors are exactly those of this reconstruction.
bool exact_plane(const Model& m, std::size_t f, int c, RoundedPlane* rp) {
    if (m.kind != ModelKind::basic) return false;
    const auto& fc = m.faces[f];
    std::int64_t z[3];
    for (int i = 0; i < 3; ++i) {
        const double v = m.values[std::size_t(fc[i]) * std::size_t(m.channels) + std::size_t(c)];
        if (!(v >= 0.0 && v <= double(m.maxval)) || v != std::floor(v)) return false;
        z[i] = std::int64_t(v);
    }
    return rp->set(m.vertices[fc[0]], z[0], m.vertices[fc[1]], z[1], m.vertices[fc[2]], z[2], m.maxval);
}

// Every pixel is written once by its owning face, then overwritten on discontinuity edges and at
// vertices; each write is final, so it is rounded on the spot (no W x H buffer of doubles). A
// face's spans are scanned once for all channels; channel c of pixel x of a row is row[x*C + c].
// Faces in parts of 1024 at least side by side (kernel/row_parallel.h): each pixel is owned by
// one face, so the parts write disjoint pixels and the image is the same for any count; the
// discontinuity and vertex writes over them follow on one thread, in their order.
void point_evaluation(const Model& m, const Prepared& p, Image* out, ProgressHook progress, int threads) {
    const std::size_t W = std::size_t(m.width), C = std::size_t(m.channels);
    const double maxval = m.maxval;
    std::uint16_t* px = out->samples.data();
    const Lattice l = Lattice::pixels();
    const RowParts parts(0, m.faces.size(), threads, 1024);
    run_parts(parts, [&](std::size_t part, std::size_t f0, std::size_t f1) {
        std::vector<Span> spans;
        RoundedPlane rp;
        // The spans of one face in one channel; `stride` is C, a constant 1 for gray so that its
        // loops stay as they were.
        const auto fill = [&](std::size_t f, std::size_t c, auto stride) {
            if (exact_plane(m, f, int(c), &rp)) {
                // p stepped from an exact start over each piece, truncated (kernel/raster.h).
                for (const Span& s : spans) {
                    std::uint16_t* row = px + std::size_t(s.y) * W * stride + c;
                    rp.pieces(s.x_begin, s.x_end, s.y, [&](std::int32_t first, std::int32_t last, double v) {
                        for (std::int32_t x = first; x <= last; ++x, v += rp.dp) row[std::size_t(x) * stride] = std::uint16_t(std::int32_t(v));
                    });
                }
                return;
            }
            const SpanPlane& pl = p.planes[f * C + c];
            const double dv = pl.step_x(l);
            for (const Span& s : spans) {
                std::uint16_t* row = px + std::size_t(s.y) * W * stride + c;
                double v = pl.at(l, s.x_begin, s.y);
                for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += dv) row[std::size_t(x) * stride] = to_sample(v, maxval);
            }
        };
        // Progress from the calling thread's part alone (the hook need not be thread-safe).
        const std::size_t n = f1 - f0, every = n / 100 + 1;
        for (std::size_t f = f0; f < f1; ++f) {
            if (part == 0 && progress && (f - f0) % every == 0) progress("reconstruct", double(f - f0) / double(n));
            const auto& fc = m.faces[f];
            scan_triangle(l, p.dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
            if (C == 1) fill(f, 0, std::integral_constant<std::size_t, 1>());
            else
                for (std::size_t c = 0; c < C; ++c) fill(f, c, C);
        }
    });
    fix_discontinuities(m, p, l, [&](std::int32_t i, std::int32_t j, int c, double mean, double) {
        px[(std::size_t(j) * W + std::size_t(i)) * C + std::size_t(c)] = to_sample(mean, maxval);
    });
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if (q.x % 2 == 0 && q.y % 2 == 0)
            for (std::size_t c = 0; c < C; ++c)
                px[(std::size_t(q.y / 2) * W + std::size_t(q.x / 2)) * C + c] = to_sample(p.vertex_value(m, std::uint32_t(v), c), maxval);
    }
}

// A face's plane along the sub-sample rows: dv per sub-sample; a partial pixel of n = 1..3
// sub-samples starting at value v adds n*v + tri[n] and moves v on by step[n] (the products
// dv * n(n-1)/2 and dv * n, taken once per face: the same doubles).
struct RowPlane {
    double dv, four, six;  // 4 dv and 6 dv: a whole pixel adds 4v + 6dv and moves v on by 4dv
    double tri[4], step[4];
    explicit RowPlane(double d) : dv(d), four(4.0 * d), six(6.0 * d), tri{0.0, d * 0.0, d * 1.0, d * 3.0}, step{0.0, d * 1.0, d * 2.0, d * 3.0} {}
};

// One span of sub-samples on Lattice::supersample() being added to its pixel row's sums: sub-sample
// i (column index; pixel i / 4) has value v. A span covers a partial pixel at each end and whole
// pixels between.
struct SubRow {
    double* row;
    double v;
    std::int32_t i, end;  // next and last sub-sample

    std::int32_t first_whole() const { return (i + 3) >> 2; }  // first pixel covered whole (before head())
    std::int32_t end_whole() const { return (end + 1) >> 2; }  // one past the last one
    void partial(std::int32_t e, const RowPlane& rp) {
        const std::int32_t n = e - i + 1;  // 1..3
        row[i >> 2] += double(n) * v + rp.tri[n];
        v += rp.step[n];
        i = e + 1;
    }
    void head(const RowPlane& rp) {
        if ((i & 3) != 0) partial(std::min(end, i | 3), rp);
    }
    // Whole pixels up to `stop` (exclusive); i is then a pixel's first sub-sample.
    void wholes(std::int32_t stop, const RowPlane& rp) {
        for (std::int32_t x = i >> 2; x < stop; ++x, v += rp.four) row[x] += 4.0 * v + rp.six;
        i = std::max(i, stop << 2);
    }
    void tail(const RowPlane& rp) {
        if (i <= end) partial(end, rp);
    }
};

// One face's plane on Lattice::supersample() in fine units (scale 4 is a power of two: no
// rounding is added), taken once per face and channel.
struct FinePlane {
    double z0, gx, gy, x0, y0;
    RowPlane rp;
    explicit FinePlane(const SpanPlane& pl)
        : z0(pl.z0), gx(pl.gx / Lattice::supersample().scale), gy(pl.gy / Lattice::supersample().scale),
          x0(pl.x0 * Lattice::supersample().scale), y0(pl.y0 * Lattice::supersample().scale),
          rp(gx * Lattice::supersample().step_x) {}
};

// Adds the sub-samples of one pixel row of a face, its n = 1..4 sub-row spans in order, to the
// pixel sums `acc`, whose row 0 is pixel row `row0`. Each pixel gets its additions sub-row by
// sub-row, as a plain span-by-span pass would; where all four sub-rows cover pixels whole, those
// pixels take their four terms in one pass (one load and store, four independent chains of v).
void add_pixel_row(const FinePlane& fp, const Span* spans, int n, double* acc, std::size_t W, std::size_t row0) {
    const Lattice l = Lattice::supersample();
    const RowPlane& rp = fp.rp;
    const auto start = [&](const Span& s) {
        double* row = acc + (std::size_t(s.y >> 2) - row0) * W;
        const double v = fp.z0 + fp.gx * (double(l.fine_x(s.x_begin)) - fp.x0) + fp.gy * (double(l.fine_y(s.y)) - fp.y0);
        return SubRow{row, v, s.x_begin, s.x_end};
    };
    if (n == 4) {  // sub-rows 0..3 of the pixel row
        SubRow r[4] = {start(spans[0]), start(spans[1]), start(spans[2]), start(spans[3])};
        const std::int32_t p0 = std::max({r[0].first_whole(), r[1].first_whole(), r[2].first_whole(), r[3].first_whole()});
        const std::int32_t p1 = std::min({r[0].end_whole(), r[1].end_whole(), r[2].end_whole(), r[3].end_whole()});
        if (p0 < p1) {
            for (SubRow& s : r) {
                s.head(rp);
                s.wholes(p0, rp);
            }
            double* row = r[0].row;
            double v0 = r[0].v, v1 = r[1].v, v2 = r[2].v, v3 = r[3].v;
            for (std::int32_t x = p0; x < p1; ++x, v0 += rp.four, v1 += rp.four, v2 += rp.four, v3 += rp.four)
                row[x] = row[x] + (4.0 * v0 + rp.six) + (4.0 * v1 + rp.six) + (4.0 * v2 + rp.six) + (4.0 * v3 + rp.six);
            r[0].v = v0, r[1].v = v1, r[2].v = v2, r[3].v = v3;
            for (SubRow& s : r) {
                s.i = p1 << 2;
                s.wholes(s.end_whole(), rp);
                s.tail(rp);
            }
            return;
        }
    }
    for (int k = 0; k < n; ++k) {
        SubRow s = start(spans[k]);
        s.head(rp);
        s.wholes(s.end_whole(), rp);
        s.tail(rp);
    }
}

// Adds the sub-samples face (a, b, c) owns in sub-rows j_begin..j_end to the sums of its C
// channels (plane c of `acc` for channel c, plane samples apart), walking the face's rows
// (kernel/raster_rows.h) and handing each pixel row's sub-row spans on as soon as the row is
// complete: no list of spans, one walk for all channels. The additions are those of scanning the
// face's spans and adding them span by span, in the same order (pixel rows are disjoint sums).
void add_face(const FinePlane* fp, std::size_t C, LatticePoint a, LatticePoint b, LatticePoint c, RasterDomain dom,
              std::int32_t j_begin, std::int32_t j_end, double* acc, std::size_t plane, std::size_t W, std::size_t row0) {
    OwnedRows rows(Lattice::supersample(), dom, a, b, c, j_begin, j_end);
    Span g[4];
    int n = 0;
    const auto flush = [&] {
        if (C == 1) add_pixel_row(fp[0], g, n, acc, W, row0);
        else
            for (std::size_t k = 0; k < C; ++k) add_pixel_row(fp[k], g, n, acc + k * plane, W, row0);
        n = 0;
    };
    for (RowRun part; rows.next(&part);) {
        for (RowRun run = part; run.j <= run.j_end; run.step()) {
            std::int64_t lo, hi;
            run.columns(&lo, &hi);
            if (lo > hi) continue;
            const std::int32_t j = std::int32_t(run.j);
            if (n > 0 && (j >> 2) != (g[0].y >> 2)) flush();
            g[n++] = Span{j, std::int32_t(lo), std::int32_t(hi)};
        }
    }
    if (n > 0) flush();
}

// One addition to a pixel's sum made after all faces' interior sub-samples; `sample` is the
// pixel's index times C plus the channel (the index of its sample in the image).
struct LateTerm {
    std::size_t sample;
    double add;
};

// The clamped border sub-samples and the discontinuity corrections, in the order the sums take them.
std::vector<LateTerm> late_terms(const Model& m, const Prepared& p) {
    const std::size_t W = std::size_t(m.width), H = std::size_t(m.height), C = std::size_t(m.channels);
    std::vector<LateTerm> late;
    std::vector<Span> spans;
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
                    for (std::size_t k = 0; k < C; ++k)
                        late.push_back({(std::size_t(s.y >> 2) * W + (i == 0 ? 0 : W - 1)) * C + k, 2.0 * p.planes[f * C + k].at(cols, i, s.y)});
        }
        if (touches_y(0) || touches_y(my)) {
            scan_triangle(rows, p.dom, a, b, c, &spans);
            for (const Span& s : spans)
                for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                    for (std::size_t k = 0; k < C; ++k)
                        late.push_back({((s.y == 0 ? 0 : H - 1) * W + std::size_t(i >> 2)) * C + k, 2.0 * p.planes[f * C + k].at(rows, i, s.y)});
        }
    }
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if ((q.x == 0 || q.x == mx) && (q.y == 0 || q.y == my))
            for (std::size_t c = 0; c < C; ++c)
                late.push_back({((q.y == 0 ? 0 : H - 1) * W + (q.x == 0 ? 0 : W - 1)) * C + c, 4.0 * p.vertex_value(m, std::uint32_t(v), c)});
    }
    fix_discontinuities(m, p, Lattice::supersample(), [&](std::int32_t i, std::int32_t j, int c, double mean, double owner) {
        late.push_back({(std::size_t(j >> 2) * W + std::size_t(i >> 2)) * C + std::size_t(c), mean - owner});
    });
    return late;
}

// Pixel sums are doubles of about this many bytes per band of rows: the band stays in the L2
// cache while its faces are rasterised in any order.
constexpr std::size_t kBandBytes = std::size_t(256) << 10;

// Items 0..n-1 grouped by band, keeping their order within each band (a counting sort):
// bands(i, fn) calls fn(b) for each band b item i belongs to. Returns item lists per band in
// (*first)[b] .. (*first)[b + 1].
template <class Bands>
std::vector<std::uint32_t> group_by_band(std::size_t n, std::size_t nb, Bands bands, std::vector<std::uint32_t>* first) {
    first->assign(nb + 1, 0);
    for (std::size_t i = 0; i < n; ++i) bands(i, [&](std::size_t b) { ++(*first)[b + 1]; });
    for (std::size_t b = 0; b < nb; ++b) (*first)[b + 1] += (*first)[b];
    std::vector<std::uint32_t> items((*first)[nb]);
    std::vector<std::uint32_t> fill(first->begin(), first->end() - 1);
    for (std::size_t i = 0; i < n; ++i) bands(i, [&](std::size_t b) { items[fill[b]++] = std::uint32_t(i); });
    return items;
}

// Supersampling band by band. Each pixel's sum takes exactly the additions, in exactly the order,
// of a whole-image pass (faces in face order, then the late terms), so banding changes no bit.
// The sums of channel c are plane c of the band's buffer; a face is scanned once for all of them.
void supersampling(const Model& m, const Prepared& p, Image* out, ProgressHook progress, int threads) {
    const std::size_t W = std::size_t(m.width), H = std::size_t(m.height), C = std::size_t(m.channels);
    const std::size_t band = std::max<std::size_t>(1, kBandBytes / (W * C * sizeof(double)));
    const std::size_t nb = (H + band - 1) / band;
    const Lattice l = Lattice::supersample();
    // The bands of the sub-sample rows j (pixel row j / 4) a face can own: fine y = phase + step * j
    // within its extent.
    const auto face_bands = [&](std::size_t f, auto fn) {
        const auto& fc = m.faces[f];
        const std::int64_t ylo = std::min({m.vertices[fc[0]].y, m.vertices[fc[1]].y, m.vertices[fc[2]].y});
        const std::int64_t yhi = std::max({m.vertices[fc[0]].y, m.vertices[fc[1]].y, m.vertices[fc[2]].y});
        const std::int64_t j0 = (ylo * l.scale - l.phase_y + l.step_y - 1) / l.step_y;  // numerators >= 0
        const std::int64_t j1 = (yhi * l.scale - l.phase_y) / l.step_y;
        const std::size_t r0 = std::size_t(j0 >> 2), r1 = std::min(H - 1, std::size_t(j1 >> 2));
        for (std::size_t b = r0 / band; b <= r1 / band; ++b) fn(b);
    };
    std::vector<std::uint32_t> face_first, late_first;
    const std::vector<std::uint32_t> band_faces = group_by_band(m.faces.size(), nb, face_bands, &face_first);
    const std::vector<LateTerm> late = late_terms(m, p);
    const std::vector<std::uint32_t> band_late =
        group_by_band(late.size(), nb, [&](std::size_t i, auto fn) { fn((C == 1 ? late[i].sample : late[i].sample / C) / W / band); }, &late_first);
    const std::size_t plane = band * W;
    const double maxval = m.maxval;
    // Threads for 2^15 samples at least each (kernel/row_parallel.h), each with sums of its own:
    // a band is finished from its own faces and late terms, so the image is the same whichever
    // thread takes it. They take the next band as they get free, not runs of bands: a thread can
    // start milliseconds late on this 2-core machine (1.8-3.9 ms on lena 3%, where the bands
    // take 9.5 ms), and halves of the image differ (7,411 and 10,016 faces there).
    const RowParts parts(0, nb, threads, rows_for(std::size_t(1) << 15, band * W * C));
    std::atomic<std::size_t> next{0};
    run_parts(parts, [&](std::size_t part, std::size_t, std::size_t) {
        std::vector<double> acc(plane * C);
        for (std::size_t b = next.fetch_add(1); b < nb; b = next.fetch_add(1)) {
            // Progress from the calling thread's part alone (the hook need not be thread-safe).
            if (part == 0) progress("reconstruct", double(b) / double(nb));
            const std::size_t row0 = b * band, rows = std::min(H, row0 + band) - row0;
            for (std::uint32_t k = face_first[b]; k < face_first[b + 1]; ++k) {
                const std::uint32_t f = band_faces[k];
                const auto& fc = m.faces[f];
                // Channel 0's plane stands in for the channels a gray model lacks (never read).
                const FinePlane fp[3] = {FinePlane(p.planes[f * C]), FinePlane(p.planes[f * C + (C > 1 ? 1 : 0)]),
                                         FinePlane(p.planes[f * C + (C > 1 ? 2 : 0)])};
                // The band's sub-rows only: a face spanning several bands is walked in pieces.
                add_face(fp, C, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], p.dom, std::int32_t(4 * row0),
                         std::int32_t(4 * (row0 + rows) - 1), acc.data(), plane, W, row0);
            }
            for (std::uint32_t k = late_first[b]; k < late_first[b + 1]; ++k) {
                const LateTerm& t = late[band_late[k]];
                if (C == 1) acc[t.sample - row0 * W] += t.add;
                else acc[(t.sample % C) * plane + t.sample / C - row0 * W] += t.add;
            }
            std::uint16_t* dst = out->samples.data() + row0 * W * C;
            const auto finish = [&](std::size_t c, auto stride) {
                double* sums = acc.data() + c * plane;
                for (std::size_t i = 0; i < rows * W; ++i) {
                    dst[i * stride + c] = to_sample(sums[i] * (1.0 / 16.0), maxval);
                    sums[i] = 0.0;  // ready for the next band (no separate clearing pass)
                }
            };
            if (C == 1) finish(0, std::integral_constant<std::size_t, 1>());  // a plain, vectorisable loop
            else
                for (std::size_t c = 0; c < C; ++c) finish(c, C);
        }
    });
}

Status reconstruct_with(const Model& m, const ModelTopology* given, bool supersample, Image* out, ProgressHook progress,
                        int threads) {
    Prepared p;
    if (Status s = prepare(m, false, given, &p); !s) return s;
    // In *out's memory when it has the size already (a caller measuring models one after the
    // other): a fresh page costs more than zeroing it (DECISIONS "Memory").
    Image im;
    if (out->width == m.width && out->height == m.height && out->channels == m.channels) {
        im = std::move(*out);
        std::fill(im.samples.begin(), im.samples.end(), std::uint16_t(0));
        im.maxval = m.maxval;
    } else {
        im = Image(m.width, m.height, m.maxval, m.channels);
    }
    if (supersample) supersampling(m, p, &im, progress, threads);
    else point_evaluation(m, p, &im, progress, threads);
    // Per-edge kinds (edge_kinds.h): the pixels the exceptions govern as their kind says.
    if (m.kind == ModelKind::erd && !m.kind_exceptions.empty() && (exception_kind(m) == EdgeKind::soft) != supersample) {
        Image other(m.width, m.height, m.maxval, m.channels);
        if (supersample) point_evaluation(m, p, &other, {}, threads);
        else supersampling(m, p, &other, {}, threads);
        const std::vector<std::uint8_t> governed = exception_pixels(m);
        const std::size_t C = std::size_t(m.channels);
        for (std::size_t i = 0; i < governed.size(); ++i)
            if (governed[i])
                for (std::size_t c = 0; c < C; ++c) im.samples[i * C + c] = other.samples[i * C + c];
    }
    progress("reconstruct", 1.0);
    *out = std::move(im);
    return Status::success();
}

}  // namespace

Status check_triangulation(const Model& m) {
    Prepared p;
    return prepare(m, true, nullptr, &p);
}

Status reconstruct(const Model& m, const ModelTopology& topo, bool supersample, Image* out, ProgressHook progress,
                   int threads) {
    return reconstruct_with(m, &topo, supersample, out, progress, threads);
}

Status reconstruct(const Model& m, bool supersample, Image* out, ProgressHook progress, int threads) {
    return reconstruct_with(m, nullptr, supersample, out, progress, threads);
}

}  // namespace erd
