// The edges section: the constrained edges as chains of lattice points.
//
// make_chains walks the constraint graph: from every vertex whose degree is not 2 (the ends and
// junctions of the polylines, in (y, x) order) along each unused edge until a vertex of degree
// other than 2, then around the cycles that remain. A polyline of the ERD model's step 1 becomes
// one chain (two at a junction), so a chain step costs what the polyline's direction change
// costs, not two vertex indices.
//
// Coding: the chain count; per chain its start relative to the previous chain's start (dy, dx),
// its step count - 1, and its steps (dx, dy), each component under the context of the sign of the
// same component in the chain's previous step.
#include <algorithm>
#include <array>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

bool before(LatticePoint a, LatticePoint b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

struct Models {
    UIntModel chains, steps;
    SIntModel start_x, start_y;
    std::array<SIntModel, 4> dx, dy;  // context: previous step's component <0, 0, >0, none
};

std::size_t sign_context(std::int64_t d) { return d < 0 ? 0 : d == 0 ? 1 : 2; }

}  // namespace

std::vector<Chain> make_chains(const std::vector<std::array<LatticePoint, 2>>& segments) {
    std::vector<LatticePoint> pts;
    for (const auto& s : segments) {
        pts.push_back(s[0]);
        pts.push_back(s[1]);
    }
    std::sort(pts.begin(), pts.end(), before);
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    const auto index = [&](LatticePoint p) {
        return std::uint32_t(std::lower_bound(pts.begin(), pts.end(), p, before) - pts.begin());
    };
    const std::size_t n = pts.size(), ne = segments.size();
    std::vector<std::array<std::uint32_t, 2>> ends(ne);
    std::vector<std::uint32_t> begin(n + 1, 0), adj(2 * ne);
    for (std::size_t e = 0; e < ne; ++e) {
        ends[e] = {index(segments[e][0]), index(segments[e][1])};
        ++begin[ends[e][0] + 1];
        ++begin[ends[e][1] + 1];
    }
    for (std::size_t v = 0; v < n; ++v) begin[v + 1] += begin[v];
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (std::size_t e = 0; e < ne; ++e) {
        adj[fill[ends[e][0]]++] = std::uint32_t(e);
        adj[fill[ends[e][1]]++] = std::uint32_t(e);
    }
    std::vector<bool> used(ne, false);
    const auto degree = [&](std::uint32_t v) { return begin[v + 1] - begin[v]; };
    const auto unused_edge = [&](std::uint32_t v) {
        for (std::uint32_t i = begin[v]; i < begin[v + 1]; ++i)
            if (!used[adj[i]]) return adj[i];
        return ~std::uint32_t(0);
    };
    std::vector<Chain> chains;
    const auto walk = [&](std::uint32_t v, std::uint32_t e) {
        Chain c{pts[v]};
        for (;;) {
            used[e] = true;
            v = ends[e][0] == v ? ends[e][1] : ends[e][0];
            c.push_back(pts[v]);
            if (degree(v) != 2) break;
            e = unused_edge(v);
            if (e == ~std::uint32_t(0)) break;
        }
        chains.push_back(std::move(c));
    };
    for (int pass = 0; pass < 2; ++pass)
        for (std::uint32_t v = 0; v < n; ++v) {
            if (pass == 0 && degree(v) == 2) continue;
            for (std::uint32_t e = unused_edge(v); e != ~std::uint32_t(0); e = unused_edge(v)) walk(v, e);
        }
    return chains;
}

std::string encode_chains(const std::vector<Chain>& chains) {
    RangeEncoder rc;
    Models m;
    m.chains.encode(rc, chains.size());
    LatticePoint prev{0, 0};
    for (const Chain& c : chains) {
        m.start_y.encode(rc, std::int64_t(c[0].y) - prev.y);
        m.start_x.encode(rc, std::int64_t(c[0].x) - prev.x);
        prev = c[0];
        m.steps.encode(rc, c.size() - 2);
        std::size_t cx = 3, cy = 3;
        for (std::size_t i = 1; i < c.size(); ++i) {
            const std::int64_t dx = std::int64_t(c[i].x) - c[i - 1].x, dy = std::int64_t(c[i].y) - c[i - 1].y;
            m.dx[cx].encode(rc, dx);
            m.dy[cy].encode(rc, dy);
            cx = sign_context(dx);
            cy = sign_context(dy);
        }
    }
    return rc.finish();
}

Status decode_chains(const unsigned char* data, std::size_t size, int width, int height, bool even,
                     std::uint64_t max_steps, int version, std::vector<Chain>* out) {
    out->clear();
    RangeDecoder rc(data, size, adaptation(version));
    Models m;
    const auto bad = [](const std::string& what) { return Status::bad_input("edges section: " + what); };
    const std::int64_t mx = 2 * std::int64_t(width) - 2, my = 2 * std::int64_t(height) - 2;
    const auto inside = [&](std::int64_t x, std::int64_t y) {
        return x >= 0 && y >= 0 && x <= mx && y <= my && (!even || (x % 2 == 0 && y % 2 == 0));
    };
    std::uint64_t count = 0, total = 0;
    if (!m.chains.decode(rc, &count) || count > max_steps) return bad("bad chain count");
    std::int64_t px = 0, py = 0;
    for (std::uint64_t k = 0; k < count && rc.good(); ++k) {
        std::int64_t dy = 0, dx = 0;
        std::uint64_t steps = 0;
        if (!m.start_y.decode(rc, &dy) || !m.start_x.decode(rc, &dx)) return bad("bad chain start");
        px += dx;
        py += dy;
        if (!inside(px, py)) return bad("chain " + std::to_string(k) + " starts outside the image");
        if (!m.steps.decode(rc, &steps) || steps + 1 > max_steps - total) return bad("too many chain steps");
        total += steps + 1;
        Chain c{LatticePoint{std::int32_t(px), std::int32_t(py)}};
        std::int64_t x = px, y = py;
        std::size_t cx = 3, cy = 3;
        for (std::uint64_t i = 0; i <= steps && rc.good(); ++i) {
            if (!m.dx[cx].decode(rc, &dx) || !m.dy[cy].decode(rc, &dy)) return bad("bad chain step");
            if (dx == 0 && dy == 0) return bad("chain " + std::to_string(k) + " has a step of zero");
            x += dx;
            y += dy;
            if (!inside(x, y)) return bad("chain " + std::to_string(k) + " leaves the image");
            c.push_back(LatticePoint{std::int32_t(x), std::int32_t(y)});
            cx = sign_context(dx);
            cy = sign_context(dy);
        }
        out->push_back(std::move(c));
    }
    const std::string why = rc.finish();
    if (!why.empty()) return bad(why == "ends early" ? "ends early" : why);
    return Status::success();
}

}  // namespace erd::codec
