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
    return flip(e);
}

}  // namespace erd
