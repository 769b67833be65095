// The row walk behind scan conversion (kernel/raster.h): OwnedRows hands out, one at a time, the
// rows of lattice points a triangle owns under the exact ownership rule, top to bottom. It lives
// in a header so that a caller's per-row work (greedy refinement's pixel loop) runs in the same
// loop as the walk instead of going through a stored list of spans; scan_triangle is this walk
// appending Span records.
//
// Per row the three edge tests become bounds on the column index: an edge with a.y > b.y (in a
// positive triangle that is an edge bounding the row from the left) gives i >= ceil(..), one with
// a.y < b.y gives i <= .., and a horizontal edge either keeps or empties the whole row. The only
// point whose tie rule differs within a row is the one on the right border x == max_x (sx = -1):
// the row rule never owns it, so it is tested on its own and appended when owned.
#pragma once
#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "kernel/predicates.h"
#include "kernel/raster.h"

namespace erd {
namespace raster_detail {

// floor(a / b) and ceil(a / b) for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && (a < 0)) --q;
    return q;
}
inline std::int64_t ceil_div(std::int64_t a, std::int64_t b) {
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
inline bool setup(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c, Setup* s) {
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
inline bool owns_point(const Setup& s, std::int64_t x, std::int64_t y) {
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

inline EdgeLine edge_line(const Lattice& l, const EdgeFn& e, std::int64_t j) {
    const std::int64_t K0 = e.B * (l.fine_y(j) - e.ay) - e.A * e.ax, dK = e.B * l.step_y;
    if (e.A > 0) return {-K0 - e.A * l.phase_x, e.A * l.step_x, -dK};
    return {K0 + e.A * l.phase_x, -e.A * l.step_x, dK};
}

// The bound ceil(n / D) kept with its excess s = ceil(n / D)*D - n in [0, D) and stepped per row
// instead of dividing: n += dn with dn = dq*D + dr (0 <= dr < D) takes s to s - dr - dq*D, so the
// bound grows by dq, plus one when s - dr borrows. Branch-free: the borrow is as likely as not,
// so a branch on it would be mispredicted half the time.
struct Stepper {
    std::int64_t c = 0, s = 0, D = 1, dq = 0, dr = 0;
    Stepper() = default;
    explicit Stepper(const EdgeLine& e)
        : c(ceil_div(e.n0, e.den)), s(c * e.den - e.n0), D(e.den), dq(floor_div(e.dn, e.den)),
          dr(e.dn - dq * e.den) {}
    std::int64_t ceil() const { return c; }
    void step() {
        s -= dr;
        const std::int64_t borrow = s < 0;
        c += dq + borrow;
        s += D & -borrow;
    }
};

// The right border x == max_x as a lattice column a triangle reaches: the row rule (sx = +1)
// never owns it, so it is tested with sx = -1; if it is owned, convexity puts every point between
// the row's span and it in the triangle too.
struct BorderColumn {
    const Setup* s = nullptr;
    std::int64_t i = 0;            // its column index
    std::int64_t y0 = 0, dy = 0;   // fine y of lattice row j: y0 + dy*j
};

}  // namespace raster_detail

// Consecutive rows j..j_end whose owned columns are bounded by the same two steppers (see
// OwnedRows): row j owns columns lo..hi from columns(), possibly none; step() moves to the next
// row. A small value type, so a caller's loop keeps it in registers.
struct RowRun {
    std::int64_t j = 0, j_end = -1;
    raster_detail::Stepper left, right;  // lo = left.ceil(), hi = right.ceil() - 1 before clipping
    std::int64_t i_lo = 0, i_hi = -1;    // the bounding box's columns, clipped to the domain
    const raster_detail::BorderColumn* border = nullptr;  // set when the triangle reaches it

    // The owned columns lo..hi of row j (none when lo > hi).
    void columns(std::int64_t* lo, std::int64_t* hi) const {
        *lo = std::max(left.ceil(), i_lo);
        *hi = std::min(right.ceil() - 1, i_hi);
        if (border && raster_detail::owns_point(*border->s, border->s->mx, border->y0 + border->dy * j)) {
            if (*lo > *hi) *lo = border->i;
            *hi = border->i;
        }
    }
    void step() {
        ++j;
        left.step();
        right.step();
    }
};

// The rows of lattice points that triangle (a, b, c) owns, in lattice rows [j_begin, j_end], top
// to bottom: the same rows and columns as scan_triangle's spans. Either orientation; a degenerate
// triangle owns nothing. Handed out as at most three RowRuns; a caller walks them as
//
//     for (RowRun part; rows.next(&part);)
//         for (RowRun run = part; run.j <= run.j_end; run.step()) { run.columns(&lo, &hi); ... }
//
// so that its per-row work sits in the same loop as the walk (no list of spans in between), and
// the run it steps is a local whose address never escapes, which lets it live in registers.
//
// Rows are split at the middle vertex M (by y) of top vertex T and bottom vertex Bt. A row
// strictly between T and M meets only edges TM and T-Bt: every point between them lies in the
// closed triangle and off segment M-Bt, so strictly inside that edge's half-plane, and its test
// holds. Likewise below M with M-Bt and T-Bt. Of the two edges at T (or at Bt) the one leaving the
// vertex downwards bounds from the right, the one arriving from the left. M's own row (when it is
// a lattice row), where ties and a horizontal edge can matter, tests all three edges; its run has
// constant steppers.
class OwnedRows {
public:
    [[gnu::always_inline]] OwnedRows(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                                     std::int32_t j_begin = INT32_MIN, std::int32_t j_end = INT32_MAX) {
        using namespace raster_detail;
        if (!setup(l, d, a, b, c, &s_)) return;
        // Rows and columns of the bounding box, clipped to the closed domain (and rows to the
        // window: each run starts its steppers at its first row, so nothing else changes).
        j0_ = std::max<std::int64_t>(j_begin, ceil_div(std::max<std::int64_t>(s_.ymin, 0) - l.phase_y, l.step_y));
        j1_ = std::min<std::int64_t>(j_end, floor_div(std::min(s_.ymax, s_.my) - l.phase_y, l.step_y));
        if (j0_ > j1_) return;
        lattice_ = l;
        i_lo_ = ceil_div(std::max<std::int64_t>(s_.xmin, 0) - l.phase_x, l.step_x);
        i_hi_ = floor_div(std::min(s_.xmax, s_.mx) - l.phase_x, l.step_x);
        if (s_.xmax == s_.mx && (s_.mx - l.phase_x) % l.step_x == 0)
            border_ = BorderColumn{&s_, (s_.mx - l.phase_x) / l.step_x, l.phase_y, l.step_y};
        // Edge t runs from vertex t to vertex t+1. T: a vertex of least y; Bt: of largest y.
        int t = 0, bt = 0;
        for (int k = 1; k < 3; ++k) {
            if (s_.e[k].ay < s_.e[t].ay) t = k;
            if (s_.e[k].ay > s_.e[bt].ay) bt = k;
        }
        if (bt == t) bt = (t + 1) % 3;  // cannot happen: a triangle is not flat
        const std::int64_t ym = s_.e[3 - t - bt].ay;
        // Row index ranges strictly above and strictly below M's fine y, and M's row if on the
        // lattice. Edges at T: t (leaves T: right bound) and (t+2)%3 (arrives at T: left bound);
        // at Bt: bt (leaves Bt upwards: left bound) and (bt+2)%3 (arrives: right bound).
        above_ = std::min(j1_, ceil_div(ym - l.phase_y, l.step_y) - 1);
        below_ = std::max(j0_, floor_div(ym - l.phase_y, l.step_y) + 1);
        upper_ = {(t + 2) % 3, t};
        lower_ = {bt, (bt + 2) % 3};
        part_ = 0;
    }

    // At most this many rows own points (the bounding box's rows in the window).
    std::size_t max_rows() const { return part_ == 3 ? 0 : std::size_t(j1_ - j0_ + 1); }

    // The next run of rows; false when there is none left. A run may hold rows that own nothing.
    [[gnu::always_inline]] bool next(RowRun* run) {
        using namespace raster_detail;
        for (; part_ < 3; ++part_) {
            std::int64_t first, last;
            if (part_ == 0) first = j0_, last = above_;
            else if (part_ == 1) first = std::max(above_ + 1, j0_), last = std::min(below_ - 1, j1_);
            else first = below_, last = j1_;
            if (first > last) continue;
            run->j = first;
            run->j_end = last;
            run->i_lo = i_lo_;
            run->i_hi = i_hi_;
            run->border = border_.s ? &border_ : nullptr;
            if (part_ == 1) {
                std::int64_t lo, hi;
                all_edges(first, &lo, &hi);
                run->left = Stepper(EdgeLine{lo, 1, 0});
                run->right = Stepper(EdgeLine{hi + 1, 1, 0});
            } else {
                const int* e = part_ == 0 ? upper_.data() : lower_.data();
                run->left = Stepper(edge_line(lattice_, s_.e[e[0]], first));
                run->right = Stepper(edge_line(lattice_, s_.e[e[1]], first));
            }
            ++part_;
            return true;
        }
        return false;
    }

private:
    // Row j with all three edges tested (the middle vertex's row): a horizontal edge lies on such
    // a row and is K = 0 along it, ties by sy.
    void all_edges(std::int64_t j, std::int64_t* lo, std::int64_t* hi) const {
        *lo = i_lo_;
        *hi = i_hi_;
        const std::int64_t y = lattice_.fine_y(j);
        for (const raster_detail::EdgeFn& e : s_.e) {
            if (e.A == 0) {
                if (y == e.ay && !((y == s_.my ? -e.B : e.B) > 0)) *hi = *lo - 1;
                continue;
            }
            const raster_detail::EdgeLine line = raster_detail::edge_line(lattice_, e, j);
            const std::int64_t bound = raster_detail::ceil_div(line.n0, line.den);
            if (e.A > 0) *lo = std::max(*lo, bound);
            else *hi = std::min(*hi, bound - 1);
        }
    }

    raster_detail::Setup s_;
    Lattice lattice_;
    std::int64_t i_lo_ = 0, i_hi_ = -1;  // the bounding box's columns, clipped to the domain
    raster_detail::BorderColumn border_;  // border_.s null: the triangle does not reach it
    std::int64_t j0_ = 0, j1_ = -1;      // the rows of the bounding box in the window
    std::int64_t above_ = 0, below_ = 0;  // last row above M, first row below M
    std::array<int, 2> upper_{}, lower_{};  // (left, right) edges of the rows above and below M
    int part_ = 3;                       // the next part: 0 above M, 1 M's row, 2 below M, 3 done
};

// The walk above with the caller's work per row: row(j, lo, hi) for each lattice row j in
// [j_begin, j_end] where the triangle owns points, columns lo..hi (never empty), top to bottom.
// A row function returning bool stops the walk by returning false, and for_each_owned_row then
// returns false (true when every row was visited). Always inlined, so the row's work sits in
// the walk's loop as if written there.
template <class Row>
[[gnu::always_inline]] inline bool for_each_owned_row(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b,
                                                      LatticePoint c, Row&& row, std::int32_t j_begin = INT32_MIN,
                                                      std::int32_t j_end = INT32_MAX) {
    OwnedRows rows(l, d, a, b, c, j_begin, j_end);
    for (RowRun part; rows.next(&part);) {
        for (RowRun run = part; run.j <= run.j_end; run.step()) {
            std::int64_t lo, hi;
            run.columns(&lo, &hi);
            if (lo > hi) continue;
            const std::int32_t j = std::int32_t(run.j);
            if constexpr (std::is_same_v<decltype(row(j, j, j)), bool>) {
                if (!row(j, std::int32_t(lo), std::int32_t(hi))) return false;
            } else {
                row(j, std::int32_t(lo), std::int32_t(hi));
            }
        }
    }
    return true;
}

}  // namespace erd
