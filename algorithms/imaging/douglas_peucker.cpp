#include "algorithms/imaging/douglas_peucker.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace erd {

// Squared distance from p to the segment a-b (to a when a == b).
static double distance2(LatticePoint p, LatticePoint a, LatticePoint b) {
    const double abx = double(b.x) - a.x, aby = double(b.y) - a.y;
    const double apx = double(p.x) - a.x, apy = double(p.y) - a.y;
    const double len2 = abx * abx + aby * aby;
    double t = len2 > 0 ? (apx * abx + apy * aby) / len2 : 0.0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double ex = apx - t * abx, ey = apy - t * aby;
    return ex * ex + ey * ey;
}

namespace {

// Scratch of the stack and the keep flags, reused across the lines of one simplify_polylines call
// (one allocation per line, not three: the lines of a noisy image are many and short).
struct Scratch {
    std::vector<char> keep;
    std::vector<std::pair<std::size_t, std::size_t>> stack;
};

template <class Accept>
void simplify_into(const LatticePoint* line, std::size_t n, double epsilon, Accept accept, Scratch* sc, Polyline* out) {
    if (n <= 2) {
        out->assign(line, line + n);
        return;
    }
    const double eps2 = epsilon > 0 ? epsilon * epsilon : 0.0;
    std::vector<char>& keep = sc->keep;
    keep.assign(n, 0);
    keep[0] = keep[n - 1] = 1;
    std::size_t kept = 2;
    auto& stack = sc->stack;
    stack.assign(1, {0, n - 1});
    while (!stack.empty()) {
        const auto [first, last] = stack.back();
        stack.pop_back();
        double best = -1;
        std::size_t at = first;
        for (std::size_t i = first + 1; i < last; ++i) {
            const double d = distance2(line[i], line[first], line[last]);
            if (d > best) { best = d; at = i; }  // first farthest point wins ties
        }
        if (at == first || (!(best > eps2) && accept(first, last))) continue;
        keep[at] = 1;
        ++kept;
        stack.push_back({at, last});
        stack.push_back({first, at});
    }
    out->clear();
    out->reserve(kept);
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) out->push_back(line[i]);
}

}  // namespace

Polyline douglas_peucker(const Polyline& line, double epsilon) {
    Scratch sc;
    Polyline out;
    simplify_into(line.data(), line.size(), epsilon, [](std::size_t, std::size_t) { return true; }, &sc, &out);
    return out;
}

Polyline douglas_peucker(const Polyline& line, double epsilon, const PieceTest& accept) {
    Scratch sc;
    Polyline out;
    simplify_into(line.data(), line.size(), epsilon,
                  [&](std::size_t first, std::size_t last) { return !accept || accept(first, last); }, &sc, &out);
    return out;
}

PolylineList simplify_polylines(const PolylineList& lines, double epsilon, int min_points, LengthRule rule) {
    const std::size_t least = rule == LengthRule::before_simplification ? std::size_t(std::max(min_points, 0)) : 0;
    // Room for every line the length rule can keep and for all their points (a bound), so the list
    // is not copied as it grows (noise keeps a million lines at 2048^2); pages it never fills cost
    // nothing.
    std::size_t room = 0, points = 0;
    for (std::size_t k = 0; k < lines.size(); ++k)
        if (lines.size(k) >= least) {
            ++room;
            points += lines.size(k);
        }
    PolylineList out(lines.stride());
    out.reserve(points, room);
    Scratch sc;
    Polyline s, line;
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const std::size_t n = lines.size(k);
        if (n < least) continue;
        lines.line(k, &line);
        simplify_into(line.data(), n, epsilon, [](std::size_t, std::size_t) { return true; }, &sc, &s);
        if (rule == LengthRule::after_simplification && int(s.size()) < min_points) continue;
        out.add(s);
    }
    return out;
}

}  // namespace erd
