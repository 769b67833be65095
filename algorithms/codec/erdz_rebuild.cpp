#include "algorithms/codec/erdz_rebuild.h"

#include <algorithm>
#include <utility>

namespace erd::codec {

Status rebuild(int width, int height, bool erd, const std::vector<LatticePoint>& free_points,
               const std::vector<Chain>& chains, Rebuilt* r) {
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

    const std::size_t nv = cdt.vertex_count(), nh = 3 * cdt.face_count();
    r->order.resize(nv);
    for (VertInd i = 0; i < nv; ++i) r->order[i] = i;
    std::sort(r->order.begin(), r->order.end(), [&](VertInd a, VertInd b) {
        const LatticePoint p = cdt.point(a), q = cdt.point(b);
        return p.y != q.y ? p.y < q.y : p.x < q.x;
    });
    r->rank.assign(nv, 0);
    for (std::uint32_t k = 0; k < nv; ++k) r->rank[r->order[k]] = k;

    r->corner_unit.assign(nh, 0);
    r->unit_begin.assign(nv + 1, 0);
    std::uint32_t units = 0;
    std::vector<Wedge> wedges;
    std::vector<EdgeInd> corners;
    for (std::uint32_t k = 0; k < nv; ++k) {
        const VertInd vert = r->order[k];
        r->unit_begin[k] = units;
        if (!erd) {
            cdt.corners_around(vert, &corners);
            for (EdgeInd e : corners) r->corner_unit[e] = units;
            ++units;
            continue;
        }
        cdt.wedges(vert, &wedges);
        for (const Wedge& w : wedges) {
            EdgeInd e = w.first;
            for (std::uint32_t i = 0; i < w.count && e != noEdge; ++i) {
                r->corner_unit[e] = units;
                e = cdt.rot_next(e);
            }
            ++units;
        }
    }
    r->unit_begin[nv] = units;

    // Neighbour lists: the units of the other two corners of each face a unit covers, unique.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
    links.reserve(2 * nh);
    for (EdgeInd e = 0; e < nh; ++e) {
        links.push_back({r->corner_unit[e], r->corner_unit[next_edge(e)]});
        links.push_back({r->corner_unit[e], r->corner_unit[prev_edge(e)]});
    }
    std::sort(links.begin(), links.end());
    links.erase(std::unique(links.begin(), links.end()), links.end());
    ValueGraph& g = r->graph;
    g.begin.assign(std::size_t(units) + 1, 0);
    g.neighbour.resize(links.size());
    for (std::size_t i = 0; i < links.size(); ++i) {
        ++g.begin[links[i].first + 1];
        g.neighbour[i] = links[i].second;
    }
    for (std::size_t u = 0; u < units; ++u) g.begin[u + 1] += g.begin[u];
    return Status::success();
}

}  // namespace erd::codec
