// Cdt vertex removal.
//
// Removing v leaves a hole, the star of v: the polygon Q = q_0 .. q_{m-1} of its neighbours in
// positive order. For a vertex on a rectangle side the fan is open and the polygon is closed by
// the chord q_{m-1} -> q_0 along the side, which becomes a hull edge.
//
// Why only the hole changes, and what fills it. v has no constrained edge, so removing it changes
// no visibility; a face outside the star stays constrained Delaunay without v, and with the tie
// rule the CDT is unique, so a fresh build keeps every face outside the star. Inside, it is the
// CDT of the polygon, which is also the part of DT(Q) in the hole: every side q_i q_{i+1} had an
// empty circle through v, and every q_j is visible from v's open star (only the unconstrained
// edges v-q_k lie between), so no q_j is inside that circle and each side is an edge of DT(Q)
// (the chord is an edge of Q's hull). Two ways to find it, both deciding with the predicates of
// insertion (predicates.h), so ties fall exactly as in a fresh build:
//
//   Apex scan (holes up to scan_max_ vertices, the common case: a mean star has 6). For a base
//   edge with the rest of its sub-polygon on the left, the apex is the polygon vertex strictly
//   left of it whose circle with the base holds no other such vertex: one pass of incircle tests,
//   no visibility test (DT(Q) holds the apex's triangle). The triangle splits the sub-polygon in
//   two, handled the same way (explicit stack). O(m^2) in the worst case (a fan), m log m typical,
//   and the fewest predicates for small stars.
//
//   A CDT of the polygon (larger holes; and meshes that flip_edge / move_vertex made
//   data-dependent, where the scan's premise fails). A temporary Cdt of the same rectangle gets Q
//   by insert_points (Hilbert BRIO order: expected O(m log m)) and the sides as constraints; its
//   faces inside the sides are the answer. The sides enclose the hole, so nothing outside is
//   visible from inside: the polygon's CDT, a valid triangulation of it in any case.
//
// Both only compute the new faces (vertices, twins, flags) into buffers; the mesh is written once
// they succeeded, so a refusal or a failure changes nothing.
#include <algorithm>

#include "kernel/cdt.h"

