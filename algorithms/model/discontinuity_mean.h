// The value on a discontinuity edge of an ERD model (reconstruct.h): the mean of the planes of
// its two faces, written over what the owning face gave the lattice points on the edge. Both
// reconstructions, point evaluation (reconstruct.cpp) and supersampling (supersampling.cpp), take
// it from here.
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "algorithms/model/prepared_model.h"

namespace erd {

// Calls fn(i, j) for every point of lattice l strictly inside segment p-q (doubled coordinates).
template <class Fn>
void for_each_on_segment(const Lattice& l, LatticePoint p, LatticePoint q, Fn fn) {
    const auto mod = [](std::int64_t a, std::int64_t b) { return ((a % b) + b) % b; };
    const auto cdiv = [&](std::int64_t a, std::int64_t b) { return (a - mod(a, b)) / b + (mod(a, b) != 0); };
    const auto fdiv = [&](std::int64_t a, std::int64_t b) { return (a - mod(a, b)) / b; };
    std::int64_t px = std::int64_t(p.x) * l.scale, py = std::int64_t(p.y) * l.scale;
    std::int64_t qx = std::int64_t(q.x) * l.scale, qy = std::int64_t(q.y) * l.scale;
    if (py == qy) {
        if (mod(py - l.phase_y, l.step_y) != 0) return;
        const std::int64_t j = (py - l.phase_y) / l.step_y;
        const std::int64_t lo = std::min(px, qx) + 1, hi = std::max(px, qx) - 1;
        for (std::int64_t i = cdiv(lo - l.phase_x, l.step_x); i <= fdiv(hi - l.phase_x, l.step_x); ++i)
            fn(std::int32_t(i), std::int32_t(j));
        return;
    }
    if (py > qy) {
        std::swap(px, qx);
        std::swap(py, qy);
    }
    const std::int64_t dy = qy - py, dx = qx - px;
    for (std::int64_t j = cdiv(py + 1 - l.phase_y, l.step_y); j <= fdiv(qy - 1 - l.phase_y, l.step_y); ++j) {
        const std::int64_t y = l.fine_y(j);
        const std::int64_t t = dx * (y - py);
        if (t % dy != 0) continue;
        const std::int64_t x = px + t / dy;
        if (mod(x - l.phase_x, l.step_x) != 0) continue;
        fn(std::int32_t((x - l.phase_x) / l.step_x), std::int32_t(j));
    }
}

// Moves the points of lattice l on discontinuity edges to the mean of the two sides:
// set(i, j, c, mean, owner_value) is called for each point and channel c. Along the edge each
// side is the linear interpolation of its corner values at the endpoints, computed from the exact
// fraction t of the way along the edge, so that e.g. sides 73 and 54 give exactly 63.5 (which
// rounds up).
template <class Set>
void fix_discontinuities(const Model& m, const PreparedModel& p, const Lattice& l, Set set) {
    if (m.kind != ModelKind::erd) return;
    for (std::uint32_t h = 0; h < p.topo->twin.size(); ++h) {
        const std::uint32_t o = p.topo->twin[h];
        if (o == kNoHalfEdge || o < h || !is_discontinuity(m, *p.topo, h)) continue;
        const std::uint32_t f = h / 3;
        const auto& fc = m.faces[f];
        const LatticePoint a = m.vertices[fc[0]], b = m.vertices[fc[1]], c = m.vertices[fc[2]];
        const LatticePoint u = m.vertices[fc[h % 3]], w = m.vertices[fc[(h + 1) % 3]];
        // h runs u->w in face f; its twin o runs w->u in the other face.
        double fu[3], fw[3], gu[3], gw[3];
        for (int k = 0; k < m.channels; ++k) {
            fu[k] = corner_value(m, h, k), fw[k] = corner_value(m, ModelTopology::next(h), k);
            gu[k] = corner_value(m, ModelTopology::next(o), k), gw[k] = corner_value(m, o, k);
        }
        const bool along_y = std::abs(std::int64_t(w.y) - u.y) >= std::abs(std::int64_t(w.x) - u.x);
        const std::int64_t u0 = std::int64_t(along_y ? u.y : u.x) * l.scale;
        const std::int64_t den = std::int64_t(along_y ? w.y : w.x) * l.scale - u0;
        for_each_on_segment(l, u, w, [&](std::int32_t i, std::int32_t j) {
            const std::int64_t num = (along_y ? l.fine_y(j) : l.fine_x(i)) - u0;
            const double r = double(den - num), q = double(num), d = double(den);
            const bool f_owns = triangle_owns(l, p.dom, a, b, c, i, j);
            for (int k = 0; k < m.channels; ++k) {
                const double vf = (r * fu[k] + q * fw[k]) / d, vg = (r * gu[k] + q * gw[k]) / d;
                set(i, j, k, 0.5 * (vf + vg), f_owns ? vf : vg);
            }
        });
    }
}

}  // namespace erd
