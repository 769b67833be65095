// Tiles (tiles.h): the grid, the border profiles' vertices, the budget split, side values.
#include "algorithms/methods/tiles.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <queue>
#include <utility>

namespace erd {

TileGrid make_tile_grid(int w, int h, int t) {
    TileGrid g;
    g.width = w;
    g.height = h;
    g.tile = t;
    g.nx = std::max(1, (w - 1 + t - 1) / t);
    g.ny = std::max(1, (h - 1 + t - 1) / t);
    return g;
}

namespace {

// The largest abs error over a < k < b of the line from (a, z[a]) to (b, z[b]), and where (the first).
std::pair<double, int> worst(const std::vector<double>& z, int a, int b, bool rounded) {
    double best = 0.0;
    int at = -1;
    const double za = z[std::size_t(a)], dz = (z[std::size_t(b)] - za) / double(b - a);
    for (int k = a + 1; k < b; ++k) {
        double v = za + dz * double(k - a);
        if (rounded) v = std::floor(v + 0.5);
        const double e = std::fabs(v - z[std::size_t(k)]);
        if (e > best) best = e, at = k;
    }
    return {best, at};
}

struct Span {
    double error;
    int a, b, at;
};
struct Lower {
    bool operator()(const Span& x, const Span& y) const {
        if (x.error != y.error) return x.error < y.error;
        return x.at > y.at;  // equal errors: the smaller index first
    }
};

}  // namespace

std::vector<int> simplify_profile(const std::vector<double>& z, const ProfileRule& rule) {
    const int last = int(z.size()) - 1;
    std::vector<int> chosen = {0, last};
    std::priority_queue<Span, std::vector<Span>, Lower> heap;
    auto push = [&](int a, int b) {
        if (b - a < 2) return;
        const std::pair<double, int> w = worst(z, a, b, rule.rounded);
        if (w.second >= 0) heap.push({w.first, a, b, w.second});
    };
    push(0, last);
    std::size_t added = 0;
    while (!heap.empty() && added < rule.max_interior) {
        const Span s = heap.top();
        if (s.error <= 0.0 || (rule.max_error >= 0.0 && s.error <= rule.max_error)) break;
        heap.pop();
        chosen.push_back(s.at);
        ++added;
        push(s.a, s.at);
        push(s.at, s.b);
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

std::vector<std::int64_t> split_budget(std::int64_t total, const std::vector<double>& weights) {
    const std::size_t n = weights.size();
    std::vector<std::int64_t> part(n, 0);
    if (n == 0) return part;
    double sum = 0.0;
    for (double w : weights) sum += std::max(0.0, w);
    std::vector<double> share(n);
    for (std::size_t i = 0; i < n; ++i)
        share[i] = sum > 0.0 ? double(total) * std::max(0.0, weights[i]) / sum : double(total) / double(n);
    std::int64_t given = 0;
    for (std::size_t i = 0; i < n; ++i) given += part[i] = std::int64_t(std::floor(share[i]));
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return share[a] - double(part[a]) > share[b] - double(part[b]);
    });
    for (std::size_t k = 0; given < total; k = (k + 1) % n, ++given) ++part[order[k]];
    return part;
}

std::vector<int> profile_crossings(const std::vector<double>& z, const std::vector<double>& before,
                                   const std::vector<double>& after, double strong) {
    std::vector<int> out;
    const int last = int(z.size()) - 1;
    auto diff = [](const std::vector<double>& p, int k) { return p[std::size_t(k) + 1] - p[std::size_t(k)]; };
    auto goes_on = [&](const std::vector<double>& p, int k, double d) {
        for (int m = std::max(0, k - kCrossingShift); m <= std::min(last - 1, k + kCrossingShift); ++m) {
            const double e = diff(p, m);
            if ((e > 0) == (d > 0) && std::fabs(e) >= 0.5 * strong) return true;
        }
        return false;
    };
    for (int k = 1; k + 2 <= last; ++k) {
        const double d = diff(z, k), a = std::fabs(d);
        if (a >= strong && a > std::fabs(diff(z, k - 1)) && a > std::fabs(diff(z, k + 1)) && goes_on(before, k, d) && goes_on(after, k, d))
            out.push_back(k);
    }
    return out;
}

std::vector<Polyline> join_crossings(std::vector<Polyline> lines, const std::vector<LatticePoint>& crossings, int w, int h,
                                     std::size_t* joined) {
    *joined = 0;
    const std::int32_t mx = 2 * (w - 1), my = 2 * (h - 1);
    auto inner = [&](LatticePoint q) { return LatticePoint{q.x == 0 ? 2 : q.x == mx ? mx - 2 : q.x, q.y == 0 ? 2 : q.y == my ? my - 2 : q.y}; };
    struct Pair {
        std::int64_t d;
        std::size_t crossing, line;
        int end;  // 0: the first point, 1: the last
    };
    std::vector<Pair> pairs;
    for (std::size_t c = 0; c < crossings.size(); ++c)
        for (std::size_t l = 0; l < lines.size(); ++l) {
            const Polyline& pl = lines[l];
            if (pl.size() < 2 || (pl.front().x == pl.back().x && pl.front().y == pl.back().y)) continue;  // closed
            for (int e = 0; e < 2; ++e) {
                const LatticePoint p = e ? pl.back() : pl.front();
                const std::int64_t d = std::max(std::abs(std::int64_t(p.x) - crossings[c].x), std::abs(std::int64_t(p.y) - crossings[c].y));
                if (d <= kCrossingReach) pairs.push_back({d, c, l, e});
            }
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
    std::vector<std::uint8_t> crossing_done(crossings.size(), 0);
    std::vector<std::array<std::uint8_t, 2>> end_used(lines.size(), {0, 0});
    for (const Pair& p : pairs) {
        if (crossing_done[p.crossing] || end_used[p.line][std::size_t(p.end)]) continue;
        crossing_done[p.crossing] = 1;
        end_used[p.line][std::size_t(p.end)] = 1;
        Polyline& pl = lines[p.line];
        const LatticePoint in = inner(crossings[p.crossing]), at = p.end ? pl.back() : pl.front();
        if (at.x != in.x || at.y != in.y) {
            if (p.end) pl.push_back(in);
            else pl.insert(pl.begin(), in);
        }
        ++*joined;
    }
    // The stubs first: inserted before the detected pieces, no detected piece can cut them off.
    std::vector<Polyline> out;
    out.reserve(crossings.size() + lines.size());
    for (LatticePoint q : crossings) out.push_back({q, inner(q)});
    for (Polyline& pl : lines) out.push_back(std::move(pl));
    return out;
}

void pin_side_values(const Image& image, Model* m) {
    const std::int32_t mx = 2 * (image.width - 1), my = 2 * (image.height - 1);
    const std::size_t C = std::size_t(m->channels);
    auto sample = [&](LatticePoint p, std::size_t c) {
        const std::size_t i = (std::size_t(p.y / 2) * std::size_t(image.width) + std::size_t(p.x / 2)) * C + c;
        return image.real() ? image.reals[i] : double(image.samples[i]);
    };
    // side[v]: 1 a side pixel, 2 a crossing (between two side pixels).
    std::vector<std::uint8_t> side(m->vertices.size(), 0);
    for (std::size_t v = 0; v < m->vertices.size(); ++v) {
        const LatticePoint p = m->vertices[v];
        if (!(p.x == 0 || p.y == 0 || p.x == mx || p.y == my)) continue;
        if (p.x % 2 == 0 && p.y % 2 == 0) {
            side[v] = 1;
            for (std::size_t c = 0; c < C; ++c) m->values[v * C + c] = sample(p, c);
        } else {
            side[v] = 2;
            const LatticePoint a = {p.x - p.x % 2, p.y - p.y % 2}, b = {p.x + p.x % 2, p.y + p.y % 2};
            for (std::size_t c = 0; c < C; ++c) m->values[v * C + c] = 0.5 * (sample(a, c) + sample(b, c));
        }
    }
    if (m->kind != ModelKind::erd) return;
    // A crossing's constrained edges (none: the side's normal stands in for one).
    std::vector<std::vector<LatticePoint>> towards(m->vertices.size());
    for (const auto& e : m->constraints)
        for (int k = 0; k < 2; ++k)
            if (side[e[std::size_t(k)]] == 2) towards[e[std::size_t(k)]].push_back(m->vertices[e[std::size_t(1 - k)]]);
    auto cross = [](std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) { return ax * by - ay * bx; };
    for (std::size_t f = 0; f < m->faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m->faces[f][std::size_t(k)];
            if (!side[v]) continue;
            const LatticePoint p = m->vertices[v];
            if (side[v] == 1) {
                for (std::size_t c = 0; c < C; ++c) m->corner_values[f * C + c][std::size_t(k)] = sample(p, c);
                continue;
            }
            // Which wedge the face lies in: towards a (every constrained edge has the face on a's
            // side), towards b, or between two constrained edges (kept).
            const LatticePoint a = {p.x - p.x % 2, p.y - p.y % 2}, b = {p.x + p.x % 2, p.y + p.y % 2};
            const LatticePoint q = m->vertices[m->faces[f][std::size_t((k + 1) % 3)]], r = m->vertices[m->faces[f][std::size_t((k + 2) % 3)]];
            const std::int64_t dx = std::int64_t(q.x) + r.x - 2 * std::int64_t(p.x), dy = std::int64_t(q.y) + r.y - 2 * std::int64_t(p.y);
            std::vector<LatticePoint> ends = towards[v];
            if (ends.empty()) ends.push_back({p.x == 0 ? 2 : p.x == mx ? mx - 2 : p.x, p.y == 0 ? 2 : p.y == my ? my - 2 : p.y});
            int on_a = 0, on_b = 0;
            for (LatticePoint e : ends) {
                const std::int64_t ex = e.x - p.x, ey = e.y - p.y;
                const std::int64_t face = cross(ex, ey, dx, dy), side_a = cross(ex, ey, a.x - p.x, a.y - p.y);
                if ((face < 0) == (side_a < 0) && face != 0) ++on_a;
                else ++on_b;
            }
            const bool all_a = on_a == int(ends.size()), all_b = on_b == int(ends.size());
            if (!all_a && !all_b) continue;
            for (std::size_t c = 0; c < C; ++c) m->corner_values[f * C + c][std::size_t(k)] = sample(all_a ? a : b, c);
        }
}

}  // namespace erd
