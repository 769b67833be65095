#include "algorithms/imaging/edge_kind.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "algorithms/imaging/douglas_peucker.h"

namespace erd {

namespace {

// The step between samples i and i + 1 of a line (a row or a column), at(k) its samples, n of
// them, i in [1, n - 3]: counted when |d| >= strong (the caller's test) and d is the largest
// difference along the line there.
template <class At>
void measure_step(int n, int i, At at, EdgeKindStats* s) {
    const int d = at(i + 1) - at(i), ad = std::abs(d);
    const int f1 = at(i) - at(i - 1), f2 = at(i + 2) - at(i + 1);
    if (!(ad > std::abs(f1) && ad > std::abs(f2))) return;
    const double lim = kFlankRatio * double(ad);
    const auto same = [&](int f) { return (f > 0) == (d > 0) && f != 0 && double(std::abs(f)) > lim; };
    const auto opposite = [&](int f) { return (f > 0) != (d > 0) && f != 0 && double(std::abs(f)) > lim; };
    if (same(f1) || same(f2)) ++s->soft;
    else if (!opposite(f1) && !opposite(f2)) ++s->hard;
    ++s->steps;
    // Clean: flat ground either side of a transition of one difference, or of two (the step
    // and its larger same-sign flank).
    const auto flat = [&](int f, double transition) { return double(std::abs(f)) <= kFlatRatio * transition; };
    if (flat(f1, ad) && flat(f2, ad)) {
        ++s->clean;
    } else if (same(f1) || same(f2)) {
        const bool before = same(f1) && (!same(f2) || std::abs(f1) >= std::abs(f2));
        const int lo = before ? i - 1 : i, hi = before ? i + 1 : i + 2;  // the ramp at(lo) .. at(hi)
        if (lo >= 1 && hi + 1 < n) {
            const double total = std::abs(at(hi) - at(lo));
            if (flat(at(lo) - at(lo - 1), total) && flat(at(hi + 1) - at(hi), total)) ++s->clean;
        }
    }
}

// Calls fn(k) for each k in [0, n) with |b[k] - a[k]| >= strong, in increasing order, skipping
// blocks of eight below it with one test (a count, so that -O2 vectorises it: most of an image is
// below the strong step).
template <class Fn>
void for_each_strong(const std::uint16_t* a, const std::uint16_t* b, int n, int strong, Fn fn) {
    int k = 0;
    for (; k + 8 <= n; k += 8) {
        const std::uint16_t *pa = a + k, *pb = b + k;
        int c = 0;
        for (int j = 0; j < 8; ++j) c += std::abs(int(pb[j]) - int(pa[j])) >= strong;
        if (c)
            for (int j = 0; j < 8; ++j)
                if (std::abs(int(pb[j]) - int(pa[j])) >= strong) fn(k + j);
    }
    for (; k < n; ++k)
        if (std::abs(int(b[k]) - int(a[k])) >= strong) fn(k);
}

std::int64_t orient(LatticePoint a, LatticePoint b, LatticePoint c) {
    return (std::int64_t(b.x) - a.x) * (std::int64_t(c.y) - a.y) - (std::int64_t(c.x) - a.x) * (std::int64_t(b.y) - a.y);
}
int sign(std::int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

EdgeKindStats measure_edge_kind(const Image& im) {
    EdgeKindStats s;
    const int strong = std::max(1, int(kStrongStep * double(im.maxval) + 0.5));
    const int W = im.width, H = im.height;
    const std::uint16_t* const px = im.samples.data();
    // Steps along rows: pixel i to i + 1 of row y, i in [1, W - 3]. The counts are sums, so the
    // order steps are taken in is free.
    for (int y = 0; y < H && W > 3; ++y) {
        const std::uint16_t* r = px + std::size_t(y) * std::size_t(W);
        const auto at = [r](int x) { return int(r[x]); };
        for_each_strong(r + 1, r + 2, W - 3, strong, [&](int k) { measure_step(W, k + 1, at, &s); });
    }
    // Steps along columns: row j to j + 1, j in [1, H - 3], all columns of the two rows at once.
    for (int j = 1; j + 2 < H; ++j) {
        const std::uint16_t* r0 = px + std::size_t(j) * std::size_t(W);
        for_each_strong(r0, r0 + W, W, strong, [&](int c) {
            measure_step(H, j, [px, W, c](int y) { return int(px[std::size_t(y) * std::size_t(W) + std::size_t(c)]); }, &s);
        });
    }
    return s;
}

CrackDetector::CrackDetector(const Image& im) : im_(im), hist_(std::size_t(im.maxval) + 1, 0) {
    // Every crack's step, row by row: between horizontal neighbours, then to the row below.
    const std::size_t W = std::size_t(im.width), H = std::size_t(im.height);
    for (std::size_t y = 0; y < H; ++y) {
        const std::uint16_t* s = im.samples.data() + y * W;
        for (std::size_t x = 0; x + 1 < W; ++x) ++hist_[std::size_t(std::abs(int(s[x + 1]) - int(s[x])))];
        if (y + 1 < H)
            for (std::size_t x = 0; x < W; ++x) ++hist_[std::size_t(std::abs(int(s[x + W]) - int(s[x])))];
    }
    cracks_ = 2 * W * H - W - H;
}

Grid<std::uint8_t> CrackDetector::detect(double beta, double r) const {
    Grid<std::uint8_t> map;
    detect(beta, r, &map);
    return map;
}

void CrackDetector::detect(double beta, double r, Grid<std::uint8_t>* out) const {
    const int W = im_.width, H = im_.height, GW = 2 * W - 1, GH = 2 * H - 1;
    Grid<std::uint8_t>& map = *out;
    if (map.width == GW && map.height == GH) {
        std::fill(map.data.begin(), map.data.end(), std::uint8_t(0));
    } else {
        map = Grid<std::uint8_t>(GW, GH, 0);
    }
    if (cracks_ == 0) return;
    const std::size_t k = std::min(cracks_, std::max<std::size_t>(1, std::size_t(beta * double(cracks_) + 0.5)));
    std::size_t above = 0;
    int q = int(hist_.size()) - 1;  // no step is above maxval
    for (; q > 0 && above + hist_[std::size_t(q)] < k; --q) above += hist_[std::size_t(q)];
    const double high = std::max(double(q), 0.5 * kStrongStep * double(im_.maxval));  // q: the k-th largest step
    const double low = std::max(1.0, r * high);
    // A crack's step, (X, Y) its midpoint (X + Y odd): between pixels (X/2, Y/2) and the next one
    // right (X odd) or down (Y odd).
    const std::uint16_t* px = im_.samples.data();
    const auto step = [&](int X, int Y) {
        const std::size_t i = std::size_t(Y >> 1) * std::size_t(W) + std::size_t(X >> 1);
        return double(std::abs(int(px[i + ((X & 1) ? 1 : std::size_t(W))]) - int(px[i])));
    };
    const auto at = [&](int X, int Y) -> std::uint8_t& { return map.data[std::size_t(Y) * std::size_t(GW) + std::size_t(X)]; };
    // fn(cx, cy) for each end of crack (X, Y) inside the grid: pixel corners, both coordinates odd.
    const auto ends = [&](int X, int Y, auto fn) {
        for (int side = -1; side <= 1; side += 2) {
            const int cx = (X & 1) ? X : X + side, cy = (X & 1) ? Y + side : Y;
            if (cx >= 0 && cy >= 0 && cx < GW && cy < GH) fn(cx, cy);
        }
    };
    // Hysteresis over cracks that share a pixel corner, from the cracks at or above `high` (the
    // integer steps at or above its ceiling), found a pixel row at a time: the cracks to the
    // right (row Y = 2y, X odd), then those down (row Y = 2y + 1, X even). `marked` holds every
    // marked crack in the order marked, and is the search's queue.
    std::vector<std::pair<int, int>> marked;
    const int seed = int(std::ceil(high));
    for (int Y = 0; Y < GH; ++Y) {
        const std::uint16_t* a = px + std::size_t(Y >> 1) * std::size_t(W);
        const auto mark = [&](int X) {
            at(X, Y) = 1;
            marked.push_back({X, Y});
        };
        if (Y & 1) for_each_strong(a, a + W, W, seed, [&](int x) { mark(2 * x); });
        else for_each_strong(a, a + 1, W - 1, seed, [&](int x) { mark(2 * x + 1); });
    }
    const auto visit = [&](int X, int Y) {
        if (X < 0 || Y < 0 || X >= GW || Y >= GH || at(X, Y) || !(step(X, Y) >= low)) return;
        at(X, Y) = 1;
        marked.push_back({X, Y});
    };
    for (std::size_t n = 0; n < marked.size(); ++n) {
        const auto [X, Y] = marked[n];  // a copy: visit grows the queue
        ends(X, Y, [&](int cx, int cy) {
            visit(cx, cy - 1);
            visit(cx, cy + 1);
            visit(cx - 1, cy);
            visit(cx + 1, cy);
        });
    }
    // A pixel corner is on an edge where two or more of its four cracks are: such a corner is an
    // end of a marked crack, so only those ends are looked at (a corner's mark is no crack of
    // another corner's). An end inside the grid has all four cracks inside it (the grid's sides
    // are even rows and columns).
    for (const auto& [X, Y] : marked)
        ends(X, Y, [&](int cx, int cy) {
            if (!at(cx, cy) && at(cx, cy - 1) + at(cx, cy + 1) + at(cx - 1, cy) + at(cx + 1, cy) >= 2) at(cx, cy) = 1;
        });
}

Grid<std::uint8_t> crack_edges(const Image& im, double beta, double r) { return CrackDetector(im).detect(beta, r); }

Polyline simplify_cracks(const Polyline& line, double epsilon) {
    const std::size_t n = line.size();
    return douglas_peucker(line, epsilon, [&](std::size_t first, std::size_t last) {
        const LatticePoint a = line[first], b = line[last];
        if (a.x == b.x && a.y == b.y) return false;
        for (std::size_t k = first; k <= last; ++k) {
            const LatticePoint p = line[k];
            if ((p.x + p.y) % 2 == 0) continue;  // a pixel corner: no pixel pair of its own
            const LatticePoint pa = p.x % 2 ? LatticePoint{p.x - 1, p.y} : LatticePoint{p.x, p.y - 1};
            const LatticePoint pb = p.x % 2 ? LatticePoint{p.x + 1, p.y} : LatticePoint{p.x, p.y + 1};
            const LatticePoint prev = line[k > 0 ? k - 1 : k], next = line[k + 1 < n ? k + 1 : k];
            const int side = sign(orient(prev, next, pa));
            if (side == 0) continue;  // a one-point line
            if (sign(orient(a, b, pa)) != side || sign(orient(a, b, pb)) != -side) return false;
        }
        return true;
    });
}

PolylineList simplify_crack_polylines(const PolylineList& lines, double epsilon, int min_points) {
    PolylineList out(lines.stride());
    for (std::size_t k = 0; k < lines.size(); ++k)
        if (lines.size(k) >= std::size_t(std::max(min_points, 0))) out.add(simplify_cracks(lines[k], epsilon));
    return out;
}

}  // namespace erd
