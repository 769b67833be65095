#include "algorithms/imaging/douglas_peucker.h"

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

Polyline douglas_peucker(const Polyline& line, double epsilon) { return douglas_peucker(line, epsilon, PieceTest()); }

Polyline douglas_peucker(const Polyline& line, double epsilon, const PieceTest& accept) {
    const std::size_t n = line.size();
    if (n <= 2) return line;
    const double eps2 = epsilon > 0 ? epsilon * epsilon : 0.0;
    std::vector<char> keep(n, 0);
    keep[0] = keep[n - 1] = 1;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, n - 1}};
    while (!stack.empty()) {
        const auto [first, last] = stack.back();
        stack.pop_back();
        double best = -1;
        std::size_t at = first;
        for (std::size_t i = first + 1; i < last; ++i) {
            const double d = distance2(line[i], line[first], line[last]);
            if (d > best) { best = d; at = i; }  // first farthest point wins ties
        }
        if (at == first || (!(best > eps2) && (!accept || accept(first, last)))) continue;
        keep[at] = 1;
        stack.push_back({at, last});
        stack.push_back({first, at});
    }
    Polyline out;
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) out.push_back(line[i]);
    return out;
}

std::vector<Polyline> simplify_polylines(const std::vector<Polyline>& lines, double epsilon, int min_points,
                                         LengthRule rule) {
    std::vector<Polyline> out;
    for (const Polyline& line : lines) {
        if (rule == LengthRule::before_simplification && int(line.size()) < min_points) continue;
        Polyline s = douglas_peucker(line, epsilon);
        if (rule == LengthRule::after_simplification && int(s.size()) < min_points) continue;
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace erd
