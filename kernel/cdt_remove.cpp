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
//   Apex scan (holes up to scan_max_ = 64 vertices; a mean star has 6). For a base edge with the
//   rest of its sub-polygon on the left, the apex is the polygon vertex strictly left of it whose
//   circle with the base holds no other such vertex: one pass of incircle tests, no visibility
//   test (DT(Q) holds the apex's triangle). The triangle splits the sub-polygon in two, handled
//   the same way (explicit stack). O(m^2) in the worst case, a fan (cocircular points: the tie
//   rule makes one), about m log m otherwise, and the fewest predicates for small stars. Measured
//   (docs/DECISIONS.md "Vertex removal"): faster than the CDT below at every size up to 256 on
//   random stars, and up to about 80 on exact lattice circles, its worst case.
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

// Frees live slot f: no vertices, twins or flags, on the free list. (remove_vertex reports it.)
void Cdt::retire(FaceInd f) {
    for (EdgeInd e = 3 * f; e < 3 * f + 3; ++e) {
        vert_[e] = noVertex;
        twin_[e] = noEdge;
        flags_[e] = 0;
    }
    free_faces_.push_back(f);
}

// The scratch arrays for a hole of up to n polygon vertices.
void Cdt::grow_hole(std::size_t n) {
    if (hole_v_.size() >= n) return;
    n = std::max<std::size_t>(n, 2 * hole_v_.size());
    hole_v_.resize(n);
    hole_t_.resize(n);
    hole_f_.resize(n);
    hole_slots_.resize(n);
    hole_p_.resize(n);
    new_v_.resize(3 * n);
    new_t_.resize(3 * n);
    new_f_.resize(3 * n);
    scan_stack_.resize(4 * n);
}

Status Cdt::remove_vertex(VertInd v) {
    begin_change();
    if (v >= points_.size()) return Status::bad_input("vertex " + std::to_string(v) + " out of range");
    if (out_[v] == noEdge) return Status::bad_input("vertex " + std::to_string(v) + " was removed already");
    if (v < 4) return Status::bad_input("vertex " + std::to_string(v) + " is a rectangle corner");
    // No constraint piece was ever made: every flag is 0 and stays 0, so none is read or written.
    const bool flagged = !segments_.empty();
    // The star, in one walk: corners e_0 .. e_{d-1} in positive order (an open fan from its hull
    // edge on). Polygon vertex i is dest(e_i), side i is next(e_i) = q_i -> q_{i+1} with its outer
    // twin and flag, and face e_i / 3 is a slot for the new faces. A constrained edge at v refuses.
    // The walk starts at out_[v]; when it runs into the hull, v is on a rectangle side (its fan is
    // open: rare) and it starts again from the fan's first corner.
    grow_hole(16);
    EdgeInd first = out_[v], e, last;
    bool open = false;
    std::uint32_t m;
    for (;;) {
        m = 0;
        e = first;
        last = first;
        do {
            if (m + 2 > hole_v_.size()) grow_hole(m + 2);
            if (flagged && flags_[e]) return Status::bad_input("vertex " + std::to_string(v) + " lies on a constrained edge");
            const EdgeInd side = next_edge(e);
            const VertInd q = vert_[side];
            hole_v_[m] = q;
            hole_p_[m] = points_[q];
            hole_t_[m] = twin_[side];
            hole_f_[m] = flagged ? flags_[side] : 0;
            hole_slots_[m] = face_of(e);
            ++m;
            last = e;
            e = twin_[prev_edge(e)];  // rot_next
        } while (e != noEdge && e != first);
        if (e != noEdge || open) break;
        open = true;
        for (EdgeInd p = rot_prev(first); p != noEdge; p = rot_prev(p)) first = p;
    }
    const std::uint32_t slots = m;
    if (open) {  // q_k and the chord q_k -> q_0, a hull edge from now on
        if (flagged && flags_[prev_edge(last)]) return Status::bad_input("vertex " + std::to_string(v) + " lies on a constrained edge");
        hole_v_[m] = vert_[prev_edge(last)];
        hole_p_[m] = points_[hole_v_[m]];
        hole_t_[m] = noEdge;
        hole_f_[m] = 0;
        ++m;
    }
    const std::uint32_t nt = m - 2;  // new faces
    bool ok = true;
    if (m == 3) {
        for (unsigned i = 0; i < 3; ++i) {
            new_v_[i] = hole_v_[i];
            new_t_[i] = hole_t_[i];
            new_f_[i] = hole_f_[i];
        }
    } else if (delaunay_ && m <= scan_max_) {
        ok = fill_hole_scan(m);
    } else {
        ok = fill_hole_cdt(m);
    }
    if (!ok) return Status::failure("vertex removal found no triangulation of the hole (corrupted mesh)");
    // Write the new faces in order: a twin given as a later face's half-edge is linked (both
    // ways) when that face is written, which overwrites the earlier placeholder.
    VertInd* const V = vert_.data();
    EdgeInd* const T = twin_.data();
    EdgeInd* const O = out_.data();
    for (std::uint32_t t = 0; t < nt; ++t) {
        const EdgeInd base = 3 * hole_slots_[t];
        for (unsigned i = 0; i < 3; ++i) {
            const EdgeInd h = base + i, tw = new_t_[3 * t + i];
            V[h] = new_v_[3 * t + i];
            O[V[h]] = h;
            T[h] = tw;
            if (tw != noEdge) T[tw] = h;
            if (flagged) flags_[h] = new_f_[3 * t + i];
        }
    }
    // The change report: the star's slots destroyed, the first nt created again, the rest freed
    // (each slot once, so no stamps are needed).
    changes_.destroyed.resize(slots);
    changes_.created.resize(nt);
    std::copy(hole_slots_.data(), hole_slots_.data() + slots, changes_.destroyed.data());
    std::copy(hole_slots_.data(), hole_slots_.data() + nt, changes_.created.data());
    for (std::uint32_t t = nt; t < slots; ++t) retire(hole_slots_[t]);
    out_[v] = noEdge;
    ++dead_vertices_;
    last_face_ = hole_slots_[0];
    return Status::success();
}

