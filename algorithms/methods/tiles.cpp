// Tiles (tiles.h): the grid, the border profiles' vertices, the budget split, side values.
#include "algorithms/methods/tiles.h"

#include <algorithm>
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

void pin_side_values(const Image& image, Model* m) {
    const std::int32_t mx = 2 * (image.width - 1), my = 2 * (image.height - 1);
    const std::size_t C = std::size_t(m->channels);
    auto sample = [&](LatticePoint p, std::size_t c) {
        const std::size_t i = (std::size_t(p.y / 2) * std::size_t(image.width) + std::size_t(p.x / 2)) * C + c;
        return image.real() ? image.reals[i] : double(image.samples[i]);
    };
    std::vector<std::uint8_t> side(m->vertices.size(), 0);
    for (std::size_t v = 0; v < m->vertices.size(); ++v) {
        const LatticePoint p = m->vertices[v];
        if (p.x % 2 == 0 && p.y % 2 == 0 && (p.x == 0 || p.y == 0 || p.x == mx || p.y == my)) {
            side[v] = 1;
            for (std::size_t c = 0; c < C; ++c) m->values[v * C + c] = sample(p, c);
        }
    }
    if (m->kind != ModelKind::erd) return;
    for (std::size_t f = 0; f < m->faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m->faces[f][std::size_t(k)];
            if (!side[v]) continue;
            for (std::size_t c = 0; c < C; ++c) m->corner_values[f * C + c][std::size_t(k)] = sample(m->vertices[v], c);
        }
}

}  // namespace erd
