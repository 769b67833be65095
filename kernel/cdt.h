// Cdt: a constrained Delaunay triangulation of a rectangle of the doubled integer lattice, as a
// half-edge mesh in flat index arrays.
//
// Navigation vocabulary (used everywhere in the kernel and by its callers)
//   Face f owns half-edges 3f, 3f+1, 3f+2. Corner i of face f is half-edge 3f+i; its origin is the
//   face's vertex i, and it runs to vertex (i+1)%3. face_of(e) = e/3.
//   next(e) = the following half-edge of the same face (e%3==2 ? e-2 : e+1); prev(e) likewise.
//   org(e), dest(e) = origin and destination vertices; dest(e) == org(next(e)).
//   twin(e) = the opposite half-edge (dest->org) in the neighbouring face, noEdge on the rectangle
//   boundary (the hull). Only twins are stored.
//   "Positive" / "counter-clockwise" = orient2d > 0 (kernel/predicates.h) = counter-clockwise with
//   y pointing up. Image y points down, so on screen it looks clockwise; only the sign matters.
//   Every face is stored with positive orientation: orient2d(v0, v1, v2) > 0.
//   Around a vertex v, the outgoing half-edges in positive rotational order are
//   e, rot_next(e) = twin(prev(e)), ...; rot_prev(e) = next(twin(e)). Corner e (a half-edge
//   leaving v) stands for the face e/3, which lies between the rays v->dest(e) and v->org(prev(e)).
//
// Edge flip (the only operation besides splits that rewires half-edges). Faces f1 = (a,b,c) and
// f2 = (b,a,d) share edge a-b; after the flip they are f1 = (c,a,d) and f2 = (d,b,c), and the
// slots of the four outer half-edges move with their edges:
//
//          c                       c
//         / \                     /|\      .
//        / f1\                   / | \     .
//       a-----b      ==>        a f1|f2 b
//        \ f2/                   \ | /     .
//         \ /                     \|/      .
//          d                       d
//
//   f1: 3f1+0 = c->a, 3f1+1 = a->d, 3f1+2 = d->c;   f2: 3f2+0 = d->b, 3f2+1 = b->c, 3f2+2 = c->d
//
// Contract
//   - Face slots are stable: an operation rewrites the slots of the faces it destroys and never
//     moves a face it keeps. Point insertion adds 2 faces (1 on the hull), constraint insertion
//     keeps the count, remove_vertex takes 2 (1 on the rectangle side): it frees their slots, and
//     later insertions take freed slots (last freed, first taken) before new ones. face_count() is
//     the number of slots; while nothing was removed every slot 0..face_count()-1 is live, after a
//     removal face_live(f) tells (live_face_count() counts them).
//   - Vertex indices are never reused: a removed vertex stays allocated but dead (vertex_live() is
//     false, its point() stays readable); a point inserted later at its place gets a new index.
//     vertex_count() is the number of indices, live_vertex_count() of live vertices.
//   - Ties are broken by symbolic perturbation (predicates.h), so the triangulation depends only
//     on the point set and the set of constraint segments, never on the insertion order (as long
//     as no crossing constraint piece was refused; the refusal itself depends on order).
//   - Every mutating call fills changes(): the face slots it destroyed and created.
//   - No exceptions, no printing, no global state; buffers are reused across calls.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernel/lattice.h"
#include "kernel/predicates.h"
#include "kernel/status.h"

