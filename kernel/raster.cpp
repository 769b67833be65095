// Scan conversion with the exact ownership rule of kernel/raster.h.
//
// Per row the three edge tests become bounds on the column index: an edge with a.y > b.y (in a
// positive triangle that is an edge bounding the row from the left) gives i >= ceil(..), one with
// a.y < b.y gives i <= .., and a horizontal edge either keeps or empties the whole row. The only
// point whose tie rule differs within a row is the one on the right border x == max_x (sx = -1):
// the row rule never owns it, so it is tested on its own and appended when owned.
#include "kernel/raster.h"

#include <algorithm>
#include <climits>
#include <utility>

#include "kernel/predicates.h"

namespace erd {
namespace {

// floor(a / b) and ceil(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && (a < 0)) --q;
    return q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && (a > 0)) ++q;
    return q;
}

// Edge a->b in fine coordinates: E(x, y) = B*(y - ay) + A*(x - ax), A = ay - by, B = bx - ax.
struct EdgeFn {
    std::int64_t ax, ay, A, B;
};

struct Setup {
    EdgeFn e[3];
    std::int64_t xmin, xmax, ymin, ymax;  // fine bounding box
    std::int64_t mx, my;                  // fine domain maxima
};

// Returns false for a degenerate triangle.
bool setup(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c, Setup* s) {
    if (l.scale < 1 || l.step_x < 1 || l.step_y < 1) return false;
    const std::int64_t o = orient2d(a, b, c);
    if (o == 0) return false;
    if (o < 0) std::swap(b, c);
    const std::int64_t k = l.scale;
    const std::int64_t px[3] = {a.x * k, b.x * k, c.x * k};
    const std::int64_t py[3] = {a.y * k, b.y * k, c.y * k};
    for (int t = 0; t < 3; ++t) {
        const int u = (t + 1) % 3;
        s->e[t] = EdgeFn{px[t], py[t], py[t] - py[u], px[u] - px[t]};
    }
    s->xmin = std::min({px[0], px[1], px[2]});
    s->xmax = std::max({px[0], px[1], px[2]});
    s->ymin = std::min({py[0], py[1], py[2]});
    s->ymax = std::max({py[0], py[1], py[2]});
    s->mx = std::int64_t(d.max_x) * k;
    s->my = std::int64_t(d.max_y) * k;
    return true;
}

// The ownership test of one point (fine coordinates) with explicit perturbation signs.
bool owns_point(const Setup& s, std::int64_t x, std::int64_t y) {
    if (x < 0 || y < 0 || x > s.mx || y > s.my) return false;
    const int sx = x == s.mx ? -1 : 1;
    const int sy = y == s.my ? -1 : 1;
    for (const EdgeFn& e : s.e) {
        const std::int64_t E = e.B * (y - e.ay) + e.A * (x - e.ax);
        if (E > 0) continue;
        if (E < 0) return false;
        if (e.A != 0) {
            if (sx * e.A > 0) continue;
            return false;
        }
        if (sy * e.B > 0) continue;
        return false;
    }
    return true;
}

// A sloped edge's bound on the column index of lattice row j is ceil(n0 / den), and n0 grows by
// dn per row. The edge bounds the row from the left (A > 0: i >= ceil(..), ties owned since
// sx*A > 0) or from the right (A < 0: i <= ceil(..) - 1, ties not owned). With E(x) = K + A*x,
// x = phase_x + step_x*i, K = B*(y - ay) - A*ax.
struct EdgeLine {
    std::int64_t n0, den, dn;
};

EdgeLine edge_line(const Lattice& l, const EdgeFn& e, std::int64_t j) {
    const std::int64_t K0 = e.B * (l.fine_y(j) - e.ay) - e.A * e.ax, dK = e.B * l.step_y;
    if (e.A > 0) return {-K0 - e.A * l.phase_x, e.A * l.step_x, -dK};
    return {K0 + e.A * l.phase_x, -e.A * l.step_x, dK};
}

