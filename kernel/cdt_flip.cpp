// Cdt: flips on request (data-dependent triangulation), beside the Delaunay flips of cdt.cpp.
#include "kernel/cdt.h"

namespace erd {

bool Cdt::can_flip(EdgeInd e) const {
    if (e >= 3 * face_count()) return false;
    const EdgeInd t = twin_[e];
    if (t == noEdge || flags_[e]) return false;
    // Faces (a,b,c) and (b,a,d): the new faces (c,a,d) and (d,b,c) must both be positive.
    const LatticePoint a = points_[vert_[e]], b = points_[vert_[t]];
    const LatticePoint c = points_[vert_[prev_edge(e)]], d = points_[vert_[prev_edge(t)]];
    return orient2d(c, a, d) > 0 && orient2d(d, b, c) > 0;
}

EdgeInd Cdt::flip_edge(EdgeInd e) {
    begin_change();
    if (!can_flip(e)) return noEdge;
    delaunay_ = false;
    return flip(e);
}

bool Cdt::can_move(VertInd v, LatticePoint p) const {
    if (v < 4 || v >= points_.size() || out_[v] == noEdge || p == points_[v]) return false;
    if (p.x <= 0 || p.y <= 0 || p.x >= max_x_ || p.y >= max_y_) return false;
    const EdgeInd first = out_[v];
    EdgeInd e = first;
    do {
        // Face e/3 = (v, a, b) with a = dest(e), b = org(prev(e)).
        if (twin_[e] == noEdge || flags_[e]) return false;
        if (orient2d(p, points_[vert_[next_edge(e)]], points_[vert_[prev_edge(e)]]) <= 0) return false;
        e = twin_[prev_edge(e)];  // rot_next
    } while (e != noEdge && e != first);
    return e == first;
}

bool Cdt::move_vertex(VertInd v, LatticePoint p) {
    begin_change();
    if (!can_move(v, p)) return false;
    delaunay_ = false;
    points_[v] = p;
    EdgeInd e = out_[v];
    do {
        touch(face_of(e));
        e = twin_[prev_edge(e)];
    } while (e != out_[v]);
    return true;
}

}  // namespace erd