namespace erd {

using VertInd = std::uint32_t;  // index of a vertex
using EdgeInd = std::uint32_t;  // index of a half-edge (face e/3, corner e%3)
using FaceInd = std::uint32_t;  // index of a face
constexpr VertInd noVertex = 0xFFFFFFFFu;
constexpr EdgeInd noEdge = 0xFFFFFFFFu;
constexpr FaceInd noFace = 0xFFFFFFFFu;

// Identifies one wedge of a vertex (see wedge_id). 0 means "the vertex has a single wedge".
using WedgeId = std::uint64_t;
constexpr WedgeId kOnlyWedge = 0;

inline EdgeInd next_edge(EdgeInd e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline EdgeInd prev_edge(EdgeInd e) { return e % 3 == 0 ? e + 2 : e - 1; }
inline FaceInd face_of(EdgeInd e) { return e / 3; }

// Where a point lies relative to the triangulation.
struct Location {
    enum class Kind { outside, in_face, on_edge, on_vertex };
    Kind kind = Kind::outside;
    FaceInd face = noFace;      // in_face; on_edge: face_of(edge)
    EdgeInd edge = noEdge;      // on_edge: a half-edge whose open segment contains the point
    VertInd vertex = noVertex;  // on_vertex
};

// What the last mutating call did to the faces. Slots are reused, so a slot can appear in both
// lists: `destroyed` = slots whose previous triangle is gone (each once), `created` = slots that
// now hold a new triangle (each once, including the new slots >= the previous face_count()).
// Insertions and constraints: every destroyed slot is also created. remove_vertex: the slots it
// frees are destroyed only; a freed slot taken again later is created only. Always
// created.size() - destroyed.size() = the change of live_face_count(). Faces not listed are unchanged.
struct ChangeReport {
    std::vector<FaceInd> destroyed;
    std::vector<FaceInd> created;
    std::size_t old_face_count = 0;  // face_count() before the call
};

// What insert_constraint did with a segment. A segment is split at the vertices lying exactly on
// it into pieces; each piece is inserted, or was already a constrained edge, or is dropped because
// it would cross an existing constrained edge (policy: the later piece loses; nothing is split at
// the crossing, so no vertex is created and the counts stay exact).
struct ConstraintReport {
    std::uint32_t pieces = 0;           // pieces the segment was split into (>= 1 unless a == b)
    std::uint32_t inserted = 0;         // pieces that became constrained edges now
    std::uint32_t already = 0;          // pieces that were constrained edges already
    std::uint32_t dropped_crossing = 0; // pieces refused because they cross a constrained edge
    void add(const ConstraintReport& r) {
        pieces += r.pieces; inserted += r.inserted; already += r.already; dropped_crossing += r.dropped_crossing;
    }
};

// One wedge of a vertex: `count` consecutive corners (half-edges leaving the vertex) in positive
// rotational order starting at `first`, bounded by constrained edges or the hull. The wedge spans
// from the ray v->dest(first) positively to the ray v->org(prev(last corner)).
struct Wedge {
    WedgeId id = kOnlyWedge;
    EdgeInd first = noEdge;
    std::uint32_t count = 0;
};

class Cdt {
public:
    // Starts over with the rectangle [0,max_x] x [0,max_y] (doubled coordinates): vertices
    // 0..3 = (0,0), (max_x,0), (max_x,max_y), (0,max_y) and two triangles. Requires
    // 1 <= max_x, max_y < kMaxCoord. Keeps allocated memory.
    Status reset(std::int32_t max_x, std::int32_t max_y);

    // Reserves memory for about `points` vertices (optional; avoids reallocation).
    void reserve(std::size_t points);

    // Inserts lattice point p (inside the rectangle) and restores the CDT condition by flips.
    // *v receives its vertex. A duplicate returns the existing vertex and changes nothing. A point
    // on a constrained edge splits it into two constrained edges; both sides are legalised.
    // `hint`, when valid, is a face at or near p (greedy insertion knows the face of its
    // candidate); otherwise the walk starts at the face of the previous insertion.
    Status insert_point(LatticePoint p, VertInd* v, FaceInd hint = noFace);

    // Inserts many points in a spatially coherent (Hilbert curve) order, each walking from the
    // previous one. (*v)[i] receives the vertex of pts[i]. changes() covers the whole batch, or
    // is left empty when report_changes is false (saves the per-face bookkeeping).
    Status insert_points(const std::vector<LatticePoint>& pts, std::vector<VertInd>* v,
                         bool report_changes = true);

    // Makes segment a-b constrained: splits it at the vertices lying exactly on it, drops the
    // pieces that would cross an existing constrained edge (counted in *rep), and restores the
    // CDT condition. a == b is a no-op. Invalid vertex indices -> bad_input.
    Status insert_constraint(VertInd a, VertInd b, ConstraintReport* rep = nullptr);

    // Removes vertex v and retriangulates its star: the result is the CDT of the remaining points
    // and constraint pieces, exactly the triangulation a fresh build of them gives (the same tie
    // rule), in time about proportional to v's degree (kernel/cdt_remove.cpp). Works for interior
    // vertices and for vertices on a rectangle side. Refused with bad_input, nothing changed: v out
    // of range or already removed, a rectangle corner (0..3), or v on a constrained edge (an end or
    // an inner vertex of a constraint piece: what would become of the constraint is the caller's
    // decision; none of erd's uses needs it). changes(): the star's d faces destroyed, d-2 of their
    // slots (d-1 for a vertex on a side) created again, the others freed. After flip_edge or
    // move_vertex (a data-dependent mesh) the hole is still filled with valid positive faces by the
    // same rule, but the result is no longer a CDT; the call never fails there either.
    Status remove_vertex(VertInd v);
    // True when remove_vertex(v) would remove v (not refuse it).
    bool can_remove(VertInd v) const;
    // The largest hole (star polygon) remove_vertex fills by its apex scan rather than by a
    // CDT of the polygon (cdt_remove.cpp); both give the same faces. Default 64; for tests and
    // benchmarks.
    void set_removal_scan_limit(std::uint32_t m) { scan_max_ = m; }

    // Locates p: outside, in the interior of a face, in the interior of an edge, or on a vertex.
    // `hint` as for insert_point.
    Location locate(LatticePoint p, FaceInd hint = noFace) const;

    // Faces destroyed and created by the last mutating call (reset, insert_*, remove_vertex).
    const ChangeReport& changes() const { return changes_; }

    // Vertex indices are 0..vertex_count()-1, face slots 0..face_count()-1; all live unless
    // remove_vertex ran (see the contract at the top).
    std::size_t vertex_count() const { return points_.size(); }
    std::size_t face_count() const { return nfaces_; }
    std::size_t live_vertex_count() const { return points_.size() - dead_vertices_; }
    std::size_t live_face_count() const { return nfaces_ - free_faces_.size(); }
    bool vertex_live(VertInd v) const { return v < out_.size() && out_[v] != noEdge; }
    bool face_live(FaceInd f) const { return f < nfaces_ && vert_[3 * f] != noVertex; }
    std::int32_t max_x() const { return max_x_; }
    std::int32_t max_y() const { return max_y_; }
    LatticePoint point(VertInd v) const { return points_[v]; }
    const std::vector<LatticePoint>& points() const { return points_; }

    VertInd org(EdgeInd e) const { return vert_[e]; }
    VertInd dest(EdgeInd e) const { return vert_[next_edge(e)]; }
    EdgeInd twin(EdgeInd e) const { return twin_[e]; }
    // True when the edge of e is a constrained edge (symmetric on twins; hull edges can be
    // constrained when a constraint runs along the rectangle boundary).
    bool constrained(EdgeInd e) const { return flags_[e] != 0; }
    bool on_hull(EdgeInd e) const { return twin_[e] == noEdge; }
    VertInd face_vertex(FaceInd f, int i) const { return vert_[3 * f + static_cast<FaceInd>(i)]; }
    // Some half-edge leaving v.
    EdgeInd out_edge(VertInd v) const { return out_[v]; }
    // Next / previous half-edge leaving org(e) in positive rotation; noEdge past the hull.
    EdgeInd rot_next(EdgeInd e) const { EdgeInd t = twin_[prev_edge(e)]; return t; }
    EdgeInd rot_prev(EdgeInd e) const { EdgeInd t = twin_[e]; return t == noEdge ? noEdge : next_edge(t); }
    // The half-edge a->b, or noEdge when a and b are not adjacent.
    EdgeInd find_edge(VertInd a, VertInd b) const;
    // True when v lies on the rectangle boundary (its fan of faces is open).
    bool on_boundary(VertInd v) const;

    // The corners (half-edges leaving v) in positive rotational order. For a boundary vertex the
    // open fan is listed from the hull edge on; for an interior vertex the list starts just after
    // an interior constrained edge (so wedges are contiguous runs), if v has one.
    void corners_around(VertInd v, std::vector<EdgeInd>* out) const;

    // Number of wedges of v (../shared/spec/NOTES.md): with k incident interior constrained edges (hull edges
    // excluded), an interior vertex has k wedges if k >= 2, else 1; a boundary vertex has k+1.
    std::uint32_t wedge_count(VertInd v) const;
    // The wedge of the corner e (a half-edge leaving v = org(e)): kOnlyWedge when v has one wedge,
    // otherwise the direction (reduced by gcd, packed as (uint32(dx) << 32) | uint32(dy)) of the
    // constrained or hull edge bounding the wedge on its negative rotational side. The id stays the
    // same while points are inserted elsewhere and when a bounding edge is split (its direction
    // from v is unchanged).
    WedgeId wedge_id(EdgeInd e) const;
    // The wedges of v in positive rotational order (corners_around order).
    void wedges(VertInd v, std::vector<Wedge>* out) const;

    // Export: faces as vertex triples with positive orientation (the live slots in slot order,
    // so out[f] is slot f while nothing was removed), constrained edges as (i < j).
    void export_faces(std::vector<std::array<VertInd, 3>>* out) const;
    void export_constraints(std::vector<std::array<VertInd, 2>>* out) const;

    // Full invariant check: twin symmetry and consistency, constraint flags symmetric, positive
    // orientation of every face, doubled areas summing to the rectangle's, Euler's relation, every
    // vertex used and its out_edge valid, every inserted constraint piece present (as a chain of
    // constrained edges), and the constrained Delaunay condition (with the tie rule) on every
    // unconstrained interior edge. On failure returns false and describes the first problem.
    bool verify(std::string* why) const;
    // verify() without the constrained Delaunay condition: for a triangulation that flip_edge
    // made data-dependent on purpose.
    bool verify_topology(std::string* why) const;

    // Data-dependent flips (algorithms/methods/flips.h). True when e is an unconstrained interior
    // edge whose two faces form a strictly convex quadrilateral (so both flipped faces are
    // positive). flip_edge flips such an edge (see the picture at the top) and returns the new
    // diagonal d->c, or noEdge (nothing changed) when it cannot. The result is no longer the
    // constrained Delaunay triangulation: later insertions keep a valid triangulation but
    // verify() then fails; use verify_topology().
    bool can_flip(EdgeInd e) const;
    EdgeInd flip_edge(EdgeInd e);
    // Vertex moves on request (algorithms/methods/moves.h), the same kind of data-dependent
    // change: true when v is an interior vertex with no constrained edge and every face around
    // it stays positive with v at lattice point p (so p lies in the open star of v, where no
    // other vertex is, and the faces keep their edges). move_vertex moves it (false: nothing
    // changed); faces and wedges keep their indices.
    bool can_move(VertInd v, LatticePoint p) const;
    bool move_vertex(VertInd v, LatticePoint p);

private:
    struct Pair { VertInd a, b; };

    bool verify_checks(std::string* why, bool delaunay) const;
    void begin_change();
    // Marks f destroyed (if it existed before the call) and created, once per call.
    void touch(FaceInd f) {
        if (tracking_ == Tracking::none) return;
        if (stamp_[f] == change_id_) return;
        stamp_[f] = change_id_;
        if (tracking_ == Tracking::stamps) return;
        changes_.created.push_back(f);
        if (f < changes_.old_face_count) changes_.destroyed.push_back(f);
    }
    void set_face(FaceInd f, VertInd a, VertInd b, VertInd c);
    void link(EdgeInd e, EdgeInd t);  // twins (t may be noEdge)
    FaceInd new_face();  // a freed slot (the last freed) or a new one
    void new_face_pair(FaceInd* a, FaceInd* b);  // two of them
    FaceInd append_faces(FaceInd n);  // n new slots after the last, the first returned
    void grow_hole(std::size_t n);  // remove_vertex's scratch arrays for n polygon vertices
    void place_new_faces(std::uint32_t m, std::uint32_t slots, bool flagged);
    void grow_faces(std::size_t faces);
    Location walk(LatticePoint p, FaceInd start) const;
    template <bool Branchless>
    Location walk_as(LatticePoint p, FaceInd start) const;  // walk's two step styles (cdt_locate.cpp)
    Location locate_brute(LatticePoint p) const;
    VertInd add_vertex(LatticePoint p);
    Status insert_one(LatticePoint p, VertInd* v, FaceInd hint);
    VertInd insert_at(LatticePoint p, const Location& loc);
    void split_face(FaceInd f, VertInd p);
    void split_edge(EdgeInd e, VertInd p);
    void split_side(FaceInd f, FaceInd n, VertInd x, VertInd u, VertInd w, VertInd p, EdgeInd txu, std::uint8_t fxu,
                    EdgeInd twx, std::uint8_t fwx, std::uint8_t fe);
    EdgeInd flip(EdgeInd e);  // returns the new diagonal d->c (in f1)
    void legalize_around(VertInd p, const EdgeInd* seeds, unsigned count);
    void legalize_pairs();
    bool is_illegal(EdgeInd e) const;
    Status insert_piece(VertInd a, VertInd b, ConstraintReport* rep);
    void set_constrained(EdgeInd e);

    std::int32_t max_x_ = 0, max_y_ = 0;
    std::vector<LatticePoint> points_;
    std::vector<EdgeInd> out_;        // per vertex: a half-edge leaving it
    std::vector<VertInd> vert_;       // per half-edge: origin
    std::vector<EdgeInd> twin_;       // per half-edge: twin or noEdge
    FaceInd nfaces_ = 0;              // face slots in use; the per-face arrays may be longer (new_face)
    std::vector<FaceInd> free_faces_; // slots freed by remove_vertex (vert_ = noVertex), taken first
    std::vector<FaceInd> revived_;    // freed slots taken during insert_points (created, not destroyed)
    std::size_t dead_vertices_ = 0;   // vertices removed
    bool delaunay_ = true;            // false after flip_edge / move_vertex (remove_vertex's method)
    std::uint32_t scan_max_ = 64;     // set_removal_scan_limit
    std::vector<std::uint8_t> flags_; // per half-edge: 1 = constrained
    std::vector<Pair> segments_;      // every constraint piece ever made constrained (for verify)
    ChangeReport changes_;
    std::vector<std::uint32_t> stamp_;  // per face: change_id_ when last touched
    std::uint32_t change_id_ = 0;
    // How touch() records: both lists (single operations), stamps only (insert_points collects the
    // lists from the stamps at the end), or nothing (insert_points without a report).
    enum class Tracking : std::uint8_t { lists, stamps, none };
    Tracking tracking_ = Tracking::lists;
    bool small_ = false;  // rectangle inside kSmallCoord: incircle in int64 (predicates.h)
    mutable FaceInd last_face_ = 0;
    mutable std::uint32_t rng_ = 0x9E3779B9u;  // walk randomisation only; never affects results
    // Scratch buffers reused across calls.
    std::vector<EdgeInd> stack_;
    std::vector<Pair> pairs_, pairs2_;
    std::vector<std::uint64_t> sort_buf_, sort_tmp_;  // insert_points' order (spatial_order.h)
    // remove_vertex's hole (kernel/cdt_remove.cpp), all sized by grow_hole: per polygon vertex
    // (and its side, q_i -> q_{i+1}) the vertex, point, side's outer twin, flag and half-edge, an
    // out_ candidate and whether the side kept its half-edge; per new face corner the polygon
    // vertex and the side or partner corner (kInner | face << 2 | corner); per new face its slot and turn;
    // the apex scan's stack.
    static constexpr std::uint32_t kInner = 0x80000000u;
    std::vector<VertInd> hole_v_;
    std::vector<LatticePoint> hole_p_;
    std::vector<EdgeInd> hole_t_;
    std::vector<std::uint8_t> hole_f_;
    std::vector<EdgeInd> hole_e_;
    std::vector<std::uint8_t> hole_pos_;  // hole_e_ % 3
    std::vector<EdgeInd> hole_out_;
    std::vector<std::uint8_t> hole_kept_;
    std::vector<std::uint32_t> new_q_, new_s_;
    std::vector<FaceInd> new_slot_;
    std::vector<std::uint8_t> new_rot_;
    std::vector<std::uint32_t> scan_stack_;
    bool fill_hole_scan(std::uint32_t m);
    template <class Wide>
    bool scan_as(std::uint32_t m);  // fill_hole_scan in int64 or __int128
    bool fill_hole_cdt(std::uint32_t m);
};

// A canonical form of the triangulation for comparisons: every face as its three points rotated
// so the (Y,X)-smallest comes first, faces sorted. Two triangulations of the same rectangle are
// equal iff their canonical forms are.
std::vector<std::array<std::int32_t, 6>> canonical_faces(const Cdt& cdt);
// The same form of faces given as vertex triples into `points` (a Model's vertices and faces).
std::vector<std::array<std::int32_t, 6>> canonical_faces(const std::vector<LatticePoint>& points,
                                                         const std::vector<std::array<VertInd, 3>>& faces);

}  // namespace erd
