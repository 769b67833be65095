// Cdt queries: fans and wedges around a vertex, export, canonical form, and verify().
#include <algorithm>
#include <numeric>

#include "kernel/cdt.h"

namespace erd {

namespace {

bool is_interior_constraint(const Cdt& cdt, EdgeInd e) { return cdt.constrained(e) && !cdt.on_hull(e); }

// The direction of e reduced by the gcd, packed into a WedgeId (never 0 since org != dest).
WedgeId direction_id(LatticePoint a, LatticePoint b) {
    std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
    std::int64_t g = std::gcd(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
    if (g > 1) {
        dx /= g;
        dy /= g;
    }
    return (WedgeId(std::uint32_t(std::int32_t(dx))) << 32) | WedgeId(std::uint32_t(std::int32_t(dy)));
}

}  // namespace

bool Cdt::on_boundary(VertInd v) const {
    const LatticePoint p = points_[v];
    return p.x == 0 || p.y == 0 || p.x == max_x_ || p.y == max_y_;
}

void Cdt::corners_around(VertInd v, std::vector<EdgeInd>* out) const {
    out->clear();
    const EdgeInd start = out_[v];
    EdgeInd first = start;
    if (on_boundary(v)) {
        for (EdgeInd p = rot_prev(first); p != noEdge; p = rot_prev(first)) first = p;
    } else {
        // Start at a constrained edge (a wedge begins there), so wedges are contiguous runs.
        EdgeInd e = start;
        do {
            if (flags_[e]) {
                first = e;
                break;
            }
            e = rot_next(e);
        } while (e != start);
    }
    EdgeInd e = first;
    do {
        out->push_back(e);
        e = rot_next(e);
    } while (e != noEdge && e != first);
}

std::uint32_t Cdt::wedge_count(VertInd v) const {
    std::uint32_t k = 0;
    const bool boundary = on_boundary(v);
    const EdgeInd start = out_[v];
    EdgeInd e = start;
    // Count every interior constrained edge leaving v once: walk the fan positively, then (open
    // fan) negatively from start.
    do {
        if (is_interior_constraint(*this, e)) ++k;
        e = rot_next(e);
    } while (e != noEdge && e != start);
    if (e == noEdge) {
        for (e = rot_prev(start); e != noEdge; e = rot_prev(e))
            if (is_interior_constraint(*this, e)) ++k;
    }
    if (boundary) return k + 1;
    return k >= 2 ? k : 1;
}

WedgeId Cdt::wedge_id(EdgeInd e) const {
    const VertInd v = vert_[e];
    if (wedge_count(v) == 1) return kOnlyWedge;
    // Rotate negatively from the corner to the bounding constrained (or hull) edge.
    EdgeInd b = e;
    for (;;) {
        if (twin_[b] == noEdge || flags_[b]) break;
        b = rot_prev(b);
    }
    return direction_id(points_[v], points_[vert_[next_edge(b)]]);
}

void Cdt::wedges(VertInd v, std::vector<Wedge>* out) const {
    out->clear();
    std::vector<EdgeInd> corners;
    corners_around(v, &corners);
    if (wedge_count(v) == 1) {
        out->push_back(Wedge{kOnlyWedge, corners.front(), static_cast<std::uint32_t>(corners.size())});
        return;
    }
    for (EdgeInd c : corners) {
        if (out->empty() || is_interior_constraint(*this, c)) {
            out->push_back(Wedge{wedge_id(c), c, 0});
        }
        ++out->back().count;
    }
}

void Cdt::export_faces(std::vector<std::array<VertInd, 3>>* out) const {
    out->resize(live_face_count());
    std::size_t n = 0;
    for (FaceInd f = 0; f < face_count(); ++f)
        if (face_live(f)) (*out)[n++] = {vert_[3 * f], vert_[3 * f + 1], vert_[3 * f + 2]};
}

void Cdt::export_constraints(std::vector<std::array<VertInd, 2>>* out) const {
    out->clear();
    for (EdgeInd e = 0; e < 3 * face_count(); ++e) {
        if (!flags_[e]) continue;
        const VertInd a = vert_[e], b = vert_[next_edge(e)];
        if (twin_[e] != noEdge && a > b) continue;  // listed from the other half
        out->push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(out->begin(), out->end());
}

std::vector<std::array<std::int32_t, 6>> canonical_faces(const std::vector<LatticePoint>& points,
                                                         const std::vector<std::array<VertInd, 3>>& faces) {
    std::vector<std::array<std::int32_t, 6>> out(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const LatticePoint p[3] = {points[faces[f][0]], points[faces[f][1]], points[faces[f][2]]};
        int m = 0;
        for (int i = 1; i < 3; ++i)
            if (perturb_before(p[i], p[m])) m = i;
        for (int i = 0; i < 3; ++i) {
            out[f][2 * i] = p[(m + i) % 3].x;
            out[f][2 * i + 1] = p[(m + i) % 3].y;
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::array<std::int32_t, 6>> canonical_faces(const Cdt& cdt) {
    std::vector<std::array<VertInd, 3>> faces;
    cdt.export_faces(&faces);
    return canonical_faces(cdt.points(), faces);
}

namespace {
bool fail(std::string* why, const std::string& msg) {
    if (why) *why = msg;
    return false;
}
std::string es(std::size_t e) { return std::to_string(e); }
}  // namespace

bool Cdt::verify(std::string* why) const { return verify_checks(why, true); }

bool Cdt::verify_topology(std::string* why) const { return verify_checks(why, false); }

bool Cdt::verify_checks(std::string* why, bool delaunay) const {
    const std::size_t nf = face_count(), nv = points_.size(), ne = 3 * nf;
    if (nv < 4 || nf < 2) return fail(why, "not initialised");
    if (vert_.size() < ne || twin_.size() != vert_.size() || flags_.size() != vert_.size() || out_.size() != nv ||
        3 * stamp_.size() != vert_.size())
        return fail(why, "array sizes disagree");
    for (std::size_t e = ne; e < vert_.size(); ++e)  // new_faces relies on spare slots being zero
        if (vert_[e] != 0 || twin_[e] != 0 || flags_[e] != 0 || stamp_[e / 3] != 0)
            return fail(why, "spare half-edge slot " + es(e) + " not zero");
    // Freed slots (remove_vertex): no vertices, no twins, no flags, each in the free list once.
    std::size_t dead = 0;
    for (FaceInd f = 0; f < nf; ++f) {
        if (face_live(f)) continue;
        ++dead;
        for (EdgeInd e = 3 * f; e < 3 * f + 3; ++e)
            if (vert_[e] != noVertex || twin_[e] != noEdge || flags_[e] != 0)
                return fail(why, "freed face slot " + es(f) + " not cleared");
    }
    if (dead != free_faces_.size()) return fail(why, "free list disagrees with the freed slots");
    for (const FaceInd f : free_faces_)
        if (f >= nf || face_live(f)) return fail(why, "free list holds a live or invalid slot");
    std::vector<std::uint8_t> used(nv, 0);
    __int128 area = 0;
    std::size_t hull = 0;
    for (EdgeInd e = 0; e < ne; ++e) {
        if (!face_live(face_of(e))) continue;
        const VertInd v = vert_[e];
        if (v >= nv) return fail(why, "half-edge " + es(e) + " has no valid origin");
        used[v] = 1;
        const EdgeInd t = twin_[e];
        if (t == noEdge) {
            ++hull;
            const LatticePoint a = points_[v], b = points_[vert_[next_edge(e)]];
            const bool on_side = (a.x == b.x && (a.x == 0 || a.x == max_x_)) || (a.y == b.y && (a.y == 0 || a.y == max_y_));
            if (!on_side) return fail(why, "hull half-edge " + es(e) + " not on the rectangle boundary");
            continue;
        }
        if (t >= ne || twin_[t] != e || !face_live(face_of(t))) return fail(why, "twin asymmetry at half-edge " + es(e));
        if (face_of(t) == face_of(e)) return fail(why, "half-edge " + es(e) + " twinned inside its face");
        if (vert_[t] != vert_[next_edge(e)] || vert_[next_edge(t)] != v)
            return fail(why, "twin endpoints disagree at half-edge " + es(e));
        if (flags_[t] != flags_[e]) return fail(why, "constraint flag asymmetric at half-edge " + es(e));
    }
    for (FaceInd f = 0; f < nf; ++f) {
        if (!face_live(f)) continue;
        const std::int64_t o = orient2d(points_[vert_[3 * f]], points_[vert_[3 * f + 1]], points_[vert_[3 * f + 2]]);
        if (o <= 0) return fail(why, "face " + es(f) + " not positively oriented");
        area += o;
    }
    if (area != __int128(2) * max_x_ * max_y_) return fail(why, "face areas do not sum to the rectangle");
    std::size_t dead_vertices = 0;
    for (VertInd v = 0; v < nv; ++v) {
        if (out_[v] == noEdge) {  // removed
            if (used[v]) return fail(why, "removed vertex " + es(v) + " still in a face");
            ++dead_vertices;
            continue;
        }
        if (!used[v]) return fail(why, "vertex " + es(v) + " in no face");
        if (out_[v] >= ne || vert_[out_[v]] != v) return fail(why, "out_edge of vertex " + es(v) + " invalid");
    }
    // Euler: V - E + F = 1 without the outer face; E = (3F + hull) / 2.
    if (dead_vertices != dead_vertices_ || nv - dead_vertices < 4) return fail(why, "removed vertex count disagrees");
    const std::size_t lf = nf - dead, lv = nv - dead_vertices;
    if ((3 * lf + hull) % 2 != 0) return fail(why, "odd half-edge count");
    const std::int64_t edges = std::int64_t(3 * lf + hull) / 2;
    if (std::int64_t(lv) - edges + std::int64_t(lf) != 1) return fail(why, "Euler's relation fails");
    // Distinct points (a duplicate would make a zero-length edge, but check directly).
    {
        std::vector<std::pair<std::int32_t, std::int32_t>> pts;
        pts.reserve(lv);
        for (VertInd v = 0; v < nv; ++v)
            if (out_[v] != noEdge) pts.push_back({points_[v].y, points_[v].x});
        std::sort(pts.begin(), pts.end());
        if (std::adjacent_find(pts.begin(), pts.end()) != pts.end()) return fail(why, "duplicate vertex");
    }
    // Constrained Delaunay condition with the tie rule.
    for (EdgeInd e = 0; delaunay && e < ne; ++e)
        if (face_live(face_of(e)) && is_illegal(e)) return fail(why, "edge " + es(e) + " violates the constrained Delaunay condition");
    // Every constraint piece present as a chain of collinear constrained edges.
    for (const Pair& s : segments_) {
        VertInd cur = s.a;
        const LatticePoint pa = points_[s.a], pb = points_[s.b];
        std::size_t guard = 0;
        while (cur != s.b) {
            if (++guard > nv) return fail(why, "constraint chain loops");
            const LatticePoint pc = points_[cur];
            VertInd nxt = noVertex;
            const EdgeInd start = out_[cur];
            auto consider = [&](EdgeInd e, VertInd w) {
                if (nxt != noVertex || !flags_[e]) return;
                const LatticePoint pw = points_[w];
                if (orient2d(pa, pb, pw) != 0) return;
                const std::int64_t dot = std::int64_t(pw.x - pc.x) * (pb.x - pc.x) + std::int64_t(pw.y - pc.y) * (pb.y - pc.y);
                if (dot > 0) nxt = w;
            };
            EdgeInd e = start;
            do {
                consider(e, vert_[next_edge(e)]);
                consider(prev_edge(e), vert_[prev_edge(e)]);
                e = rot_next(e);
            } while (e != noEdge && e != start);
            if (e == noEdge)
                for (e = rot_prev(start); e != noEdge; e = rot_prev(e)) {
                    consider(e, vert_[next_edge(e)]);
                    consider(prev_edge(e), vert_[prev_edge(e)]);
                }
            if (nxt == noVertex)
                return fail(why, "constraint " + es(s.a) + "-" + es(s.b) + " missing at vertex " + es(cur));
            cur = nxt;
        }
    }
    return true;
}

}  // namespace erd