namespace erd {

bool Cdt::can_remove(VertInd v) const {
    if (v < 4 || v >= out_.size() || out_[v] == noEdge) return false;
    const EdgeInd start = out_[v];
    EdgeInd e = start;
    do {
        if (flags_[e] || flags_[prev_edge(e)]) return false;  // v-dest(e), org(prev(e))-v
        e = rot_next(e);
    } while (e != noEdge && e != start);
    if (e == noEdge)  // open fan: the corners before start
        for (e = rot_prev(start); e != noEdge; e = rot_prev(e))
            if (flags_[e] || flags_[prev_edge(e)]) return false;
    return true;
}

void Cdt::retire(FaceInd f) {
    if (tracking_ == Tracking::lists && stamp_[f] != change_id_) {
        stamp_[f] = change_id_;
        changes_.destroyed.push_back(f);
    }
    for (EdgeInd e = 3 * f; e < 3 * f + 3; ++e) {
        vert_[e] = noVertex;
        twin_[e] = noEdge;
        flags_[e] = 0;
    }
    free_faces_.push_back(f);
}

Status Cdt::remove_vertex(VertInd v) {
    begin_change();
    if (v >= points_.size()) return Status::bad_input("vertex " + std::to_string(v) + " out of range");
    if (out_[v] == noEdge) return Status::bad_input("vertex " + std::to_string(v) + " was removed already");
    if (v < 4) return Status::bad_input("vertex " + std::to_string(v) + " is a rectangle corner");
    if (!can_remove(v)) return Status::bad_input("vertex " + std::to_string(v) + " lies on a constrained edge");
    // The star: corners e_0 .. e_{d-1} in positive order (an open fan from its hull edge on).
    // Polygon vertex i is dest(e_i), side i is next(e_i) = q_i -> q_{i+1}, and face e_i / 3 is a
    // slot for the new faces.
    const bool open = on_boundary(v);
    EdgeInd first = out_[v];
    if (open)
        for (EdgeInd p = rot_prev(first); p != noEdge; p = rot_prev(p)) first = p;
    hole_v_.clear();
    hole_t_.clear();
    hole_f_.clear();
    hole_slots_.clear();
    EdgeInd e = first, last = first;
    do {
        const EdgeInd side = next_edge(e);
        hole_v_.push_back(vert_[side]);
        hole_t_.push_back(twin_[side]);
        hole_f_.push_back(flags_[side]);
        hole_slots_.push_back(face_of(e));
        last = e;
        e = rot_next(e);
    } while (e != noEdge && e != first);
    if (open) {  // q_k and the chord q_k -> q_0, a hull edge from now on
        hole_v_.push_back(vert_[prev_edge(last)]);
        hole_t_.push_back(noEdge);
        hole_f_.push_back(0);
    }
    const std::uint32_t m = static_cast<std::uint32_t>(hole_v_.size());
    const std::uint32_t nt = m - 2;  // new faces
    new_v_.resize(3 * std::size_t(nt));
    new_t_.resize(3 * std::size_t(nt));
    new_f_.resize(3 * std::size_t(nt));
    bool ok = true;
    if (m == 3) {
        for (unsigned s = 0; s < 3; ++s) {
            new_v_[s] = hole_v_[s];
            new_t_[s] = hole_t_[s];
            new_f_[s] = hole_f_[s];
        }
    } else if (delaunay_ && m <= scan_max_) {
        ok = fill_hole_scan(m);
    } else {
        ok = fill_hole_cdt(m);
    }
    if (!ok) return Status::failure("vertex removal found no triangulation of the hole (corrupted mesh)");
    // Write the new faces in order: a twin given as a later face's half-edge is linked (both
    // ways) when that face is written, which overwrites the earlier placeholder.
    for (std::uint32_t t = 0; t < nt; ++t) {
        const EdgeInd base = 3 * hole_slots_[t];
        for (unsigned s = 0; s < 3; ++s) {
            const EdgeInd h = base + s, tw = new_t_[3 * t + s];
            vert_[h] = new_v_[3 * t + s];
            out_[vert_[h]] = h;
            flags_[h] = new_f_[3 * t + s];
            twin_[h] = tw;
            if (tw != noEdge) twin_[tw] = h;
        }
        touch(hole_slots_[t]);
    }
    for (std::size_t i = nt; i < hole_slots_.size(); ++i) retire(hole_slots_[i]);
    out_[v] = noEdge;
    ++dead_vertices_;
    last_face_ = hole_slots_[0];
    return Status::success();
}

// Apex scan over the hole polygon hole_v_[0..m). A sub-polygon (i, j) is hole_v_[i..j] closed by
// its base j -> i, with the polygon on the base's left; its face is (j, i, apex) and its base's
// twin is the half-edge given with it (the enclosing face's, or the outer twin of side m-1).
bool Cdt::fill_hole_scan(std::uint32_t m) {
    const VertInd* const Q = hole_v_.data();
    const LatticePoint* const P = points_.data();
    const bool small = small_;
    scan_stack_.clear();
    scan_stack_.insert(scan_stack_.end(), {0u, m - 1, hole_t_[m - 1], hole_f_[m - 1]});
    std::uint32_t t = 0;
    while (!scan_stack_.empty()) {
        const std::size_t top = scan_stack_.size() - 4;
        const std::uint32_t i = scan_stack_[top], j = scan_stack_[top + 1];
        const EdgeInd tw = scan_stack_[top + 2];
        const std::uint8_t fl = static_cast<std::uint8_t>(scan_stack_[top + 3]);
        scan_stack_.resize(top);
        const LatticePoint pi = P[Q[i]], pj = P[Q[j]];
        std::uint32_t c = noVertex;
        LatticePoint pc{};
        for (std::uint32_t k = i + 1; k < j; ++k) {
            const LatticePoint pk = P[Q[k]];
            if (orient2d(pj, pi, pk) <= 0) continue;
            if (c == noVertex || incircle_perturbed(pj, pi, pc, pk, small) > 0) {
                c = k;
                pc = pk;
            }
        }
        if (c == noVertex) return false;
        const EdgeInd h = 3 * hole_slots_[t];
        const std::size_t o = 3 * std::size_t(t);
        new_v_[o] = Q[j];
        new_v_[o + 1] = Q[i];
        new_v_[o + 2] = Q[c];
        new_t_[o] = tw;
        new_f_[o] = fl;
        if (c == i + 1) {  // i -> c is side i
            new_t_[o + 1] = hole_t_[i];
            new_f_[o + 1] = hole_f_[i];
        } else {
            new_t_[o + 1] = noEdge;  // linked by the face of sub-polygon (i, c)
            new_f_[o + 1] = 0;
            scan_stack_.insert(scan_stack_.end(), {i, c, h + 1, 0u});
        }
        if (j == c + 1) {  // c -> j is side c
            new_t_[o + 2] = hole_t_[c];
            new_f_[o + 2] = hole_f_[c];
        } else {
            new_t_[o + 2] = noEdge;
            new_f_[o + 2] = 0;
            scan_stack_.insert(scan_stack_.end(), {c, j, h + 2, 0u});
        }
        ++t;
    }
    return t == m - 2;
}

// The hole as the CDT of its polygon, built in a temporary Cdt (see the top).
bool Cdt::fill_hole_cdt(std::uint32_t m) {
    Cdt tmp;
    if (!tmp.reset(max_x_, max_y_).ok()) return false;
    std::vector<LatticePoint> pts(m);
    for (std::uint32_t i = 0; i < m; ++i) pts[i] = points_[hole_v_[i]];
    std::vector<VertInd> tv;
    if (!tmp.insert_points(pts, &tv, false).ok()) return false;
    std::vector<std::uint32_t> index(tmp.vertex_count(), noVertex);  // temporary vertex -> polygon index
    for (std::uint32_t i = 0; i < m; ++i) index[tv[i]] = i;
    for (std::uint32_t i = 0; i < m; ++i) {
        ConstraintReport rep;
        if (!tmp.insert_constraint(tv[i], tv[i + 1 == m ? 0 : i + 1], &rep).ok() || rep.pieces != 1 ||
            rep.dropped_crossing != 0)
            return false;
    }
    // The faces inside, numbered in the order a flood from side 0 reaches them; a half-edge k -> l
    // with l == k + 1 (mod m) is a side, any other leads to a face inside.
    const EdgeInd seed = tmp.find_edge(tv[0], tv[1]);
    if (seed == noEdge) return false;
    std::vector<std::uint32_t> number(tmp.face_count(), noVertex);
    std::vector<FaceInd> inside{face_of(seed)};
    number[face_of(seed)] = 0;
    for (std::size_t n = 0; n < inside.size(); ++n) {
        if (inside.size() > m - 2) return false;
        for (unsigned s = 0; s < 3; ++s) {
            const EdgeInd e = 3 * inside[n] + s;
            const std::uint32_t k = index[tmp.org(e)], l = index[tmp.dest(e)];
            if (k == noVertex || l == noVertex) return false;  // a rectangle corner: not inside
            if (l == (k + 1 == m ? 0 : k + 1)) continue;
            const FaceInd g = face_of(tmp.twin(e));
            if (number[g] == noVertex) {
                number[g] = static_cast<std::uint32_t>(inside.size());
                inside.push_back(g);
            }
        }
    }
    if (inside.size() != m - 2) return false;
    for (std::uint32_t t = 0; t < m - 2; ++t)
        for (unsigned s = 0; s < 3; ++s) {
            const EdgeInd e = 3 * inside[t] + s;
            const std::uint32_t k = index[tmp.org(e)], l = index[tmp.dest(e)];
            const std::size_t o = 3 * std::size_t(t) + s;
            new_v_[o] = hole_v_[k];
            if (l == (k + 1 == m ? 0 : k + 1)) {
                new_t_[o] = hole_t_[k];
                new_f_[o] = hole_f_[k];
            } else {
                const EdgeInd u = tmp.twin(e);
                new_t_[o] = 3 * hole_slots_[number[face_of(u)]] + u % 3;
                new_f_[o] = 0;
            }
        }
    return true;
}

}  // namespace erd
