// Differential testing of erd's Cdt against CGAL's Constrained_Delaunay_triangulation_2 (issue
// 49): the same operations go to both and to a model of erd's constraint policy, and the results
// are compared exactly. Used by tests/cgal/test_cgal_diff.cpp and fuzz/fuzz_cgal_diff.cpp.
//
// What "the same" means. The vertex sets and the constrained edges must be equal, and so must the
// triangle counts. Both must pass the exact Delaunay check (no vertex strictly inside the circle
// of a neighbouring face across an unconstrained edge), and erd its own verify(). A (constrained)
// Delaunay triangulation is unique up to cocircular ties: removing every unconstrained interior
// edge whose two faces are cocircular (incircle exactly 0) leaves the constrained Delaunay
// subdivision, which is unique, so those edges must be equal (where no four points are cocircular
// that is triangle for triangle). Ties: erd breaks them by its symbolic perturbation, CGAL by its
// own; given mirrored points (mirror() below) CGAL's rule is erd's, so the triangles must then be
// the same, ties included: the check that sees a wrong tie rule.
//
// Constraints: CGAL splits crossing constraints at their crossing (a new vertex), erd drops the
// later piece (kernel/cdt.h, ConstraintReport). The model below applies erd's policy on its own:
// it splits each segment at the vertices on it, classifies each piece as already constrained,
// crossing (dropped) or new, checks erd's counts against that, and only the new pieces go to CGAL.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "kernel/cdt.h"
#include "kernel/predicates.h"
#include "third_party/cgal_glue.h"

namespace cgal_diff {

using erd::LatticePoint;
using Face = std::array<LatticePoint, 3>;
using Seg = std::array<LatticePoint, 2>;

inline std::string str(LatticePoint p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }
inline bool less(LatticePoint a, LatticePoint b) { return erd::perturb_before(a, b); }
inline Seg seg(LatticePoint a, LatticePoint b) { return less(b, a) ? Seg{b, a} : Seg{a, b}; }
inline bool seg_less(const Seg& s, const Seg& t) {
    return s[0] != t[0] ? less(s[0], t[0]) : less(s[1], t[1]);
}

// What a comparison found: an empty `difference` means equal.
struct Result {
    std::string difference;
    std::size_t faces = 0;
    std::size_t tie_edges = 0;  // erd's unconstrained interior edges with 4 cocircular points
    bool same_triangles = false;  // triangle for triangle, ties included
};

// A triangulation as coordinates with its edges: for each (smaller, larger) edge the opposite
// vertices of its one or two faces.
struct Edges {
    std::map<Seg, std::vector<LatticePoint>, bool (*)(const Seg&, const Seg&)> opposite{seg_less};
};

inline Edges edges_of(const std::vector<Face>& faces) {
    Edges e;
    for (const Face& f : faces)
        for (int i = 0; i < 3; ++i) e.opposite[seg(f[i], f[(i + 1) % 3])].push_back(f[(i + 2) % 3]);
    return e;
}

// The subdivision edges (tie edges left out), counting the tie edges; "" or the first edge
// violating the exact Delaunay condition.
inline std::string subdivision(const std::vector<Face>& faces, const std::vector<Seg>& constrained,
                               std::vector<Seg>* out, std::size_t* ties) {
    const Edges e = edges_of(faces);
    out->clear();
    *ties = 0;
    for (const auto& [s, opp] : e.opposite) {
        if (opp.size() > 2) return "edge " + str(s[0]) + "-" + str(s[1]) + " in more than two faces";
        const bool con = std::binary_search(constrained.begin(), constrained.end(), s, seg_less);
        if (opp.size() == 2 && !con) {
            // Orient (s0, s1, opp0) positively, then test opp1 against its circle.
            LatticePoint a = s[0], b = s[1];
            if (erd::orient2d(a, b, opp[0]) < 0) std::swap(a, b);
            const __int128 in = erd::incircle(a, b, opp[0], opp[1]);
            if (in > 0) return "edge " + str(s[0]) + "-" + str(s[1]) + " not Delaunay";
            if (in == 0) {
                ++*ties;
                continue;
            }
        }
        out->push_back(s);
    }
    return "";
}

inline std::vector<Face> faces_of(const erd::Cdt& cdt) {
    std::vector<std::array<erd::VertInd, 3>> f;
    cdt.export_faces(&f);
    std::vector<Face> out;
    for (const auto& t : f) out.push_back({cdt.point(t[0]), cdt.point(t[1]), cdt.point(t[2])});
    return out;
}

inline std::vector<Seg> constrained_of(const erd::Cdt& cdt) {
    std::vector<std::array<erd::VertInd, 2>> c;
    cdt.export_constraints(&c);
    std::vector<Seg> out;
    for (const auto& e : c) out.push_back(seg(cdt.point(e[0]), cdt.point(e[1])));
    std::sort(out.begin(), out.end(), seg_less);
    return out;
}

// Faces as sorted point triples, sorted: equal iff the same triangles.
inline std::vector<Face> sorted_faces(std::vector<Face> faces) {
    for (Face& f : faces) std::sort(f.begin(), f.end(), less);
    std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
        for (int i = 0; i < 3; ++i)
            if (a[i] != b[i]) return less(a[i], b[i]);
        return false;
    });
    return faces;
}