// The bound kept as quotient and remainder and stepped per row instead of dividing.
// Branch-free: the carry is as likely as not, so a branch on it would be mispredicted half the
// time.
struct Stepper {
    std::int64_t q, r, D, dq, dr;  // n = q*D + r, 0 <= r < D
    explicit Stepper(const EdgeLine& e)
        : q(floor_div(e.n0, e.den)), r(e.n0 - q * e.den), D(e.den), dq(floor_div(e.dn, e.den)),
          dr(e.dn - dq * e.den) {}
    std::int64_t ceil() const { return q + (r != 0); }
    void step() {
        r += dr;
        const std::int64_t carry = r >= D;
        q += dq + carry;
        r -= D & -carry;
    }
};

// The row context shared by the row loops of scan_triangle.
struct Rows {
    const Setup& s;
    const Lattice& l;
    std::int64_t i_lo, i_hi;  // the bounding box's columns, clipped to the domain
    bool border_col;          // the right border x == max_x is a lattice column the triangle reaches
    std::int64_t i_border;
    std::vector<Span>* out;
    std::int64_t count = 0;

    // Appends row j's span lo..hi (clipped to the box), with the right-border point added when
    // owned: the row rule (sx = +1) never owns x == max_x, so it is tested with sx = -1; if it is
    // owned, convexity puts every point between the row's span and it in the triangle too.
    void emit(std::int64_t j, std::int64_t lo, std::int64_t hi) {
        lo = std::max(lo, i_lo);
        hi = std::min(hi, i_hi);
        if (border_col && owns_point(s, s.mx, l.fine_y(j))) {
            if (lo > hi) lo = i_border;
            hi = i_border;
        }
        if (lo > hi) return;
        out->push_back(Span{std::int32_t(j), std::int32_t(lo), std::int32_t(hi)});
        count += hi - lo + 1;
    }

    // Rows ja..jb between two sloped edges, `left` (A > 0) and `right` (A < 0), where the third
    // edge cannot matter (see scan_triangle).
    void between(std::int64_t ja, std::int64_t jb, const EdgeFn& left, const EdgeFn& right) {
        if (ja > jb) return;
        Stepper a(edge_line(l, left, ja)), b(edge_line(l, right, ja));
        if (border_col) {
            for (std::int64_t j = ja; j <= jb; ++j, a.step(), b.step()) emit(j, a.ceil(), b.ceil() - 1);
            return;
        }
        // Without the border column (nearly every face) the loop is kept tight: no border test,
        // the count summed in a local (scan_triangle reserved a span per row, so push_back never
        // reallocates).
        std::int64_t n = 0;
        const std::int64_t clip_lo = i_lo, clip_hi = i_hi;
        for (std::int64_t j = ja; j <= jb; ++j) {
            const std::int64_t lo = std::max(a.ceil(), clip_lo), hi = std::min(b.ceil() - 1, clip_hi);
            a.step();
            b.step();
            if (lo > hi) continue;
            out->push_back(Span{std::int32_t(j), std::int32_t(lo), std::int32_t(hi)});
            n += hi - lo + 1;
        }
        count += n;
    }

    // Row j with all three edges tested (the middle vertex's row): a horizontal edge lies on such
    // a row and is K = 0 along it, ties by sy.
    void all_edges(std::int64_t j) {
        std::int64_t lo = i_lo, hi = i_hi;
        const std::int64_t y = l.fine_y(j);
        for (const EdgeFn& e : s.e) {
            if (e.A == 0) {
                if (y == e.ay && !((y == s.my ? -e.B : e.B) > 0)) hi = lo - 1;
                continue;
            }
            const EdgeLine line = edge_line(l, e, j);
            const std::int64_t bound = ceil_div(line.n0, line.den);
            if (e.A > 0) lo = std::max(lo, bound);
            else hi = std::min(hi, bound - 1);
        }
        emit(j, lo, hi);
    }
};

}  // namespace

