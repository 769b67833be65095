#include "algorithms/codec/erdz_rebuild.h"

#include <algorithm>
#include <utility>

namespace erd::codec {

Status rebuild(int width, int height, const std::vector<LatticePoint>& free_points, const std::vector<Chain>& chains,
               Rebuilt* r) {
    Cdt& cdt = r->cdt;
    Status st = cdt.reset(2 * width - 2, 2 * height - 2);
    if (!st) return st;
    std::vector<LatticePoint> pts = free_points;
    for (const Chain& c : chains) pts.insert(pts.end(), c.begin(), c.end());
    cdt.reserve(pts.size() + 4);
    std::vector<VertInd> v;
    if (!(st = cdt.insert_points(pts, &v, false))) return st;
    // Corners and chain points may repeat among themselves; a free point repeats nothing.
    std::vector<std::uint8_t> taken(cdt.vertex_count(), 0);
    for (VertInd c = 0; c < 4; ++c) taken[c] = 1;
    for (std::size_t i = free_points.size(); i < pts.size(); ++i) taken[v[i]] = 1;
    for (std::size_t i = 0; i < free_points.size(); ++i) {
        if (taken[v[i]])
            return Status::bad_input("positions section: the point (" + std::to_string(pts[i].x) + ", " +
                                     std::to_string(pts[i].y) + ") is also a corner or on an edge");
        taken[v[i]] = 1;
    }
    std::size_t at = free_points.size();
    ConstraintReport rep;
    for (const Chain& c : chains) {
        for (std::size_t i = 0; i + 1 < c.size(); ++i)
            if (!(st = cdt.insert_constraint(v[at + i], v[at + i + 1], &rep))) return st;
        at += c.size();
    }
    if (rep.dropped_crossing > 0) return Status::bad_input("edges section: two constrained edges cross");
    return Status::success();
}

void number_units(bool erd, Rebuilt* r) {
    const Cdt& cdt = r->cdt;

    const std::size_t nv = cdt.vertex_count(), nh = 3 * cdt.face_count();
    // (y, x) order (the points are distinct) by two stable counting passes over the lattice's
    // columns, then its rows: linear in the vertices and the lattice side.
    const auto counting_pass = [&](const std::vector<VertInd>& in, std::size_t size, auto coord, std::vector<VertInd>* out) {
        std::vector<std::uint32_t> first(size + 1, 0);
        for (const VertInd i : in) ++first[std::size_t(coord(cdt.point(i))) + 1];
        for (std::size_t c = 0; c < size; ++c) first[c + 1] += first[c];
        out->resize(in.size());
        for (const VertInd i : in) (*out)[first[std::size_t(coord(cdt.point(i)))]++] = i;
    };
    std::vector<VertInd> by_x, all(nv);
    for (VertInd i = 0; i < nv; ++i) all[i] = i;
    counting_pass(all, std::size_t(cdt.max_x()) + 1, [](LatticePoint p) { return p.x; }, &by_x);
    counting_pass(by_x, std::size_t(cdt.max_y()) + 1, [](LatticePoint p) { return p.y; }, &r->order);
    r->rank.assign(nv, 0);
    for (std::uint32_t k = 0; k < nv; ++k) r->rank[r->order[k]] = k;

    r->corner_unit.assign(nh, 0);
    r->unit_begin.assign(nv + 1, 0);
    std::uint32_t units = 0;
    // Every half-edge is the corner of its face at its origin, so the walk below meets each once;
    // by_unit lists them in the walk's order, in which their units never decrease.
    std::vector<EdgeInd> by_unit;
    by_unit.reserve(nh);
    // Units: one per vertex (basic), else one per wedge, as Cdt::wedges() counts them (a run of
    // corners_around() between interior constrained edges; an interior vertex with one such edge
    // has one wedge), without its per-call allocations.
    std::vector<EdgeInd> corners;
    for (std::uint32_t k = 0; k < nv; ++k) {
        const VertInd vert = r->order[k];
        r->unit_begin[k] = units;
        cdt.corners_around(vert, &corners);
        std::uint32_t cuts = 0;
        if (erd)
            for (EdgeInd e : corners) cuts += cdt.constrained(e) && !cdt.on_hull(e);
        const bool one = !erd || cuts == 0 || (cuts == 1 && !cdt.on_boundary(vert));
        // An interior vertex's wedges are numbered from the constrained edge to the (y, x)-smallest
        // neighbour, so the numbering depends on the triangulation alone, not on which half-edge
        // the kernel's history left in out_edge().
        if (!one && !cdt.on_boundary(vert)) {
            std::size_t best = corners.size();
            for (std::size_t i = 0; i < corners.size(); ++i) {
                const EdgeInd e = corners[i];
                if (!cdt.constrained(e) || cdt.on_hull(e)) continue;
                const LatticePoint p = cdt.point(cdt.dest(e));
                if (best == corners.size()) { best = i; continue; }
                const LatticePoint q = cdt.point(cdt.dest(corners[best]));
                if (p.y < q.y || (p.y == q.y && p.x < q.x)) best = i;
            }
            std::rotate(corners.begin(), corners.begin() + long(best), corners.end());
        }
        bool first = true;
        for (EdgeInd e : corners) {
            if (!first && !one && cdt.constrained(e) && !cdt.on_hull(e)) ++units;
            first = false;
            r->corner_unit[e] = units;
            by_unit.push_back(e);
        }
        ++units;
    }
    r->unit_begin[nv] = units;

    // Neighbour lists: the units of the other two corners of each face a unit covers, increasing
    // and unique. The relation is symmetric (u's face has a corner of w exactly when w's face has
    // one of u), so each unit w, taken in increasing order, is appended to the lists of the units
    // beside its corners: every list fills in increasing order, with repeats side by side, and
    // needs no sort (sorting a dozen entries per unit mispredicted most of its comparisons).
    ValueGraph& g = r->graph;
    g.begin.assign(std::size_t(units) + 1, 0);
    for (EdgeInd e = 0; e < nh; ++e) g.begin[r->corner_unit[e] + 1] += 2;
    for (std::size_t u = 0; u < units; ++u) g.begin[u + 1] += g.begin[u];
    std::vector<std::uint32_t> raw(g.begin.back()), fill(g.begin.begin(), g.begin.end() - 1);
    for (const EdgeInd e : by_unit) {
        const std::uint32_t w = r->corner_unit[e];
        raw[fill[r->corner_unit[next_edge(e)]]++] = w;
        raw[fill[r->corner_unit[prev_edge(e)]]++] = w;
    }
    // Unique in place, without a branch per entry (a unit appears once or twice, unpredictably).
    std::uint32_t n = 0;
    for (std::size_t u = 0; u < units; ++u) {
        const std::uint32_t b0 = g.begin[u], b1 = g.begin[u + 1];
        g.begin[u] = n;
        std::uint32_t last = ~0u;  // no unit: units stay below 2^32 - 1
        for (std::uint32_t i = b0; i < b1; ++i) {
            const std::uint32_t w = raw[i];
            raw[n] = w;
            n += w != last;
            last = w;
        }
    }
    raw.resize(n);
    g.neighbour = std::move(raw);
    g.begin[units] = n;
}

}  // namespace erd::codec