inline Result compare(const erd::Cdt& cdt, const cgal_glue::Mesh& m) {
    Result r;
    std::string why;
    if (!cdt.verify(&why)) {
        r.difference = "erd verify: " + why;
        return r;
    }
    std::vector<LatticePoint> ve, vc = m.vertices;
    for (erd::VertInd v = 0; v < cdt.vertex_count(); ++v)
        if (cdt.vertex_live(v)) ve.push_back(cdt.point(v));
    std::sort(ve.begin(), ve.end(), less);
    std::sort(vc.begin(), vc.end(), less);
    if (ve != vc) {
        r.difference = "vertex sets differ (erd " + std::to_string(ve.size()) + ", CGAL " + std::to_string(vc.size()) + ")";
        return r;
    }
    const std::vector<Seg> ce = constrained_of(cdt);
    std::vector<Seg> cc;
    for (const Seg& s : m.constrained) cc.push_back(seg(s[0], s[1]));
    std::sort(cc.begin(), cc.end(), seg_less);
    if (ce != cc) {
        r.difference = "constrained edges differ (erd " + std::to_string(ce.size()) + ", CGAL " + std::to_string(cc.size()) + ")";
        return r;
    }
    const std::vector<Face> fe = faces_of(cdt);
    r.faces = fe.size();
    if (fe.size() != m.faces.size()) {
        r.difference = "triangle counts differ (erd " + std::to_string(fe.size()) + ", CGAL " + std::to_string(m.faces.size()) + ")";
        return r;
    }
    std::vector<Seg> se, sc;
    std::size_t tc = 0;
    std::string bad = subdivision(fe, ce, &se, &r.tie_edges);
    if (!bad.empty()) {
        r.difference = "erd: " + bad;
        return r;
    }
    bad = subdivision(m.faces, cc, &sc, &tc);
    if (!bad.empty()) {
        r.difference = "CGAL: " + bad;
        return r;
    }
    if (se != sc) {
        r.difference = "Delaunay subdivisions differ (" + std::to_string(se.size()) + " and " + std::to_string(sc.size()) + " edges)";
        return r;
    }
    r.same_triangles = sorted_faces(fe) == sorted_faces(m.faces);
    if (!r.same_triangles) r.difference = "triangles differ at cocircular points: the tie rules disagree";
    return r;
}

// Ties. CGAL breaks them by its own symbolic perturbation (Triangulation_2::side_of_oriented_circle):
// of the four points, the largest in (x, y) order decides; erd's (predicates.h) lets the smallest in
// (Y, X) order decide, by the same terms. CGAL is given every point mirrored, (x, y) -> (-y, -x),
// which makes its order erd's; a mirror flips every orientation and CGAL orders each face
// positively again, so the two rules agree term for term, and where both build the unique
// perturbed CDT the triangles are the same, ties included (Result::same_triangles).
inline LatticePoint mirror(LatticePoint p) { return {-p.y, -p.x}; }  // its own inverse

inline cgal_glue::Mesh unmirror(cgal_glue::Mesh m) {
    for (LatticePoint& p : m.vertices) p = mirror(p);
    for (Face& f : m.faces) f = {mirror(f[0]), mirror(f[2]), mirror(f[1])};
    for (Seg& s : m.constrained) s = {mirror(s[0]), mirror(s[1])};
    return m;
}

