#include "algorithms/imaging/polylines.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/imaging/point_rings.h"
#include "algorithms/imaging/set_points.h"

namespace erd {

namespace {

// The links of a ring (polyline tracing below), their count, and the lowest set bit of a byte
// (-1 for none), made once at compile time: tracing asks them once per point and link.
struct RingTables {
    std::uint8_t links[256] = {};
    std::uint8_t degree[256] = {};
    std::int8_t lowest[256] = {};

    constexpr RingTables() {
        for (unsigned ring = 0; ring < 256; ++ring) {
            unsigned mask = 0;
            for (unsigned d = 0; d < 8; ++d) {
                if (!(ring & (1u << d))) continue;
                if ((d & 1u) && (ring & ((1u << ((d + 7) & 7u)) | (1u << ((d + 1) & 7u))))) continue;
                mask |= 1u << d;
            }
            links[ring] = std::uint8_t(mask);
            std::uint8_t k = 0;
            for (unsigned m = mask; m; m &= m - 1) ++k;
            degree[ring] = k;
            std::int8_t low = -1;
            for (int d = 7; d >= 0; --d)
                if (ring & (1u << d)) low = std::int8_t(d);
            lowest[ring] = low;
        }
    }
};

constexpr RingTables kRingTables;

}  // namespace

PolylineList trace_polylines(const Grid<std::uint8_t>& edges) {
    const int w = edges.width, h = edges.height;
    if (w <= 0 || h <= 0) return {};
    // The set points (found by skipping zero bytes eight at a time) as a bit plane with a one-point
    // frame, the row below the last and a spare word (PointBits::adopt).
    const std::size_t stride = std::size_t(w) + 2;
    std::vector<std::uint64_t> bits((std::size_t(h) + 2) * stride / 64 + 2, 0);
    std::size_t n = 0;
    for_each_set(edges.data.data(), edges.data.size(), [&](std::size_t k) {
        const std::size_t q = (k / std::size_t(w) + 1) * stride + k % std::size_t(w) + 1;
        bits[q >> 6] |= std::uint64_t(1) << (q & 63u);
        ++n;
    });
    PointBits pts;
    pts.adopt(std::move(bits), std::ptrdiff_t(stride), n);
    return trace_polylines(pts);
}

PolylineList trace_polylines(const PointBits& pts) {
    PolylineList out(pts.stride());
    const std::size_t n = pts.size();
    // Links: 8-neighbour pairs, except a diagonal pair that is also joined through a common
    // 4-neighbour (the corner of a staircase or of a T): that link would make a triangle, and a
    // cluster of mutual "junctions" out of one junction. Directions E, SE, S, SW, W, NW, N, NE.
    // A point's links depend on its ring alone (one table lookup per point), and its degree on
    // its links (a link mask is its own ring's links).
    std::vector<std::uint8_t> links(n), used(n, 0);  // used: one bit per direction
    std::size_t link_ends = 0, node_ends = 0, isolated = 0;
    pts.for_each([&](std::uint32_t i, std::uint32_t p) {
        links[i] = kRingTables.links[pts.mask(p)];
        const std::size_t degree = kRingTables.degree[links[i]];
        link_ends += degree;
        if (degree != 2) node_ends += degree;
        isolated += degree == 0;
    });
    const auto degree = [&](std::uint32_t i) { return kRingTables.degree[links[i]]; };
    // Every link is used once and every line but the closed curves of degree-2 points runs from
    // a node to a node: room for all of those lines up front, and for a closed curve per 32 points
    // (noise: 14 in 92K lines), so the store is not copied as it grows.
    const std::size_t lines = node_ends / 2 + isolated + n / 32 + 1;
    out.reserve(link_ends / 2 + lines, lines);
    auto free_link = [&](std::uint32_t i) { return int(kRingTables.lowest[links[i] & ~used[i] & 0xFFu]); };
    // Follows links from point `start` at cell p through points of degree 2 until a node
    // (degree != 2), a point with no free link left, or the start again.
    auto run = [&](std::uint32_t start, std::uint32_t p, int d) {
        out.push(p);
        std::uint32_t cur = start;
        for (;;) {
            used[cur] |= std::uint8_t(1u << d);
            cur = pts.neighbour(p, cur, d);
            p = pts.step(p, d);
            used[cur] |= std::uint8_t(1u << ((d + 4) & 7));
            out.push(p);
            if (cur == start || degree(cur) != 2) break;
            d = free_link(cur);
            if (d < 0) break;
        }
        out.end_line();
    };

    pts.for_each([&](std::uint32_t i, std::uint32_t p) {
        if (degree(i) == 2) return;
        if (degree(i) == 0) {
            out.push(p);
            out.end_line();
            return;
        }
        for (int d; (d = free_link(i)) >= 0;) run(i, p, d);
    });
    // What is left are closed curves made of degree-2 points only.
    pts.for_each([&](std::uint32_t i, std::uint32_t p) {
        for (int d; (d = free_link(i)) >= 0;) run(i, p, d);
    });
    return out;
}

}  // namespace erd
