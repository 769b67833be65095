#include "algorithms/imaging/valid_region.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <unordered_map>

namespace erd {

namespace {

std::uint64_t key_of(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

// Drops the points of a chain that lie on the segment between their neighbours (the outline is
// made of unit steps along 8 directions; a straight run needs only its ends). A closed chain
// (first == last) keeps a corner as its first point.
Polyline merge_collinear(const Polyline& in) {
    const auto straight = [](LatticePoint a, LatticePoint b, LatticePoint c) {
        const std::int64_t ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
        return ux * vy - uy * vx == 0 && ux * vx + uy * vy > 0;
    };
    const bool closed = in.size() > 3 && in.front() == in.back();
    Polyline pts(in.begin(), closed ? in.end() - 1 : in.end());
    if (closed) {
        // Start at a corner so that the loop's seam is not in the middle of a straight run.
        const std::size_t n = pts.size();
        std::size_t start = 0;
        while (start < n && straight(pts[(start + n - 1) % n], pts[start], pts[(start + 1) % n])) ++start;
        if (start == n) return in;  // cannot happen for a closed outline
        std::rotate(pts.begin(), pts.begin() + std::ptrdiff_t(start), pts.end());
        pts.push_back(pts.front());
    }
    Polyline out;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (i > 0 && i + 1 < pts.size() && straight(out.back(), pts[i], pts[i + 1])) continue;
        out.push_back(pts[i]);
    }
    return out;
}

}  // namespace

std::vector<Polyline> valid_outline(const std::vector<std::uint8_t>& valid, int w, int h) {
    std::vector<Polyline> out;
    if (valid.empty() || w < 2 || h < 2) return out;
    const std::size_t W = std::size_t(w);
    // The segments of every cell (marching squares), as pairs of edge midpoints.
    std::vector<std::array<LatticePoint, 2>> segs;
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            const std::size_t i = std::size_t(y) * W + std::size_t(x);
            const bool a = valid[i] != 0, b = valid[i + 1] != 0, c = valid[i + W + 1] != 0, d = valid[i + W] != 0;
            const int k = int(a) + int(b) + int(c) + int(d);
            if (k == 0 || k == 4) continue;
            const LatticePoint ab{2 * x + 1, 2 * y}, bc{2 * x + 2, 2 * y + 1}, cd{2 * x + 1, 2 * y + 2}, da{2 * x, 2 * y + 1};
            if (k == 2 && a == c) {  // a saddle: the valid diagonal joined, each nodata corner cut off
                if (!b) segs.push_back({ab, bc});
                if (!d) segs.push_back({cd, da});
                if (!a) segs.push_back({da, ab});
                if (!c) segs.push_back({bc, cd});
                continue;
            }
            LatticePoint m[2];
            int n = 0;
            if (a != b) m[n++] = ab;
            if (b != c) m[n++] = bc;
            if (c != d) m[n++] = cd;
            if (d != a) m[n++] = da;
            segs.push_back({m[0], m[1]});
        }
    if (segs.empty()) return out;
    // Each midpoint inside the image is shared by the segments of its two cells; one on the
    // border belongs to one segment and ends a chain.
    std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> at;
    at.reserve(2 * segs.size());
    constexpr std::uint32_t kNone = 0xffffffffu;
    for (std::uint32_t s = 0; s < segs.size(); ++s)
        for (const LatticePoint p : segs[s]) {
            auto it = at.try_emplace(key_of(p), std::array<std::uint32_t, 2>{kNone, kNone}).first;
            (it->second[0] == kNone ? it->second[0] : it->second[1]) = s;
        }
    std::vector<std::uint8_t> used(segs.size(), 0);
    // Follows the chain from segment s entering at point p; appends the points to *line.
    const auto follow = [&](std::uint32_t s, LatticePoint p, Polyline* line) {
        line->push_back(p);
        while (s != kNone && !used[s]) {
            used[s] = 1;
            const LatticePoint q = segs[s][0] == p ? segs[s][1] : segs[s][0];
            line->push_back(q);
            const auto& nb = at[key_of(q)];
            s = nb[0] == s ? nb[1] : nb[0];
            p = q;
        }
    };
    // Open chains first (from a border midpoint), in a fixed order, then the loops.
    for (std::uint32_t s = 0; s < segs.size(); ++s)
        for (const LatticePoint p : segs[s]) {
            if (used[s]) break;
            const auto& nb = at[key_of(p)];
            if (nb[1] != kNone) continue;
            Polyline line;
            follow(s, p, &line);
            out.push_back(merge_collinear(line));
        }
    for (std::uint32_t s = 0; s < segs.size(); ++s) {
        if (used[s]) continue;
        Polyline line;
        follow(s, segs[s][0], &line);
        out.push_back(merge_collinear(line));
    }
    return out;
}