// erd's constraint policy on its own terms (see the top).
class PolicyModel {
public:
    void insert_point(LatticePoint p) {
        if (std::find(points_.begin(), points_.end(), p) == points_.end()) points_.push_back(p);
    }
    void remove_point(LatticePoint p) { points_.erase(std::find(points_.begin(), points_.end(), p)); }
    // True when p lies on an accepted segment (an end or inside): erd must refuse to remove it.
    bool on_constraint(LatticePoint p) const {
        for (const Seg& s : accepted_)
            if (on_closed(s, p)) return true;
        return false;
    }
    // Splits a-b at the vertices on it and classifies the pieces; the new ones are accepted and
    // appended to *fresh.
    erd::ConstraintReport insert_constraint(LatticePoint a, LatticePoint b, std::vector<Seg>* fresh) {
        erd::ConstraintReport r;
        if (a == b) return r;
        std::vector<LatticePoint> on{a, b};
        for (const LatticePoint p : points_)
            if (p != a && p != b && on_closed({a, b}, p)) on.push_back(p);
        const std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
        std::sort(on.begin(), on.end(), [&](LatticePoint p, LatticePoint q) {
            return (p.x - a.x) * dx + (p.y - a.y) * dy < (q.x - a.x) * dx + (q.y - a.y) * dy;
        });
        for (std::size_t i = 0; i + 1 < on.size(); ++i) {
            const Seg piece{on[i], on[i + 1]};
            ++r.pieces;
            bool already = false, crossing = false;
            for (const Seg& s : accepted_) {
                if (on_closed(s, piece[0]) && on_closed(s, piece[1])) already = true;
                if (crosses(s, piece)) crossing = true;
            }
            if (already) {
                ++r.already;
            } else if (crossing) {
                ++r.dropped_crossing;
            } else {
                ++r.inserted;
                accepted_.push_back(piece);
                fresh->push_back(piece);
            }
        }
        return r;
    }

private:
    static bool on_closed(const Seg& s, LatticePoint p) {
        if (erd::orient2d(s[0], s[1], p) != 0) return false;
        return std::min(s[0].x, s[1].x) <= p.x && p.x <= std::max(s[0].x, s[1].x) && std::min(s[0].y, s[1].y) <= p.y &&
               p.y <= std::max(s[0].y, s[1].y);
    }
    static int sgn(std::int64_t v) { return (v > 0) - (v < 0); }
    // Open segments crossing at one point interior to both.
    static bool crosses(const Seg& s, const Seg& t) {
        const int a = sgn(erd::orient2d(s[0], s[1], t[0])), b = sgn(erd::orient2d(s[0], s[1], t[1]));
        const int c = sgn(erd::orient2d(t[0], t[1], s[0])), d = sgn(erd::orient2d(t[0], t[1], s[1]));
        return a * b < 0 && c * d < 0;
    }
    std::vector<LatticePoint> points_;
    std::vector<Seg> accepted_;
};

// One input run through erd, CGAL and the policy model; each call returns "" or what differed.
class Differential {
public:
    // scan_limit: Cdt::set_removal_scan_limit (both hole methods are compared).
    Differential(std::int32_t max_x, std::int32_t max_y, std::uint32_t scan_limit = 10) {
        ok_ = cdt_.reset(max_x, max_y).ok();
        cdt_.set_removal_scan_limit(scan_limit);
        for (const LatticePoint c : {LatticePoint{0, 0}, LatticePoint{max_x, 0}, LatticePoint{max_x, max_y}, LatticePoint{0, max_y}}) {
            cgal_.insert(mirror(c));
            model_.insert_point(c);
        }
    }
    std::string insert_point(LatticePoint p) {
        if (!ok_) return "reset failed";
        if (!cdt_.insert_point(p, nullptr).ok()) return "erd refused point " + str(p);
        cgal_.insert(mirror(p));
        model_.insert_point(p);
        return "";
    }
    std::string insert_constraint(LatticePoint a, LatticePoint b) {
        const erd::Location la = cdt_.locate(a), lb = cdt_.locate(b);
        if (la.kind != erd::Location::Kind::on_vertex || lb.kind != erd::Location::Kind::on_vertex)
            return "constraint ends are no vertices";
        erd::ConstraintReport got;
        if (!cdt_.insert_constraint(la.vertex, lb.vertex, &got).ok()) return "erd refused constraint";
        std::vector<Seg> fresh;
        const erd::ConstraintReport want = model_.insert_constraint(a, b, &fresh);
        if (got.pieces != want.pieces || got.inserted != want.inserted || got.already != want.already ||
            got.dropped_crossing != want.dropped_crossing)
            return "constraint " + str(a) + "-" + str(b) + ": erd's pieces differ from the policy";
        for (const Seg& s : fresh) cgal_.insert_constraint(mirror(s[0]), mirror(s[1]));
        dropped_ += want.dropped_crossing;
        return "";
    }
    // Removes the vertex at p from both (when erd and the policy agree it is removable).
    std::string remove(LatticePoint p, bool* removed) {
        *removed = false;
        const erd::Location l = cdt_.locate(p);
        if (l.kind != erd::Location::Kind::on_vertex) return "";
        const bool corner = l.vertex < 4, can = cdt_.can_remove(l.vertex);
        if (can != (!corner && !model_.on_constraint(p))) return "erd and the policy disagree on removing " + str(p);
        if (!can) return cdt_.remove_vertex(l.vertex).ok() ? "erd removed a vertex it should refuse" : "";
        if (!cdt_.remove_vertex(l.vertex).ok()) return "erd failed to remove " + str(p);
        if (!cgal_.remove(mirror(p))) return "CGAL failed to remove " + str(p);
        model_.remove_point(p);
        *removed = true;
        return "";
    }
    Result compare() const { return cgal_diff::compare(cdt_, unmirror(cgal_.mesh())); }
    const erd::Cdt& cdt() const { return cdt_; }
    std::uint32_t dropped() const { return dropped_; }

private:
    bool ok_ = false;
    erd::Cdt cdt_;
    cgal_glue::ConstrainedDelaunay cgal_;
    PolicyModel model_;
    std::uint32_t dropped_ = 0;
};

}  // namespace cgal_diff
