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
// Both only compute the new faces into buffers (each corner as a polygon vertex, and either the
// polygon side it lies on or its partner corner in another new face); the mesh is written once
// they succeeded, so a refusal or a failure changes nothing.
//
// Where the new faces go. Each new face that has a polygon side takes the slot of the old face
// that had that side, turned so that the side keeps its half-edge: its outer twin already points
// there and its flag is in place, and every out_ entry of the side's two ends that pointed into
// that slot stays valid, so neither the neighbour's twin nor those out_ entries are written. Faces
// without a side take the slots left over. On random points that saves about 40% of the writes to
// other faces' twins and vertices' out_ entries, which are cache misses on a large mesh
// (docs/DECISIONS.md "Vertex removal").
#include <algorithm>

#include "kernel/cdt.h"

namespace erd {

namespace {
constexpr std::uint8_t kMod3[6] = {0, 1, 2, 0, 1, 2};  // (a + b) % 3 for a, b < 3, without a division
}  // namespace

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

// The scratch arrays for a hole of up to n polygon vertices.
void Cdt::grow_hole(std::size_t n) {
    if (hole_v_.size() >= n) return;
    n = std::max<std::size_t>(n, 2 * hole_v_.size());
    hole_v_.resize(n);
    hole_p_.resize(n);
    hole_t_.resize(n);
    hole_f_.resize(n);
    hole_e_.resize(n);
    hole_pos_.resize(n);
    hole_out_.resize(n);
    hole_kept_.resize(n);
    new_q_.resize(3 * n);
    new_s_.resize(3 * n);
    new_slot_.resize(n);
    new_rot_.resize(n);
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
    // edge on). Polygon vertex i is q_i = dest(e_i); side i is the half-edge next(e_i) = q_i ->
    // q_{i+1}, with its outer twin and flag; its face is a slot for the new faces. A constrained
    // edge at v refuses. The walk starts at out_[v]; when it runs into the hull, v is on a
    // rectangle side (its fan is open: rare) and it starts again from the fan's first corner.
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
            const EdgeInd tw = twin_[side];
            // The writes at the end miss the cache on a large mesh: start fetching their lines now.
            __builtin_prefetch(&out_[q], 1);
            if (tw != noEdge) __builtin_prefetch(&twin_[tw], 1);
            hole_v_[m] = q;
            hole_p_[m] = points_[q];
            hole_t_[m] = tw;
            hole_f_[m] = flagged ? flags_[side] : 0;
            hole_e_[m] = side;
            hole_pos_[m] = static_cast<std::uint8_t>(side - 3 * face_of(side));
            ++m;
            last = e;
            e = twin_[prev_edge(e)];  // rot_next
        } while (e != noEdge && e != first);
        if (e != noEdge || open) break;
        open = true;
        for (EdgeInd p = rot_prev(first); p != noEdge; p = rot_prev(p)) first = p;
    }
    const std::uint32_t slots = m;  // sides 0..slots-1 have a face; an open fan's chord has none
    if (open) {  // q_k and the chord q_k -> q_0, a hull edge from now on
        if (flagged && flags_[prev_edge(last)]) return Status::bad_input("vertex " + std::to_string(v) + " lies on a constrained edge");
        hole_v_[m] = vert_[prev_edge(last)];
        hole_p_[m] = points_[hole_v_[m]];
        hole_t_[m] = noEdge;
        hole_f_[m] = 0;
        hole_e_[m] = noEdge;
        ++m;
    }
    bool ok = true;
    if (m == 3) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            new_q_[i] = i;
            new_s_[i] = i;
        }
    } else if (delaunay_ && m <= scan_max_) {
        ok = fill_hole_scan(m);
    } else {
        ok = fill_hole_cdt(m);
    }
    if (!ok) return Status::failure("vertex removal found no triangulation of the hole (corrupted mesh)");
    place_new_faces(m, slots, flagged);
    out_[v] = noEdge;
    ++dead_vertices_;
    last_face_ = new_slot_[0];
    return Status::success();
}