// Apex scan over the hole polygon hole_v_[0..m). A sub-polygon (i, j) is hole_v_[i..j] closed by
// its base j -> i, with the polygon on the base's left; its face is (j, i, apex) and its base's
// twin is the half-edge given with it (the enclosing face's, or the outer twin of side m-1). The
// stack of sub-polygons holds 4 numbers each: i, j, the base's twin and its flag.
//
// The in-circle test against the base a -> b (a = j's point, b = i's) reuses two numbers per
// candidate: O_k = orient2d(a, b, k) > 0 (the side test) and L_k = (k - a).(k - b). For O_c, O_d > 0,
// d lies inside the circle through a, b, c exactly when the angle adb exceeds acb, that is when
// cot(adb) = L_d / O_d < L_c / O_c: the sign of L_c O_d - L_d O_c is incircle(a, b, c, d)'s. Six
// products a candidate instead of fourteen. Below kSmallCoord, |L|, O < 2^29 and the products fit
// int64; otherwise |L|, O < 2^49 and they need __int128 (Wide). Zero is a tie: incircle_tie.
template <class Wide>
bool Cdt::scan_as(std::uint32_t m) {
    const VertInd* const Q = hole_v_.data();
    const LatticePoint* const P = hole_p_.data();
    const EdgeInd* const HT = hole_t_.data();
    const std::uint8_t* const HF = hole_f_.data();
    VertInd* const NV = new_v_.data();
    EdgeInd* const NT = new_t_.data();
    std::uint8_t* const NF = new_f_.data();
    std::uint32_t* const S = scan_stack_.data();
    std::size_t n = 0;
    S[n++] = 0;
    S[n++] = m - 1;
    S[n++] = HT[m - 1];
    S[n++] = HF[m - 1];
    std::uint32_t t = 0;
    while (n > 0) {
        n -= 4;
        const std::uint32_t i = S[n], j = S[n + 1];
        const EdgeInd tw = S[n + 2];
        const std::uint8_t fl = static_cast<std::uint8_t>(S[n + 3]);
        const LatticePoint a = P[j], b = P[i];
        std::uint32_t c = noVertex;
        Wide oc = 0, lc = 0;
        for (std::uint32_t k = i + 1; k < j; ++k) {
            const LatticePoint pk = P[k];
            const Wide o = orient2d(a, b, pk);
            if (o <= 0) continue;
            const Wide l = Wide(std::int64_t(pk.x) - a.x) * (std::int64_t(pk.x) - b.x) +
                           Wide(std::int64_t(pk.y) - a.y) * (std::int64_t(pk.y) - b.y);
            if (c != noVertex) {
                const Wide in = lc * o - l * oc;  // incircle(a, b, c, k)
                if (in < 0 || (in == 0 && incircle_tie(a, b, P[c], pk) < 0)) continue;
            }
            c = k;
            oc = o;
            lc = l;
        }
        if (c == noVertex) return false;
        const EdgeInd h = 3 * hole_slots_[t];
        const std::size_t o = 3 * std::size_t(t);
        NV[o] = Q[j];
        NV[o + 1] = Q[i];
        NV[o + 2] = Q[c];
        NT[o] = tw;
        NF[o] = fl;
        if (c == i + 1) {  // i -> c is side i
            NT[o + 1] = HT[i];
            NF[o + 1] = HF[i];
        } else {  // linked by the face of sub-polygon (i, c)
            NT[o + 1] = noEdge;
            NF[o + 1] = 0;
            S[n++] = i;
            S[n++] = c;
            S[n++] = h + 1;
            S[n++] = 0;
        }
        if (j == c + 1) {  // c -> j is side c
            NT[o + 2] = HT[c];
            NF[o + 2] = HF[c];
        } else {
            NT[o + 2] = noEdge;
            NF[o + 2] = 0;
            S[n++] = c;
            S[n++] = j;
            S[n++] = h + 2;
            S[n++] = 0;
        }
        ++t;
    }
    return t == m - 2;
}

bool Cdt::fill_hole_scan(std::uint32_t m) { return small_ ? scan_as<std::int64_t>(m) : scan_as<__int128>(m); }

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
