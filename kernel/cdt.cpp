// Cdt core: reset, point insertion (splits + Lawson flips), change tracking. Point location lives
// in cdt_locate.cpp, constraint insertion in cdt_constraints.cpp, flips on request in
// cdt_flip.cpp, queries and verify() in cdt_query.cpp.
#include "kernel/cdt.h"

#include "kernel/spatial_order.h"

#include <algorithm>
#include <utility>

namespace erd {

void Cdt::reserve(std::size_t points) {
    points_.reserve(points + 4);
    out_.reserve(points + 4);
    grow_faces(2 * points + 8);
}

void Cdt::begin_change() {
    if (++change_id_ == 0) {  // wrapped: old stamps could collide
        std::fill(stamp_.begin(), stamp_.end(), 0u);
        change_id_ = 1;
    }
    changes_.destroyed.clear();
    changes_.created.clear();
    changes_.old_face_count = face_count();
    revived_.clear();
}

// The arrays are kept longer than face_count() and grown geometrically, so taking a slot is a
// counter increment (not a push_back with its capacity check per array). Slots past nfaces_ are
// all zero (a memset to grow): split_face relies on new faces' flags being 0 and stamps must not
// match a change id; vertices and twins of a new face are always written by its creator. Slots
// freed by remove_vertex come first; their flags are 0 too (cdt_remove.cpp).
FaceInd Cdt::new_face() {
    if (free_faces_.empty()) return append_faces(1);
    const FaceInd f = free_faces_.back();
    free_faces_.pop_back();
    // The slot held no triangle when the call began: created, not destroyed.
    if (tracking_ != Tracking::none && stamp_[f] != change_id_) {
        stamp_[f] = change_id_;
        if (tracking_ == Tracking::lists) changes_.created.push_back(f);
        else revived_.push_back(f);
    }
    return f;
}

FaceInd Cdt::append_faces(FaceInd n) {
    const FaceInd f = nfaces_;
    nfaces_ += n;
    if (stamp_.size() < nfaces_) grow_faces(std::max<std::size_t>(nfaces_, 2 * stamp_.size()));
    return f;
}

// Two slots for a split; appended together when none is free (the common case).
void Cdt::new_face_pair(FaceInd* a, FaceInd* b) {
    if (free_faces_.empty()) {
        *a = append_faces(2);
        *b = *a + 1;
        return;
    }
    *a = new_face();
    *b = new_face();
}

void Cdt::grow_faces(std::size_t faces) {
    if (stamp_.size() >= faces) return;
    vert_.resize(3 * faces);
    twin_.resize(3 * faces);
    flags_.resize(3 * faces);
    stamp_.resize(faces);
}

void Cdt::set_face(FaceInd f, VertInd a, VertInd b, VertInd c) {
    const EdgeInd e = 3 * f;
    vert_[e] = a;
    vert_[e + 1] = b;
    vert_[e + 2] = c;
    out_[a] = e;
    out_[b] = e + 1;
    out_[c] = e + 2;
    touch(f);
}

namespace {
// Makes e and t twins (t may be noEdge) in the raw twin array T: the hot paths (flip,
// split_face) work on local array pointers.
inline void link_twins(EdgeInd* T, EdgeInd e, EdgeInd t) {
    T[e] = t;
    if (t != noEdge) T[t] = e;
}
}  // namespace

void Cdt::link(EdgeInd e, EdgeInd t) { link_twins(twin_.data(), e, t); }

Status Cdt::reset(std::int32_t max_x, std::int32_t max_y) {
    if (max_x < 1 || max_y < 1 || max_x >= kMaxCoord || max_y >= kMaxCoord)
        return Status::bad_input("triangulation rectangle " + std::to_string(max_x) + "x" + std::to_string(max_y) +
                                 " (doubled) outside 1.." + std::to_string(kMaxCoord - 1));
    max_x_ = max_x;
    max_y_ = max_y;
    small_ = max_x < kSmallCoord && max_y < kSmallCoord;
    points_.clear();
    out_.clear();
    vert_.clear();
    twin_.clear();
    flags_.clear();
    segments_.clear();
    stamp_.clear();
    free_faces_.clear();
    nfaces_ = 0;
    dead_vertices_ = 0;
    delaunay_ = true;
    change_id_ = 0;
    last_face_ = 0;
    begin_change();
    add_vertex({0, 0});
    add_vertex({max_x, 0});
    add_vertex({max_x, max_y});
    add_vertex({0, max_y});
    const FaceInd f0 = new_face(), f1 = new_face();
    set_face(f0, 0, 1, 2);
    set_face(f1, 0, 2, 3);
    for (EdgeInd e = 0; e < 6; ++e) twin_[e] = noEdge;
    link(3 * f0 + 2, 3 * f1 + 0);
    // The four corners are cocircular: the tie rule picks the diagonal.
    if (is_illegal(3 * f0 + 2)) flip(3 * f0 + 2);
    return Status::success();
}

VertInd Cdt::add_vertex(LatticePoint p) {
    points_.push_back(p);
    out_.push_back(noEdge);
    return static_cast<VertInd>(points_.size() - 1);
}

bool Cdt::is_illegal(EdgeInd e) const {
    const EdgeInd t = twin_[e];
    if (t == noEdge || flags_[e]) return false;
    const LatticePoint a = points_[vert_[e]], b = points_[vert_[t]];
    const LatticePoint c = points_[vert_[prev_edge(e)]], d = points_[vert_[prev_edge(t)]];
    return incircle_perturbed(a, b, c, d, small_) > 0;
}

// Raw pointers on purpose: flags_ is a byte array, and a store through a byte pointer may alias
// anything, which would make the compiler reload every vector's data pointer after each flag store.
EdgeInd Cdt::flip(EdgeInd e) {
    VertInd* const V = vert_.data();
    EdgeInd* const T = twin_.data();
    std::uint8_t* const F = flags_.data();
    EdgeInd* const O = out_.data();
    // Corner offsets from tables: next_edge/prev_edge compiled to data-dependent branches here.
    static constexpr EdgeInd kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
    const EdgeInd t = T[e];
    const EdgeInd g1 = 3 * face_of(e), g2 = 3 * face_of(t);
    const EdgeInd ebc = g1 + kNext[e - g1], eca = g1 + kPrev[e - g1], ead = g2 + kNext[t - g2], edb = g2 + kPrev[t - g2];
    const VertInd a = V[e], b = V[t], c = V[eca], d = V[edb];
    const EdgeInd tbc = T[ebc], tca = T[eca], tad = T[ead], tdb = T[edb];
    const std::uint8_t fbc = F[ebc], fca = F[eca], fad = F[ead], fdb = F[edb];
    V[g1] = c;
    V[g1 + 1] = a;
    V[g1 + 2] = d;
    V[g2] = d;
    V[g2 + 1] = b;
    V[g2 + 2] = c;
    O[a] = g1 + 1;
    O[b] = g2 + 1;
    O[c] = g1;
    O[d] = g2;
    link_twins(T, g1, tca);
    link_twins(T, g1 + 1, tad);
    link_twins(T, g2, tdb);
    link_twins(T, g2 + 1, tbc);
    T[g1 + 2] = g2 + 2;
    T[g2 + 2] = g1 + 2;
    F[g1] = fca;
    F[g1 + 1] = fad;
    F[g1 + 2] = 0;
    F[g2] = fdb;
    F[g2 + 1] = fbc;
    F[g2 + 2] = 0;
    touch(g1 / 3);
    touch(g2 / 3);
    return g1 + 2;
}

// Lawson flips after a split: seeds[0..count) are the edges opposite the new vertex p
// (p = org(prev(e))), the last one processed first. A flip of such an edge creates two faces
// around p whose opposite edges are pushed in turn; the other stack entries live in other faces of
// p's star, which a flip never touches. The stack is a reused array with an index: vector
// push_back/pop_back here cost a capacity check each and kept the loop from being inlined.
void Cdt::legalize_around(VertInd p, const EdgeInd* seeds, unsigned count) {
    if (stack_.size() < 64) stack_.resize(64);
    EdgeInd* S = stack_.data();
    std::size_t n = 0;
    for (unsigned i = 0; i < count; ++i) S[n++] = seeds[i];
    // Local array pointers: flip() never resizes them, but the compiler cannot know that and
    // would reload every vector after each call.
    const VertInd* const V = vert_.data();
    const EdgeInd* const T = twin_.data();
    const std::uint8_t* const F = flags_.data();
    const LatticePoint* const P = points_.data();
    const bool small = small_;
    const LatticePoint pp = P[p];
    while (n > 0) {
        const EdgeInd e = S[--n];
        const EdgeInd t = T[e];
        if (t == noEdge || F[e]) continue;
        if (incircle_perturbed(P[V[e]], P[V[t]], pp, P[V[prev_edge(t)]], small) <= 0) continue;
        const EdgeInd diag = flip(e);  // d->c in f1 = (c=p, a, d); f2 = (d, b, p)
        const FaceInd f1 = face_of(diag), f2 = face_of(T[diag]);
        if (n + 2 > stack_.size()) {
            stack_.resize(2 * stack_.size());
            S = stack_.data();
        }
        S[n++] = 3 * f1 + 1;  // a->d
        S[n++] = 3 * f2 + 0;  // d->b
    }
}

// Face f = (a,b,c) becomes (a,b,p), (b,c,p), (c,a,p). Written out on raw arrays (set_face and
// link per corner reloaded every array pointer after each byte store); the final out_ entries,
// twins, flags and touch order are those of set_face(f), set_face(n1), set_face(n2) + links.
void Cdt::split_face(FaceInd f, VertInd p) {
    FaceInd n1, n2;
    new_face_pair(&n1, &n2);  // may grow the arrays: take pointers after it
    VertInd* const V = vert_.data();
    EdgeInd* const T = twin_.data();
    std::uint8_t* const F = flags_.data();
    EdgeInd* const O = out_.data();
    const EdgeInd e = 3 * f, e1 = 3 * n1, e2 = 3 * n2;
    const VertInd a = V[e], b = V[e + 1], c = V[e + 2];
    const EdgeInd tbc = T[e + 1], tca = T[e + 2];
    const std::uint8_t fbc = F[e + 1], fca = F[e + 2];
    V[e + 2] = p;  // f = (a, b, p) keeps a->b with its twin and flag
    V[e1] = b;
    V[e1 + 1] = c;
    V[e1 + 2] = p;
    V[e2] = c;
    V[e2 + 1] = a;
    V[e2 + 2] = p;
    O[a] = e2 + 1;
    O[b] = e1;
    O[c] = e2;
    O[p] = e2 + 2;
    link_twins(T, e1, tbc);
    link_twins(T, e2, tca);
    T[e + 1] = e1 + 2;
    T[e1 + 2] = e + 1;
    T[e1 + 1] = e2 + 2;
    T[e2 + 2] = e1 + 1;
    T[e2 + 1] = e + 2;
    T[e + 2] = e2 + 1;
    F[e1] = fbc;  // the other new corners are zero already (new_face)
    F[e2] = fca;
    F[e + 1] = 0;
    F[e + 2] = 0;
    touch(f);
    touch(n1);
    touch(n2);
    const EdgeInd seeds[3] = {e, e1, e2};
    legalize_around(p, seeds, 3);
}

// Half-edge e = a->b of f = (a,b,c), twin b->a of g = (b,a,d), gets p in its interior:
//   f = (c,a,p), n1 = (c,p,b), g = (d,b,p), n2 = (d,p,a).
// The halves a->p, p->b inherit the constrained flag. Both sides are legalised, so a point on a
// constrained edge finds its conflicts on both sides (the CGAL 3.5.1 bug of thesis A.6).
void Cdt::split_edge(EdgeInd e, VertInd p) {
    const EdgeInd t = twin_[e];
    const FaceInd f = face_of(e);
    const VertInd a = vert_[e], b = vert_[next_edge(e)], c = vert_[prev_edge(e)];
    const EdgeInd ebc = next_edge(e), eca = prev_edge(e);
    const EdgeInd tbc = twin_[ebc], tca = twin_[eca];
    const std::uint8_t fbc = flags_[ebc], fca = flags_[eca], fe = flags_[e];
    FaceInd g = noFace;
    VertInd d = noVertex;
    EdgeInd tad = noEdge, tdb = noEdge;
    std::uint8_t fad = 0, fdb = 0;
    if (t != noEdge) {
        g = face_of(t);
        d = vert_[prev_edge(t)];
        const EdgeInd ead = next_edge(t), edb = prev_edge(t);
        tad = twin_[ead];
        tdb = twin_[edb];
        fad = flags_[ead];
        fdb = flags_[edb];
    }
    FaceInd n1 = noFace, n2 = noFace;
    if (t != noEdge)
        new_face_pair(&n1, &n2);
    else
        n1 = new_face();
    split_side(f, n1, c, a, b, p, tca, fca, tbc, fbc, fe);
    EdgeInd seeds[4] = {3 * f + 0, 3 * n1 + 2, noEdge, noEdge};
    if (t != noEdge) {
        split_side(g, n2, d, b, a, p, tdb, fdb, tad, fad, fe);
        link(3 * f + 1, 3 * n2 + 1);
        link(3 * n1 + 1, 3 * g + 1);
        seeds[2] = 3 * g + 0;
        seeds[3] = 3 * n2 + 2;
    } else {
        twin_[3 * f + 1] = noEdge;
        twin_[3 * n1 + 1] = noEdge;
    }
    legalize_around(p, seeds, t != noEdge ? 4 : 2);
}

// One side of split_edge: face f = (x, u, w), whose edge u->w gets p, becomes f = (x, u, p) and
// n = (x, p, w). txu, fxu: the twin and flag of the old edge x->u; twx, fwx: of w->x; fe: the
// split edge's flag, which both halves u->p, p->w inherit (their twins are the other side's).
void Cdt::split_side(FaceInd f, FaceInd n, VertInd x, VertInd u, VertInd w, VertInd p, EdgeInd txu, std::uint8_t fxu,
                     EdgeInd twx, std::uint8_t fwx, std::uint8_t fe) {
    set_face(f, x, u, p);
    set_face(n, x, p, w);
    link(3 * f + 0, txu);
    flags_[3 * f + 0] = fxu;
    link(3 * n + 2, twx);
    flags_[3 * n + 2] = fwx;
    link(3 * f + 2, 3 * n + 0);
    flags_[3 * f + 2] = 0;
    flags_[3 * n + 0] = 0;
    flags_[3 * f + 1] = fe;
    flags_[3 * n + 1] = fe;
}

Status Cdt::insert_point(LatticePoint p, VertInd* v, FaceInd hint) {
    begin_change();
    return insert_one(p, v, hint);
}

// insert_point without starting a new change report (insert_points accumulates one).
Status Cdt::insert_one(LatticePoint p, VertInd* v, FaceInd hint) {
    if (face_count() == 0) return Status::failure("triangulation not initialised (call reset first)");
    if (p.x < 0 || p.y < 0 || p.x > max_x_ || p.y > max_y_)
        return Status::bad_input("point (" + std::to_string(p.x) + "," + std::to_string(p.y) +
                                 ") outside the rectangle [0," + std::to_string(max_x_) + "]x[0," +
                                 std::to_string(max_y_) + "]");
    if (points_.size() >= std::size_t(noVertex / 8)) return Status::failure("triangulation too large");
    const VertInd nv = insert_at(p, locate(p, hint));
    if (nv == noVertex) return Status::failure("point location failed");
    if (v) *v = nv;
    return Status::success();
}

// The checked insertion's core: p (inside the rectangle) at its location loc. Returns the new or
// existing vertex, noVertex when loc is outside.
VertInd Cdt::insert_at(LatticePoint p, const Location& loc) {
    if (loc.kind == Location::Kind::on_vertex) return loc.vertex;
    if (loc.kind == Location::Kind::outside) return noVertex;
    const VertInd nv = add_vertex(p);
    if (loc.kind == Location::Kind::in_face)
        split_face(loc.face, nv);
    else
        split_edge(loc.edge, nv);
    last_face_ = face_of(out_[nv]);
    return nv;
}

Status Cdt::insert_points(const std::vector<LatticePoint>& pts, std::vector<VertInd>* v, bool report_changes) {
    begin_change();
    if (face_count() == 0) return Status::failure("triangulation not initialised (call reset first)");
    if (points_.size() + pts.size() >= std::size_t(noVertex / 8)) return Status::failure("triangulation too large");
    for (const LatticePoint& p : pts)
        if (p.x < 0 || p.y < 0 || p.x > max_x_ || p.y > max_y_)
            return Status::bad_input("point (" + std::to_string(p.x) + "," + std::to_string(p.y) +
                                     ") outside the rectangle");
    if (pts.empty()) {
        if (v) v->clear();
        return Status::success();
    }
    int bits = 1;
    while ((std::int64_t(1) << bits) <= std::max(max_x_, max_y_)) ++bits;
    brio_order(pts, bits, &sort_buf_, &sort_tmp_);
    if (v) v->assign(pts.size(), noVertex);
    reserve(points_.size() + pts.size());
    tracking_ = report_changes ? Tracking::stamps : Tracking::none;
    // Every point was checked above, so each is located by a walk from the previous insertion's
    // face (what insert_point does with that hint) and inserted without insert_point's checks.
    Status st;
    for (const std::uint64_t index : sort_buf_) {
        const LatticePoint p = pts[index];
        const VertInd nv = insert_at(p, walk_as<true>(p, last_face_));
        if (nv == noVertex) {
            st = Status::failure("point location failed");
            break;
        }
        if (v) (*v)[index] = nv;
    }
    tracking_ = Tracking::lists;
    if (!report_changes) return st;
    std::sort(revived_.begin(), revived_.end());  // freed slots taken: created, not destroyed
    std::size_t r = 0;
    for (FaceInd f = 0; f < face_count(); ++f) {
        if (stamp_[f] != change_id_) continue;
        changes_.created.push_back(f);
        if (r < revived_.size() && revived_[r] == f) {
            ++r;
            continue;
        }
        if (f < changes_.old_face_count) changes_.destroyed.push_back(f);
    }
    return st;
}

}  // namespace erd