// Rows are split at the middle vertex M (by y) of top vertex T and bottom vertex Bt. A row strictly
// between T and M meets only edges TM and T-Bt: every point between them lies in the closed
// triangle and off segment M-Bt, so strictly inside that edge's half-plane, and its test holds.
// Likewise below M with M-Bt and T-Bt. Of the two edges at T (or at Bt) the one leaving the vertex
// downwards bounds from the right, the one arriving from the left. M's own row, where ties and a
// horizontal edge can matter, tests all three edges.
std::int64_t scan_triangle(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                           std::vector<Span>* out) {
    return scan_triangle(l, d, a, b, c, out, INT32_MIN, INT32_MAX);
}

std::int64_t scan_triangle(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                           std::vector<Span>* out, std::int32_t j_begin, std::int32_t j_end) {
    out->clear();
    Setup s;
    if (!setup(l, d, a, b, c, &s)) return 0;
    // Rows and columns of the bounding box, clipped to the closed domain (and rows to the window:
    // the row loops below start their steppers at their first row, so nothing else changes).
    const std::int64_t j0 =
        std::max<std::int64_t>(j_begin, ceil_div(std::max<std::int64_t>(s.ymin, 0) - l.phase_y, l.step_y));
    const std::int64_t j1 = std::min<std::int64_t>(j_end, floor_div(std::min(s.ymax, s.my) - l.phase_y, l.step_y));
    if (j0 > j1) return 0;
    out->reserve(std::size_t(j1 - j0 + 1));
    const bool border_col = s.xmax == s.mx && (s.mx - l.phase_x) % l.step_x == 0;
    Rows rows{s,
              l,
              ceil_div(std::max<std::int64_t>(s.xmin, 0) - l.phase_x, l.step_x),
              floor_div(std::min(s.xmax, s.mx) - l.phase_x, l.step_x),
              border_col,
              border_col ? (s.mx - l.phase_x) / l.step_x : 0,
              out};
    // Edge t runs from vertex t to vertex t+1. T: a vertex of least y; Bt: of largest y (another one).
    int t = 0, bt = 0;
    for (int k = 1; k < 3; ++k) {
        if (s.e[k].ay < s.e[t].ay) t = k;
        if (s.e[k].ay > s.e[bt].ay) bt = k;
    }
    if (bt == t) bt = (t + 1) % 3;  // cannot happen: a triangle is not flat
    const int m = 3 - t - bt;
    const std::int64_t ym = s.e[m].ay;
    // Row index ranges strictly above and strictly below M's fine y, and M's row if on the lattice.
    const std::int64_t above = std::min(j1, ceil_div(ym - l.phase_y, l.step_y) - 1);
    const std::int64_t below = std::max(j0, floor_div(ym - l.phase_y, l.step_y) + 1);
    // Edges at T: t (leaves T: right bound) and (t+2)%3 (arrives at T: left bound); at Bt: bt
    // (leaves Bt upwards: left bound) and (bt+2)%3 (arrives: right bound).
    rows.between(j0, above, s.e[(t + 2) % 3], s.e[t]);
    for (std::int64_t j = std::max(above + 1, j0); j < below && j <= j1; ++j) rows.all_edges(j);
    rows.between(below, j1, s.e[bt], s.e[(bt + 2) % 3]);
    return rows.count;
}

bool triangle_owns(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c, std::int32_t i,
                   std::int32_t j) {
    Setup s;
    if (!setup(l, d, a, b, c, &s)) return false;
    return owns_point(s, l.fine_x(i), l.fine_y(j));
}

bool SpanPlane::set(LatticePoint p0, double z0v, LatticePoint p1, double z1v, LatticePoint p2, double z2v) {
    x0 = p0.x;
    y0 = p0.y;
    z0 = z0v;
    gx = gy = 0.0;
    const std::int64_t D = orient2d(p0, p1, p2);
    if (D == 0) return false;
    const double dx1 = double(p1.x) - x0, dy1 = double(p1.y) - y0;
    const double dx2 = double(p2.x) - x0, dy2 = double(p2.y) - y0;
    const double dz1 = z1v - z0v, dz2 = z2v - z0v;
    const double inv = 1.0 / double(D);
    gx = (dz1 * dy2 - dz2 * dy1) * inv;
    gy = (dz2 * dx1 - dz1 * dx2) * inv;
    return true;
}

}  // namespace erd
