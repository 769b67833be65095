#include "algorithms/polylines.h"

#include <cstddef>

#include "algorithms/douglas_peucker.h"
#include "algorithms/set_points.h"

namespace erd {

std::vector<Polyline> trace_polylines(const Grid<std::uint8_t>& edges) {
    std::vector<Polyline> out;
    const int w = edges.width, h = edges.height;
    if (w <= 0 || h <= 0) return out;
    const int s = w + 2;
    // Zero-framed copy; `used` holds one bit per direction for links already part of a polyline.
    std::vector<std::uint8_t> b(std::size_t(s) * std::size_t(h + 2), 0), used(b.size(), 0), degree(b.size(), 0);
    const int dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};  // E, SE, S, SW, W, NW, N, NE
    const int dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    std::ptrdiff_t off[8];
    for (int d = 0; d < 8; ++d) off[d] = std::ptrdiff_t(dy[d]) * s + dx[d];
    auto index = [&](int x, int y) { return std::size_t(y + 1) * std::size_t(s) + std::size_t(x + 1); };
    auto point = [&](std::size_t i) {
        return LatticePoint{std::int32_t(int(i % std::size_t(s)) - 1), std::int32_t(int(i / std::size_t(s)) - 1)};
    };
    // The set points in row-major order, found by skipping zero bytes eight at a time.
    std::vector<std::size_t> pts;
    for_each_set(edges.data.data(), edges.data.size(), [&](std::size_t k) {
        const std::size_t i = index(int(k % std::size_t(w)), int(k / std::size_t(w)));
        b[i] = 1;
        pts.push_back(i);
    });
    // Links: 8-neighbour pairs, except a diagonal pair that is also joined through a common
    // 4-neighbour (the corner of a staircase or of a T): that link would make a triangle, and a
    // cluster of mutual "junctions" out of one junction.
    std::vector<std::uint8_t> links(b.size(), 0);
    for (const std::size_t i : pts) {
        unsigned mask = 0;
        for (int d = 0; d < 8; ++d) {
            if (!b[std::size_t(std::ptrdiff_t(i) + off[d])]) continue;
            if ((d & 1) && (b[std::size_t(std::ptrdiff_t(i) + off[(d + 7) & 7])] ||
                            b[std::size_t(std::ptrdiff_t(i) + off[(d + 1) & 7])]))
                continue;
            mask |= 1u << d;
        }
        links[i] = std::uint8_t(mask);
        int n = 0;
        for (; mask; mask &= mask - 1) ++n;
        degree[i] = std::uint8_t(n);
    }
    auto use = [&](std::size_t i, int d) {
        used[i] |= std::uint8_t(1u << d);
        used[std::size_t(std::ptrdiff_t(i) + off[d])] |= std::uint8_t(1u << ((d + 4) & 7));
    };
    auto free_link = [&](std::size_t i) {
        for (int d = 0; d < 8; ++d)
            if ((links[i] & ~used[i]) & (1u << d)) return d;
        return -1;
    };
    // Follows links from `start` through points of degree 2 until a node (degree != 2), a point with
    // no free link left, or the start again.
    auto run = [&](std::size_t start, int d) {
        Polyline line{point(start)};
        std::size_t cur = start;
        for (;;) {
            use(cur, d);
            cur = std::size_t(std::ptrdiff_t(cur) + off[d]);
            line.push_back(point(cur));
            if (cur == start || degree[cur] != 2) break;
            d = free_link(cur);
            if (d < 0) break;
        }
        out.push_back(std::move(line));
    };

    for (const std::size_t i : pts) {
        if (degree[i] == 2) continue;
        if (degree[i] == 0) { out.push_back(Polyline{point(i)}); continue; }
        for (int d; (d = free_link(i)) >= 0;) run(i, d);
    }
    // What is left are closed curves made of degree-2 points only.
    for (const std::size_t i : pts)
        for (int d; (d = free_link(i)) >= 0;) run(i, d);
    return out;
}

Status edge_polylines(const Image& im, const EdgePolylineParams& params, Grid<std::uint8_t>* edges,
                      std::vector<Polyline>* polylines, CannyStats* stats) {
    if (params.epsilon < 0 || params.epsilon != params.epsilon)
        return Status::bad_input("polylines: epsilon must be >= 0");
    Status st = detect_edges(im, params.canny, edges, stats);
    if (!st) return st;
    *polylines = simplify_polylines(trace_polylines(*edges), params.epsilon, params.min_points);
    return Status::success();
}

}  // namespace erd
