// Scan conversion with the exact ownership rule of kernel/raster.h.
//
// Per row the three edge tests become bounds on the column index: an edge with a.y > b.y (in a
// positive triangle that is an edge bounding the row from the left) gives i >= ceil(..), one with
// a.y < b.y gives i <= .., and a horizontal edge either keeps or empties the whole row. The only
// point whose tie rule differs within a row is the one on the right border x == max_x (sx = -1):
// the row rule never owns it, so it is tested on its own and appended when owned.
#include "kernel/raster.h"

#include <algorithm>
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

}  // namespace

std::int64_t scan_triangle(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                           std::vector<Span>* out) {
    out->clear();
    Setup s;
    if (!setup(l, d, a, b, c, &s)) return 0;
    const std::int64_t sx_step = l.step_x, sy_step = l.step_y;
    // Rows and columns of the bounding box, clipped to the closed domain.
    const std::int64_t j0 = ceil_div(std::max<std::int64_t>(s.ymin, 0) - l.phase_y, sy_step);
    const std::int64_t j1 = floor_div(std::min(s.ymax, s.my) - l.phase_y, sy_step);
    const std::int64_t i_lo = ceil_div(std::max<std::int64_t>(s.xmin, 0) - l.phase_x, sx_step);
    const std::int64_t i_hi = floor_div(std::min(s.xmax, s.mx) - l.phase_x, sx_step);
    // The right-border column, when it is a lattice column this triangle reaches.
    const bool border_col = s.xmax == s.mx && (s.mx - l.phase_x) % sx_step == 0;
    const std::int64_t i_border = border_col ? (s.mx - l.phase_x) / sx_step : 0;
    // Each sloped edge bounds the row by ceil(N(j) / D) with N linear in j: keep the quotient
    // and remainder and step them per row instead of dividing.
    struct Stepper {
        std::int64_t q = 0, r = 0, D = 1, dq = 0, dr = 0;  // N = q*D + r, 0 <= r < D
        void init(std::int64_t n0, std::int64_t den, std::int64_t dn) {
            D = den;
            q = floor_div(n0, D);
            r = n0 - q * D;
            dq = floor_div(dn, D);
            dr = dn - dq * D;
        }
        std::int64_t ceil() const { return q + (r != 0); }
        void step() {
            q += dq;
            r += dr;
            if (r >= D) {
                r -= D;
                ++q;
            }
        }
    };
    // Sloped edges bound the row from the left (A > 0, ties owned: sx*A > 0) or from the right
    // (A < 0, ties not owned). A horizontal edge (at most one) lies on the first or last row and
    // only matters there: K = 0 on it, ties by sy.
    Stepper left[2], right[2];
    int nl = 0, nr = 0;
    bool has_h = false;
    std::int64_t h_y = 0, h_b = 0;
    const std::int64_t y0 = l.fine_y(j0);
    for (const EdgeFn& e : s.e) {
        // E(x) = K + A*x with x = phase_x + step_x*i and K = B*(y - ay) - A*ax.
        const std::int64_t K0 = e.B * (y0 - e.ay) - e.A * e.ax, dK = e.B * sy_step;
        if (e.A > 0) left[nl++].init(-K0 - e.A * l.phase_x, e.A * sx_step, -dK);        // i >= ceil(..)
        else if (e.A < 0) right[nr++].init(K0 + e.A * l.phase_x, -e.A * sx_step, dK);  // i <= ceil(..) - 1
        else {
            has_h = true;
            h_y = e.ay;
            h_b = e.B;
        }
    }
    std::int64_t count = 0;
    for (std::int64_t j = j0; j <= j1; ++j) {
        const std::int64_t y = l.fine_y(j);
        std::int64_t lo = i_lo, hi = i_hi;
        for (int t = 0; t < nl; ++t) {
            lo = std::max(lo, left[t].ceil());
            left[t].step();
        }
        for (int t = 0; t < nr; ++t) {
            hi = std::min(hi, right[t].ceil() - 1);
            right[t].step();
        }
        const bool empty = has_h && y == h_y && !((y == s.my ? -h_b : h_b) > 0);
        if (empty) lo = hi + 1;
        // The row rule (sx = +1) never owns x == max_x; test it with sx = -1. If it is owned,
        // convexity puts every point between the row's span and it in the triangle too.
        if (border_col && owns_point(s, s.mx, y)) {
            if (lo > hi) lo = i_border;
            hi = i_border;
        }
        if (lo > hi) continue;
        out->push_back(Span{std::int32_t(j), std::int32_t(lo), std::int32_t(hi)});
        count += hi - lo + 1;
    }
    return count;
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
