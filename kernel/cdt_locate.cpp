// Cdt point location: the randomised visibility walk, jump and walk from sampled vertices, and a
// scan as the fallback.
#include <cstdint>

#include "kernel/cdt.h"

namespace erd {

// Visibility walk with a randomised order of the edge tests (the remembering stochastic walk of
// Devillers et al.), which terminates on any triangulation, constrained or not. The randomness only
// chooses the path, never the answer. A generous step limit falls back to a scan, so a corrupted
// mesh cannot hang the caller.
// Each step loads the face's corners rotated by the random start r and leaves through the first
// edge, in that order, that has p strictly on its outer side. The edge the walk came through is
// positive (exactly the negation of the test that crossed it), so it is tested rather than
// skipped: same path, no unpredictable skip branch. Two ways to find the exit, same answer:
//   Branchless (insert_points): all three tests, then a select. Faster on short walks in a
//     spatially coherent order, where the exit branches mispredict.
//   otherwise: a branch per test. Faster on long random-order walks, where predicted exits
//     let the next face's loads start before the tests finish (docs/DECISIONS.md "Kernel").
Location Cdt::walk(LatticePoint p, FaceInd start) const { return walk_as<false>(p, start); }

template <bool Branchless>
Location Cdt::walk_as(LatticePoint p, FaceInd start) const {
    static constexpr unsigned kNext[3] = {1, 2, 0};
    const VertInd* const V = vert_.data();
    const EdgeInd* const T = twin_.data();
    const LatticePoint* const P = points_.data();
    FaceInd f = start;
    std::uint32_t rng = rng_;
    const std::size_t limit = 4 * face_count() + 64;
    for (std::size_t steps = 0; steps < limit; ++steps) {
        const EdgeInd base = 3 * f;
        rng = rng * 1664525u + 1013904223u;
        const unsigned r = ((rng >> 16) * 3u) >> 16;  // 0, 1 or 2
        // Corners in test order; the branch-free step keeps them in place and applies r in kPick.
        const unsigned i0 = Branchless ? 0 : r, i1 = kNext[i0], i2 = kNext[i1];
        const LatticePoint a = P[V[base + i0]], b = P[V[base + i1]], c = P[V[base + i2]];
        EdgeInd exit = noEdge;
        const std::int64_t s0 = orient2d(a, b, p);
        std::int64_t s1 = 1, s2 = 1;
        if constexpr (Branchless) {
            s1 = orient2d(b, c, p);
            s2 = orient2d(c, a, p);
            // kPick[r][m]: the first edge in the order r, r+1, r+2 (mod 3) whose bit is set in m
            // (a table, because a chain of selects compiled to branches again).
            static constexpr std::uint8_t kPick[3][8] = {
                {0, 0, 1, 0, 2, 0, 1, 0}, {0, 0, 1, 1, 2, 2, 1, 1}, {0, 0, 1, 0, 2, 2, 2, 2}};
            const unsigned negative = unsigned(s0 < 0) << i0 | unsigned(s1 < 0) << i1 | unsigned(s2 < 0) << i2;
            if (negative != 0) exit = base + kPick[r][negative];
        } else if (s0 < 0) {
            exit = base + i0;
        } else {
            s1 = orient2d(b, c, p);
            if (s1 < 0) {
                exit = base + i1;
            } else {
                s2 = orient2d(c, a, p);
                if (s2 < 0) exit = base + i2;
            }
        }
        if (exit != noEdge) {
            const EdgeInd t = T[exit];
            if (t == noEdge) {
                rng_ = rng;
                return Location{};  // outside the rectangle
            }
            f = face_of(t);
            continue;
        }
        rng_ = rng;
        last_face_ = f;
        Location loc;
        loc.face = f;
        // Zero tests in corner order: bit i for edge i (from corner i to corner i+1).
        const unsigned zero = unsigned(s0 == 0) << i0 | unsigned(s1 == 0) << i1 | unsigned(s2 == 0) << i2;
        if (zero == 0) {
            loc.kind = Location::Kind::in_face;
        } else if (zero == 1 || zero == 2 || zero == 4) {
            loc.kind = Location::Kind::on_edge;
            loc.edge = base + (zero >> 1);  // 1, 2, 4 -> 0, 1, 2
        } else {
            // Two edges through p: p is their shared vertex, the origin of the later one
            // (edges 0,1 -> vertex 1; 1,2 -> 2; 2,0 -> 0).
            loc.kind = Location::Kind::on_vertex;
            loc.vertex = V[base + (zero == 3 ? 1 : zero == 6 ? 2 : 0)];
        }
        return loc;
    }
    rng_ = rng;
    return locate_brute(p);
}

Location Cdt::locate_brute(LatticePoint p) const {
    for (FaceInd f = 0; f < face_count(); ++f) {
        if (!face_live(f)) continue;
        const EdgeInd base = 3 * f;
        int o[3];
        bool inside = true;
        for (unsigned i = 0; i < 3 && inside; ++i) {
            const std::int64_t s = orient2d(points_[vert_[base + i]], points_[vert_[next_edge(base + i)]], p);
            if (s < 0) inside = false;
            o[i] = s > 0 ? 1 : 0;
        }
        if (!inside) continue;
        Location loc;
        loc.face = f;
        const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
        if (zeros == 0) {
            loc.kind = Location::Kind::in_face;
        } else if (zeros == 1) {
            loc.kind = Location::Kind::on_edge;
            loc.edge = base + (o[0] == 0 ? 0u : (o[1] == 0 ? 1u : 2u));
        } else {
            unsigned v = 0;
            if (o[0] == 0 && o[1] == 0) v = 1;
            else if (o[1] == 0 && o[2] == 0) v = 2;
            loc.kind = Location::Kind::on_vertex;
            loc.vertex = vert_[base + v];
        }
        return loc;
    }
    return Location{};
}

Location Cdt::locate(LatticePoint p, FaceInd hint) const {
    if (face_count() == 0 || p.x < 0 || p.y < 0 || p.x > max_x_ || p.y > max_y_) return Location{};
    if (face_live(hint)) return walk(p, hint);
    FaceInd start = face_live(last_face_) ? last_face_ : face_of(out_[0]);  // corner 0 is never removed
    // Jump and walk (Muecke, Saias, Zhu): when the previous face is far from p compared with the
    // mean vertex spacing, start from the nearest of about n^(1/3) sampled vertices instead, which
    // cuts a random-order walk from O(sqrt n) to O(n^(1/6)) steps. Spatially coherent callers never
    // pay for the samples.
    const std::size_t nv = points_.size();
    if (nv > 64) {
        auto dist2 = [p](LatticePoint q) {
            const std::int64_t dx = std::int64_t(q.x) - p.x, dy = std::int64_t(q.y) - p.y;
            return dx * dx + dy * dy;
        };
        std::int64_t best = dist2(points_[vert_[3 * start]]);
        const std::int64_t spacing2 = (std::int64_t(max_x_) * max_y_) / std::int64_t(nv) + 1;
        if (best > 16 * spacing2) {
            std::size_t k = 1;
            while (k * k * k < nv) ++k;
            for (std::size_t i = 0; i < k; ++i) {
                rng_ = rng_ * 1664525u + 1013904223u;
                const VertInd v = static_cast<VertInd>((std::uint64_t(rng_) * nv) >> 32);
                const std::int64_t d = dist2(points_[v]);
                if (d < best && out_[v] != noEdge) {  // removed vertices have no face
                    best = d;
                    start = face_of(out_[v]);
                }
            }
        }
    }
    return walk(p, start);
}

// insert_points walks branch-free (cdt.cpp).
template Location Cdt::walk_as<true>(LatticePoint p, FaceInd start) const;

}  // namespace erd