bool inside_valid_region(const std::vector<std::uint8_t>& valid, int w, int h, std::int64_t x6, std::int64_t y6) {
    if (valid.empty() || w < 2 || h < 2) return true;
    const std::int64_t cx = std::min<std::int64_t>(std::max<std::int64_t>(x6 / 6, 0), w - 2);
    const std::int64_t cy = std::min<std::int64_t>(std::max<std::int64_t>(y6 / 6, 0), h - 2);
    const std::size_t i = std::size_t(cy) * std::size_t(w) + std::size_t(cx), W = std::size_t(w);
    const bool ok[4] = {valid[i] != 0, valid[i + 1] != 0, valid[i + W + 1] != 0, valid[i + W] != 0};  // a b c d
    const std::int64_t u = x6 - 6 * cx, v = y6 - 6 * cy;                                             // 0..6
    const std::int64_t cu[4] = {0, 6, 6, 0}, cv[4] = {0, 0, 6, 6};
    const auto l1 = [&](int k) { return (u > cu[k] ? u - cu[k] : cu[k] - u) + (v > cv[k] ? v - cv[k] : cv[k] - v); };
    const int k = int(ok[0]) + int(ok[1]) + int(ok[2]) + int(ok[3]);
    if (k == 4) return true;
    if (k == 0) return false;
    if (k == 1)
        for (int j = 0; j < 4; ++j)
            if (ok[j]) return l1(j) <= 3;
    if (k == 3)
        for (int j = 0; j < 4; ++j)
            if (!ok[j]) return l1(j) >= 3;
    if (ok[0] == ok[2]) {  // a saddle: both nodata corners cut off
        for (int j = 0; j < 4; ++j)
            if (!ok[j] && l1(j) < 3) return false;
        return true;
    }
    if (ok[0] && ok[1]) return v <= 3;
    if (ok[2] && ok[3]) return v >= 3;
    if (ok[0] && ok[3]) return u <= 3;
    return u >= 3;  // b and c
}

std::vector<std::uint8_t> near_nodata(const std::vector<std::uint8_t>& valid, int w, int h, int radius) {
    const std::size_t W = std::size_t(w), H = std::size_t(h);
    std::vector<std::uint8_t> rows(W * H, 0), out(W * H, 0);
    if (valid.empty()) return out;
    const std::ptrdiff_t r = radius;
    for (std::size_t y = 0; y < H; ++y) {
        // The distance to the last nodata pixel on the left, then on the right.
        std::ptrdiff_t last = -(r + 1) - 1;
        for (std::ptrdiff_t x = 0; x < std::ptrdiff_t(W); ++x) {
            if (!valid[y * W + std::size_t(x)]) last = x;
            if (x - last <= r) rows[y * W + std::size_t(x)] = 1;
        }
        last = std::ptrdiff_t(W) + r + 1;
        for (std::ptrdiff_t x = std::ptrdiff_t(W) - 1; x >= 0; --x) {
            if (!valid[y * W + std::size_t(x)]) last = x;
            if (last - x <= r) rows[y * W + std::size_t(x)] = 1;
        }
    }
    for (std::size_t x = 0; x < W; ++x) {
        std::ptrdiff_t last = -(r + 1) - 1;
        for (std::ptrdiff_t y = 0; y < std::ptrdiff_t(H); ++y) {
            if (rows[std::size_t(y) * W + x]) last = y;
            if (y - last <= r) out[std::size_t(y) * W + x] = 1;
        }
        last = std::ptrdiff_t(H) + r + 1;
        for (std::ptrdiff_t y = std::ptrdiff_t(H) - 1; y >= 0; --y) {
            if (rows[std::size_t(y) * W + x]) last = y;
            if (last - y <= r) out[std::size_t(y) * W + x] = 1;
        }
    }
    return out;
}

std::vector<Polyline> clip_polylines(const std::vector<Polyline>& lines, const std::vector<std::uint8_t>& near, int w) {
    if (near.empty()) return lines;
    std::vector<Polyline> out;
    const auto is_near = [&](LatticePoint p) {
        return near[std::size_t((p.y + 1) / 2) * std::size_t(w) + std::size_t((p.x + 1) / 2)] != 0;
    };
    for (const Polyline& pl : lines) {
        Polyline run;
        for (const LatticePoint p : pl) {
            if (is_near(p)) {
                if (run.size() >= 2) out.push_back(run);
                run.clear();
                continue;
            }
            run.push_back(p);
        }
        if (run.size() >= 2) out.push_back(run);
    }
    return out;
}

}  // namespace erd
