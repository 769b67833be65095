// Random triangulations of the image rectangle for the raster and model-file tests, built
// without the kernel (so they also exercise configurations a Delaunay kernel never makes).
#pragma once
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "algorithms/model/model.h"
#include "kernel/predicates.h"

namespace erd_test {

using erd::LatticePoint;

using Tri = std::array<LatticePoint, 3>;

// A random triangulation of [0,mx]x[0,my] built without the kernel: split the face containing
// each random point (into three inside a face, into two per side on an edge), then flip random
// convex quads. Degenerate-looking configurations (points on edges, collinear runs, vertices on
// the border) are frequent because the lattice is coarse.
inline std::vector<Tri> random_triangulation(std::mt19937& rng, std::int32_t mx, std::int32_t my, int points, bool even) {
    std::vector<Tri> t;
    const LatticePoint c00{0, 0}, c10{mx, 0}, c01{0, my}, c11{mx, my};
    t.push_back({c00, c10, c11});
    t.push_back({c00, c11, c01});
    std::uniform_int_distribution<std::int32_t> dx(0, even ? mx / 2 : mx), dy(0, even ? my / 2 : my);
    for (int n = 0; n < points; ++n) {
        LatticePoint p{dx(rng), dy(rng)};
        if (even) p = {2 * p.x, 2 * p.y};
        std::vector<Tri> next;
        bool vertex = false;
        for (const Tri& f : t)
            for (const LatticePoint& q : f) vertex = vertex || q == p;
        if (vertex) continue;
        for (const Tri& f : t) {
            std::int64_t o[3];
            for (int k = 0; k < 3; ++k) o[k] = erd::orient2d(f[k], f[(k + 1) % 3], p);
            const bool sgn = erd::orient2d(f[0], f[1], f[2]) > 0;
            bool inside = true;
            for (int k = 0; k < 3; ++k) inside = inside && (sgn ? o[k] >= 0 : o[k] <= 0);
            if (!inside) {
                next.push_back(f);
                continue;
            }
            // Split into the sub-triangles with nonzero area.
            for (int k = 0; k < 3; ++k)
                if (o[k] != 0) next.push_back({f[k], f[(k + 1) % 3], p});
        }
        t.swap(next);
    }
    // Random flips of strictly convex quads.
    std::uniform_int_distribution<std::size_t> pick(0, t.size() - 1);
    for (std::size_t round = 0; round < t.size() * 3; ++round) {
        const std::size_t f = pick(rng);
        const int k = int(round % 3);
        const LatticePoint a = t[f][std::size_t(k)], b = t[f][std::size_t((k + 1) % 3)], c = t[f][std::size_t((k + 2) % 3)];
        for (std::size_t g = 0; g < t.size(); ++g) {
            if (g == f) continue;
            int ia = -1, ib = -1, id = -1;
            for (int m = 0; m < 3; ++m) {
                if (t[g][std::size_t(m)] == a) ia = m;
                else if (t[g][std::size_t(m)] == b) ib = m;
                else id = m;
            }
            if (ia < 0 || ib < 0) continue;
            const LatticePoint d = t[g][std::size_t(id)];
            // Quad a, d, b, c (c and d on opposite sides of ab); flip ab -> cd if strictly convex.
            const std::int64_t s1 = erd::orient2d(c, d, a), s2 = erd::orient2d(c, d, b);
            if ((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) {
                t[f] = {c, a, d};
                t[g] = {c, d, b};
            }
            break;
        }
    }
    return t;
}

// The same as a Model: vertices (deduplicated, in first-seen order) and positive faces.
inline erd::Model to_model(const std::vector<Tri>& t, std::int32_t mx, std::int32_t my) {
    erd::Model m;
    m.width = mx / 2 + 1;
    m.height = my / 2 + 1;
    auto index = [&](LatticePoint p) {
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
            if (m.vertices[i] == p) return std::uint32_t(i);
        m.vertices.push_back(p);
        return std::uint32_t(m.vertices.size() - 1);
    };
    for (const Tri& f : t) {
        std::array<std::uint32_t, 3> fc{index(f[0]), index(f[1]), index(f[2])};
        if (erd::orient2d(f[0], f[1], f[2]) < 0) std::swap(fc[1], fc[2]);
        m.faces.push_back(fc);
    }
    return m;
}

// A random triangulation of a W x H image (random_triangulation with `points` points) as a Model
// without values.
inline erd::Model random_model(std::mt19937& rng, int W, int H, int points, bool even) {
    return to_model(random_triangulation(rng, 2 * W - 2, 2 * H - 2, points, even), 2 * W - 2, 2 * H - 2);
}

}  // namespace erd_test
