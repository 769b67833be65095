// Cdt constraint insertion.
//
// A segment a-b is traced from a through the triangulation. The trace stops at the first vertex
// lying exactly on the segment (or at b), which splits the segment into pieces handled one at a
// time. The edges a piece crosses are removed by flips (Sloan 1993: flip a crossing edge whose
// quadrilateral is strictly convex; if the new diagonal still crosses, queue it again), after which
// the piece is an edge of the triangulation. Lawson flips over every edge of the flipped quadrilaterals then
// restore the constrained Delaunay condition; the tie rule of predicates.h makes the result
// independent of the order of all operations.
//
// Crossing policy: a piece whose interior would cross an existing constrained edge is dropped
// whole (counted in ConstraintReport::dropped_crossing). Splitting both segments at the crossing
// would create a vertex that is usually not a lattice point, and a lattice crossing point would
// still change the vertex count the density targets rely on, so the later piece simply loses.
#include <algorithm>

#include "kernel/cdt.h"

namespace erd {

EdgeInd Cdt::find_edge(VertInd a, VertInd b) const {
    if (a >= out_.size() || b >= out_.size() || out_[a] == noEdge) return noEdge;
    const EdgeInd start = out_[a];
    EdgeInd e = start;
    do {
        if (vert_[next_edge(e)] == b) return e;
        e = rot_next(e);
    } while (e != noEdge && e != start);
    if (e == start) return noEdge;
    // Open fan (boundary vertex): the rest lies on the other side of start.
    e = rot_prev(start);
    while (e != noEdge) {
        if (vert_[next_edge(e)] == b) return e;
        e = rot_prev(e);
    }
    return noEdge;
}

void Cdt::set_constrained(EdgeInd e) {
    flags_[e] = 1;
    touch(face_of(e));
    const EdgeInd t = twin_[e];
    if (t != noEdge) {
        flags_[t] = 1;
        touch(face_of(t));
    }
}

// The first corner (half-edge leaving v) of v's fan: after the hull edge for a boundary vertex,
// out_[v] itself for an interior one.
static EdgeInd first_corner(const Cdt& cdt, VertInd v) {
    const EdgeInd start = cdt.out_edge(v);
    EdgeInd e = start;
    for (;;) {
        const EdgeInd p = cdt.rot_prev(e);
        if (p == noEdge || p == start) return p == noEdge ? e : start;
        e = p;
    }
}

Status Cdt::insert_constraint(VertInd a, VertInd b, ConstraintReport* rep) {
    begin_change();
    if (a >= points_.size() || b >= points_.size())
        return Status::bad_input("constraint vertex index out of range");
    if (out_[a] == noEdge || out_[b] == noEdge) return Status::bad_input("constraint vertex was removed");
    ConstraintReport r;
    VertInd cur = a;
    Status st;
    while (cur != b && st.ok()) {
        // Find, around cur, the edge along the segment or the face the segment enters.
        const LatticePoint pc = points_[cur], pb = points_[b];
        const EdgeInd first = first_corner(*this, cur);
        EdgeInd along = noEdge;   // a half-edge of the edge cur-w with w on the segment
        VertInd next_v = noVertex;
        EdgeInd cross = noEdge;   // first crossed half-edge, in the face at cur
        EdgeInd e = first;
        do {
            const VertInd w = vert_[next_edge(e)], x = vert_[prev_edge(e)];
            const LatticePoint pw = points_[w], px = points_[x];
            const std::int64_t ow = orient2d(pc, pb, pw);
            if (ow == 0 && (std::int64_t(pw.x - pc.x) * (pb.x - pc.x) + std::int64_t(pw.y - pc.y) * (pb.y - pc.y)) > 0) {
                along = e;
                next_v = w;
                break;
            }
            const std::int64_t ox = orient2d(pc, pb, px);
            if (ox == 0 && (std::int64_t(px.x - pc.x) * (pb.x - pc.x) + std::int64_t(px.y - pc.y) * (pb.y - pc.y)) > 0) {
                along = prev_edge(e);  // x->cur
                next_v = x;
                break;
            }
            if (ow < 0 && ox > 0) {  // w right of cur->b, x left: the segment crosses w->x
                cross = next_edge(e);
                break;
            }
            e = rot_next(e);
        } while (e != noEdge && e != first);
        ++r.pieces;
        if (along != noEdge) {
            if (flags_[along]) {
                ++r.already;
            } else {
                set_constrained(along);
                segments_.push_back({cur, next_v});
                ++r.inserted;
            }
            cur = next_v;
            continue;
        }
        if (cross == noEdge) {
            st = Status::failure("constraint trace found no way out of a vertex");
            break;
        }
        // Walk across the crossed edges (org on the right of cur->b, dest on the left).
        pairs_.clear();
        bool blocked = false;
        EdgeInd ce = cross;
        for (;;) {
            if (flags_[ce]) blocked = true;
            pairs_.push_back({vert_[ce], vert_[next_edge(ce)]});
            const EdgeInd t = twin_[ce];
            if (t == noEdge) {
                st = Status::failure("constraint trace left the rectangle");
                break;
            }
            const VertInd y = vert_[prev_edge(t)];
            if (y == b) {
                next_v = b;
                break;
            }
            const std::int64_t o = orient2d(pc, pb, points_[y]);
            if (o == 0) {
                next_v = y;
                break;
            }
            ce = o > 0 ? next_edge(t) : prev_edge(t);
        }
        if (!st.ok()) break;
        if (blocked) {
            ++r.dropped_crossing;
            cur = next_v;
            continue;
        }
        st = insert_piece(cur, next_v, &r);
        cur = next_v;
    }
    if (rep) rep->add(r);
    return st;
}

// Removes the edges in pairs_ (all crossing the open segment a-b, none constrained) by flips,
// constrains a-b and restores the CDT condition.
Status Cdt::insert_piece(VertInd a, VertInd b, ConstraintReport* rep) {
    // Every edge of every quadrilateral flipped below may violate the CDT condition afterwards;
    // they are collected as vertex pairs (flips move slots) for the Lawson pass at the end. (Not
    // from changes_: a face already reported by an earlier piece of the same call is not listed
    // again there.)
    pairs2_.clear();
    const LatticePoint pa = points_[a], pb = points_[b];
    std::size_t head = 0;
    const std::size_t k = pairs_.size();
    const std::size_t cap = 16 * (k + 4) * (k + 4);
    std::size_t steps = 0;
    while (head < pairs_.size()) {
        if (++steps > cap) return Status::failure("constraint insertion did not converge");
        const Pair pr = pairs_[head++];
        const EdgeInd e = find_edge(pr.a, pr.b);
        if (e == noEdge || twin_[e] == noEdge) return Status::failure("constraint insertion lost an edge");
        const VertInd c = vert_[prev_edge(e)], d = vert_[prev_edge(twin_[e])];
        const LatticePoint pc = points_[c], pd = points_[d];
        const std::int64_t o1 = orient2d(pc, pd, points_[pr.a]), o2 = orient2d(pc, pd, points_[pr.b]);
        if (!((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0))) {  // not strictly convex: later
            pairs_.push_back(pr);
            continue;
        }
        flip(e);
        pairs2_.push_back({c, pr.a});
        pairs2_.push_back({pr.a, d});
        pairs2_.push_back({d, pr.b});
        pairs2_.push_back({pr.b, c});
        pairs2_.push_back({c, d});
        bool crosses = false;
        if (c != a && c != b && d != a && d != b) {
            const std::int64_t oc = orient2d(pa, pb, pc), od = orient2d(pa, pb, pd);
            crosses = (oc > 0 && od < 0) || (oc < 0 && od > 0);
        }
        if (crosses) pairs_.push_back({c, d});
    }
    pairs_.clear();
    EdgeInd e = find_edge(a, b);
    if (e == noEdge) e = find_edge(b, a);
    if (e == noEdge) return Status::failure("constraint edge missing after flips");
    set_constrained(e);
    segments_.push_back({a, b});
    ++rep->inserted;
    legalize_pairs();
    return Status::success();
}

// General Lawson flipping from the edges in pairs2_ (as vertex pairs, since flips move slots).
void Cdt::legalize_pairs() {
    while (!pairs2_.empty()) {
        const Pair pr = pairs2_.back();
        pairs2_.pop_back();
        const EdgeInd e = find_edge(pr.a, pr.b);
        if (e == noEdge || !is_illegal(e)) continue;
        const VertInd a = pr.a, b = pr.b, c = vert_[prev_edge(e)], d = vert_[prev_edge(twin_[e])];
        flip(e);
        pairs2_.push_back({c, a});
        pairs2_.push_back({a, d});
        pairs2_.push_back({d, b});
        pairs2_.push_back({b, c});
    }
}

}  // namespace erd