// Writes the nt = m - 2 new faces into the star's slots (see the top), frees the slots left over
// and fills the change report. new_q_ / new_s_ hold, per corner 3t + k, the polygon vertex and
// either the polygon side (< m) or the partner corner u, l in another new face as kInner | u << 2 | l.
void Cdt::place_new_faces(std::uint32_t m, std::uint32_t slots, bool flagged) {
    // Local array pointers: the byte stores (flags, kept, turns) may alias anything, and through
    // the members the compiler would reload every vector after each of them.
    const std::uint32_t nt = m - 2;
    const VertInd* const HV = hole_v_.data();
    const EdgeInd* const HT = hole_t_.data();
    const std::uint8_t* const HF = hole_f_.data();
    const EdgeInd* const HE = hole_e_.data();
    const std::uint8_t* const HP = hole_pos_.data();
    EdgeInd* const HO = hole_out_.data();
    std::uint8_t* const kept = hole_kept_.data();
    const std::uint32_t* const NQ = new_q_.data();
    const std::uint32_t* const NS = new_s_.data();
    FaceInd* const slot = new_slot_.data();
    std::uint8_t* const rot = new_rot_.data();
    VertInd* const V = vert_.data();
    EdgeInd* const T = twin_.data();
    std::uint8_t* const F = flags_.data();
    EdgeInd* const O = out_.data();
    for (std::uint32_t i = 0; i < m; ++i) kept[i] = 0;
    // Faces with a side of their own take its slot, turned so the side keeps its position.
    const bool keep = m <= 32;  // bit i of `taken`: the slot of side i is taken (larger holes keep none)
    std::uint32_t taken = 0;
    for (std::uint32_t t = 0; t < nt; ++t) {
        slot[t] = noFace;
        rot[t] = 0;
        for (unsigned k = 0; k < 3 && keep; ++k) {
            const std::uint32_t s = NS[3 * t + k];
            if (s >= slots) continue;  // an inner edge, or the chord (no slot)
            slot[t] = face_of(HE[s]);
            rot[t] = kMod3[HP[s] + 3 - k];  // corner k -> position of side s
            kept[s] = 1;
            taken |= std::uint32_t(1) << s;
            break;
        }
    }
    // The other faces take the slots left over, in side order; what is left then is freed.
    std::uint32_t next = 0;
    for (std::uint32_t t = 0; t < nt; ++t) {
        if (slot[t] != noFace) continue;
        while (keep && (taken >> next & 1)) ++next;
        slot[t] = face_of(HE[next++]);
    }
    for (std::uint32_t t = 0; t < nt; ++t) {
        const EdgeInd base = 3 * slot[t];
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeInd h = base + kMod3[k + rot[t]];
            const std::uint32_t q = NQ[3 * t + k], s = NS[3 * t + k];
            V[h] = HV[q];
            HO[q] = h;
            if (s < m) {
                if (kept[s] && h == HE[s]) continue;  // twin and flag in place
                const EdgeInd tw = HT[s];
                T[h] = tw;
                if (tw != noEdge) T[tw] = h;
                if (flagged) F[h] = HF[s];
            } else {
                const std::uint32_t u = (s - kInner) >> 2;
                T[h] = 3 * slot[u] + kMod3[(s & 3) + rot[u]];
                if (flagged) F[h] = 0;
            }
        }
    }
    // out_ of q_i may point into the faces of sides i-1 and i; unless both kept their side (and
    // with it q_i's corner), it gets a corner of a new face.
    for (std::uint32_t i = 0, before = m - 1; i < m; before = i++)
        if (!(kept[before] && kept[i])) O[HV[i]] = HO[i];
    // The change report: the star's slots destroyed, those taken created again, the rest freed
    // (each slot once, so no stamps are needed).
    for (std::uint32_t i = 0; i < slots; ++i) changes_.destroyed.push_back(face_of(HE[i]));
    for (std::uint32_t t = 0; t < nt; ++t) changes_.created.push_back(slot[t]);
    for (; next < slots; ++next) {
        if (keep && (taken >> next & 1)) continue;
        const EdgeInd b = 3 * face_of(HE[next]);
        for (EdgeInd h = b; h < b + 3; ++h) {
            V[h] = noVertex;
            T[h] = noEdge;
            if (flagged) F[h] = 0;  // without constraints every flag is 0 already (a write miss saved)
        }
        free_faces_.push_back(b / 3);
    }
}

