#include "algorithms/imaging/edge_kind.h"

#include <algorithm>
#include <cstdlib>

#include "algorithms/imaging/douglas_peucker.h"

namespace erd {

namespace {

// One line of samples (a row or a column) as the measure reads it.
template <class At>
void measure_line(int n, At at, int strong, EdgeKindStats* s) {
    for (int i = 1; i + 2 < n; ++i) {
        const int d = at(i + 1) - at(i), ad = std::abs(d);
        if (ad < strong) continue;
        const int f1 = at(i) - at(i - 1), f2 = at(i + 2) - at(i + 1);
        if (!(ad > std::abs(f1) && ad > std::abs(f2))) continue;
        const double lim = kFlankRatio * double(ad);
        const auto same = [&](int f) { return (f > 0) == (d > 0) && f != 0 && double(std::abs(f)) > lim; };
        const auto opposite = [&](int f) { return (f > 0) != (d > 0) && f != 0 && double(std::abs(f)) > lim; };
        if (same(f1) || same(f2)) ++s->soft;
        else if (!opposite(f1) && !opposite(f2)) ++s->hard;
    }
}

std::int64_t orient(LatticePoint a, LatticePoint b, LatticePoint c) {
    return (std::int64_t(b.x) - a.x) * (std::int64_t(c.y) - a.y) - (std::int64_t(c.x) - a.x) * (std::int64_t(b.y) - a.y);
}
int sign(std::int64_t v) { return (v > 0) - (v < 0); }

}  // namespace

EdgeKindStats measure_edge_kind(const Image& im) {
    EdgeKindStats s;
    const int strong = std::max(1, int(kStrongStep * double(im.maxval) + 0.5));
    for (int y = 0; y < im.height; ++y) measure_line(im.width, [&](int x) { return int(im.at(x, y)); }, strong, &s);
    for (int x = 0; x < im.width; ++x) measure_line(im.height, [&](int y) { return int(im.at(x, y)); }, strong, &s);
    return s;
}

Grid<std::uint8_t> crack_edges(const Image& im, double beta, double r) {
    const int W = im.width, H = im.height, GW = 2 * W - 1, GH = 2 * H - 1;
    // The step at each crack, read from the samples (no plane of steps): 4 bytes per pixel for
    // the map, a 64 Ki histogram for the quantile.
    const auto step = [&](int X, int Y) {  // (X, Y) a crack midpoint: X + Y odd
        const int x = X / 2, y = Y / 2;
        return X % 2 ? std::abs(int(im.at(x + 1, y)) - int(im.at(x, y))) : std::abs(int(im.at(x, y + 1)) - int(im.at(x, y)));
    };
    Grid<std::uint8_t> map(GW, GH, 0);
    std::vector<std::size_t> hist(65536, 0);
    std::size_t cracks = 0;
    for (int Y = 0; Y < GH; ++Y)
        for (int X = 1 - Y % 2; X < GW; X += 2) ++hist[std::size_t(step(X, Y))], ++cracks;
    if (cracks == 0) return map;
    const std::size_t k = std::min(cracks, std::max<std::size_t>(1, std::size_t(beta * double(cracks) + 0.5)));
    std::size_t above = 0;
    int q = 65535;
    for (; q > 0 && above + hist[std::size_t(q)] < k; --q) above += hist[std::size_t(q)];
    const double high = std::max(double(q), 0.5 * kStrongStep * double(im.maxval));  // q: the k-th largest step
    const double low = std::max(1.0, r * high);
    // Hysteresis over cracks that share a pixel corner.
    std::vector<std::pair<int, int>> stack;
    for (int Y = 0; Y < GH; ++Y)
        for (int X = 1 - Y % 2; X < GW; X += 2)
            if (double(step(X, Y)) >= high) {
                map(X, Y) = 1;
                stack.push_back({X, Y});
            }
    const auto corner_cracks = [&](int X, int Y, std::pair<int, int> out[4]) {
        out[0] = {X, Y - 1}, out[1] = {X, Y + 1}, out[2] = {X - 1, Y}, out[3] = {X + 1, Y};
    };
    while (!stack.empty()) {
        const auto [X, Y] = stack.back();
        stack.pop_back();
        std::pair<int, int> corners[2];
        if (X % 2) corners[0] = {X, Y - 1}, corners[1] = {X, Y + 1};
        else corners[0] = {X - 1, Y}, corners[1] = {X + 1, Y};
        for (const auto& [cx, cy] : corners) {
            if (!map.inside(cx, cy)) continue;
            std::pair<int, int> cr[4];
            corner_cracks(cx, cy, cr);
            for (const auto& [qx, qy] : cr)
                if (map.inside(qx, qy) && !map(qx, qy) && double(step(qx, qy)) >= low) {
                    map(qx, qy) = 1;
                    stack.push_back({qx, qy});
                }
        }
    }
    for (int Y = 1; Y < GH; Y += 2)
        for (int X = 1; X < GW; X += 2) {
            std::pair<int, int> cr[4];
            corner_cracks(X, Y, cr);
            int set = 0;
            for (const auto& [qx, qy] : cr) set += map.inside(qx, qy) && map(qx, qy);
            if (set >= 2) map(X, Y) = 1;
        }
    return map;
}

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

std::vector<Polyline> simplify_crack_polylines(const std::vector<Polyline>& lines, double epsilon, int min_points) {
    std::vector<Polyline> out;
    for (const Polyline& l : lines)
        if (l.size() >= std::size_t(std::max(min_points, 0))) out.push_back(simplify_cracks(l, epsilon));
    return out;
}

}  // namespace erd