// Apex scan over the hole polygon hole_v_[0..m). A sub-polygon (i, j) is hole_v_[i..j] closed by
// its base j -> i, with the polygon on the base's left; its face is (j, i, apex), and its base is
// either side m-1 (the whole polygon) or the partner of a corner of the enclosing face. The stack
// of sub-polygons holds 3 numbers each: i, j and that corner (as in new_s_; or the side).
//
// The in-circle test against the base a -> b (a = j's point, b = i's) reuses two numbers per
// candidate: O_k = orient2d(a, b, k) > 0 (the side test) and L_k = (k - a).(k - b). For O_c, O_d > 0,
// d lies inside the circle through a, b, c exactly when the angle adb exceeds acb, that is when
// cot(adb) = L_d / O_d < L_c / O_c: the sign of L_c O_d - L_d O_c is incircle(a, b, c, d)'s. Six
// products a candidate instead of fourteen. Below kSmallCoord, |L|, O < 2^29 and the products fit
// int64; otherwise |L|, O < 2^49 and they need __int128 (Wide). Zero is a tie: incircle_tie.
template <class Wide>
bool Cdt::scan_as(std::uint32_t m) {
    const LatticePoint* const P = hole_p_.data();
    std::uint32_t* const NQ = new_q_.data();
    std::uint32_t* const NS = new_s_.data();
    std::uint32_t* const S = scan_stack_.data();
    std::size_t n = 0;
    S[n++] = 0;
    S[n++] = m - 1;
    S[n++] = m - 1;
    std::uint32_t t = 0;
    while (n > 0) {
        n -= 3;
        const std::uint32_t i = S[n], j = S[n + 1], base = S[n + 2];
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
        if (c == noVertex || t == m - 2) return false;
        const std::uint32_t o = 3 * t;
        NQ[o] = j;
        NQ[o + 1] = i;
        NQ[o + 2] = c;
        NS[o] = base;
        if (base >= kInner) NS[3 * ((base - kInner) >> 2) + (base & 3)] = kInner | t << 2;  // the enclosing face's corner
        if (c == i + 1) {
            NS[o + 1] = i;  // i -> c is side i
        } else {
            S[n++] = i;  // sub-polygon (i, c), its base the partner of corner 1
            S[n++] = c;
            S[n++] = kInner | t << 2 | 1;
        }
        if (j == c + 1) {
            NS[o + 2] = c;  // c -> j is side c
        } else {
            S[n++] = c;
            S[n++] = j;
            S[n++] = kInner | t << 2 | 2;
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
    std::vector<VertInd> tv;
    if (!tmp.insert_points(std::vector<LatticePoint>(hole_p_.begin(), hole_p_.begin() + m), &tv, false).ok()) return false;
    std::vector<std::uint32_t> index(tmp.vertex_count(), noVertex);  // temporary vertex -> polygon index
    for (std::uint32_t i = 0; i < m; ++i) index[tv[i]] = i;
    for (std::uint32_t i = 0; i < m; ++i) {
        ConstraintReport rep;
        if (!tmp.insert_constraint(tv[i], tv[i + 1 == m ? 0 : i + 1], &rep).ok() || rep.pieces != 1 ||
            rep.dropped_crossing != 0)
            return false;
    }
    // The faces inside, numbered in the order a flood from side 0 reaches them; a half-edge k -> l
    // with l == k + 1 (mod m) is side k, any other leads to a face inside.
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
            new_q_[3 * t + s] = k;
            const EdgeInd u = tmp.twin(e);
            new_s_[3 * t + s] = l == (k + 1 == m ? 0 : k + 1) ? k : kInner | number[face_of(u)] << 2 | u % 3;
        }
    return true;
}

}  // namespace erd
