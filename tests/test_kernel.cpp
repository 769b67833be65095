// Tests of the geometry kernel: exact predicates and the constrained Delaunay triangulation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "kernel/cdt.h"
#include "tests/cdt_util.h"
#include "tests/test_cdt_util.h"
#include "kernel/predicates.h"
#include "kernel/spatial_order.h"

using namespace erd;

using cdt_util::constraint_coords;

namespace {

// Builds a CDT or fails the test.
void must_reset(Cdt& cdt, int mx, int my) {
    const Status s = cdt.reset(mx, my);
    REQUIRE(s.ok());
}

VertInd must_insert(Cdt& cdt, LatticePoint p, FaceInd hint = noFace) {
    VertInd v = noVertex;
    const Status s = cdt.insert_point(p, &v, hint);
    INFO(s.message);
    REQUIRE(s.ok());
    return v;
}

std::uint32_t rnd(std::mt19937& g, std::uint32_t n) { return static_cast<std::uint32_t>(g() % n); }

template <class T>
void shuffle(std::vector<T>& v, std::mt19937& g) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rnd(g, static_cast<std::uint32_t>(i))]);
}

std::array<std::int32_t, 6> face_coords(const Cdt& cdt, FaceInd f) {
    std::array<std::int32_t, 6> r{};
    for (int i = 0; i < 3; ++i) {
        r[size_t(2 * i)] = cdt.point(cdt.face_vertex(f, i)).x;
        r[size_t(2 * i + 1)] = cdt.point(cdt.face_vertex(f, i)).y;
    }
    return r;
}

}  // namespace

TEST_CASE("orient2d and incircle are exact at the extreme allowed coordinates", "[kernel]") {
    const std::int32_t M = kMaxCoord - 1;
    const LatticePoint a{0, 0}, b{M, 0}, c{0, M}, d{M, M};
    CHECK(orient2d(a, b, c) == std::int64_t(M) * M);
    CHECK(orient2d(a, c, b) == -std::int64_t(M) * M);
    CHECK(orient2d(a, d, LatticePoint{M - 1, M - 1}) == 0);
    CHECK(orient2d(a, d, LatticePoint{M - 1, M - 2}) == -std::int64_t(M));
    // For the right triangle a, b, c the determinant is M^2 * (M x + M y - x^2 - y^2).
    auto expect = [&](std::int64_t x, std::int64_t y) {
        return __int128(M) * M * (__int128(M) * x + __int128(M) * y - __int128(x) * x - __int128(y) * y);
    };
    const LatticePoint probes[] = {{M, M}, {M - 1, M - 1}, {M, M - 1}, {1, 1}, {0, 0}, {M / 2, M / 2}, {M, 1}};
    for (LatticePoint p : probes) {
        INFO(p.x << "," << p.y);
        CHECK(incircle(a, b, c, p) == expect(p.x, p.y));
    }
    CHECK(incircle(a, b, c, d) == 0);
    CHECK(incircle(a, b, c, LatticePoint{M - 1, M - 1}) > 0);
    CHECK(incircle(a, b, c, LatticePoint{M, M - 1}) > 0);  // M^2 (M - 1): inside
    // Perturbed: d is exactly on the circle; the rule decides and is consistent from both sides.
    const int s1 = incircle_perturbed(b, c, a, d);  // edge b-c, opposite a and d
    const int s2 = incircle_perturbed(c, b, d, a);
    CHECK(s1 != 0);
    CHECK(s1 == s2);
    CHECK(coord_ok(LatticePoint{M, M}));
    CHECK_FALSE(coord_ok(LatticePoint{M + 1, 0}));
    CHECK_FALSE(coord_ok(LatticePoint{0, -1}));
}

TEST_CASE("the tie rule picks exactly one diagonal of every cocircular quadruple of a 2x2 pixel block", "[kernel]") {
    // All points of the doubled lattice of a 2x2-pixel block plus its half-pixel points: {0..4}^2.
    std::vector<LatticePoint> pts;
    for (int y = 0; y <= 4; ++y)
        for (int x = 0; x <= 4; ++x) pts.push_back({x, y});
    int cocircular = 0;
    const size_t n = pts.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k)
                for (size_t l = k + 1; l < n; ++l) {
                    std::array<LatticePoint, 4> q = {pts[i], pts[j], pts[k], pts[l]};
                    // Put them in counter-clockwise convex order if possible.
                    std::sort(q.begin() + 1, q.end(), [&](LatticePoint u, LatticePoint w) { return orient2d(q[0], u, w) > 0; });
                    bool convex = true;
                    for (int t = 0; t < 4; ++t)
                        if (orient2d(q[size_t(t)], q[size_t((t + 1) % 4)], q[size_t((t + 2) % 4)]) <= 0) convex = false;
                    if (!convex) continue;
                    if (incircle(q[0], q[1], q[2], q[3]) != 0) continue;
                    ++cocircular;
                    const LatticePoint a = q[0], b = q[1], c = q[2], d = q[3];
                    // Diagonal a-c: edge c->a in (a,b,c) opposite b, twin a->c in (a,c,d) opposite d.
                    const int ac1 = incircle_perturbed(c, a, b, d), ac2 = incircle_perturbed(a, c, d, b);
                    const int bd1 = incircle_perturbed(d, b, c, a), bd2 = incircle_perturbed(b, d, a, c);
                    REQUIRE(ac1 != 0);
                    REQUIRE(bd1 != 0);
                    CHECK(ac1 == ac2);
                    CHECK(bd1 == bd2);
                    CHECK((ac1 > 0) != (bd1 > 0));  // exactly one diagonal is illegal
                }
    CHECK(cocircular > 100);
}

TEST_CASE("reset builds the rectangle and checks the coordinate bound", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 10, 6);
    CHECK(cdt.vertex_count() == 4);
    CHECK(cdt.face_count() == 2);
    CHECK(cdt.point(2) == LatticePoint{10, 6});
    must_verify(cdt);
    CHECK_FALSE(cdt.reset(0, 5).ok());
    CHECK_FALSE(cdt.reset(5, kMaxCoord).ok());
    CHECK(cdt.reset(kMaxCoord - 1, kMaxCoord - 1).ok());
    must_verify(cdt);
    must_insert(cdt, {kMaxCoord - 2, 1});
    must_insert(cdt, {kMaxCoord / 2, kMaxCoord / 2});
    must_insert(cdt, {1, kMaxCoord - 2});
    must_verify(cdt);
}

TEST_CASE("a full 5x5 lattice inserted in 100 random orders gives one triangulation", "[kernel]") {
    std::vector<LatticePoint> pts;
    for (int y = 0; y <= 8; y += 2)
        for (int x = 0; x <= 8; x += 2) pts.push_back({x, y});
    std::mt19937 g(12345);
    std::vector<std::array<std::int32_t, 6>> first;
    for (int run = 0; run < 100; ++run) {
        shuffle(pts, g);
        Cdt cdt;
        must_reset(cdt, 8, 8);
        for (LatticePoint p : pts) must_insert(cdt, p);
        must_verify(cdt);
        CHECK(cdt.vertex_count() == 25);
        CHECK(cdt.face_count() == 32);  // 2n - 2 - h with h = 16 hull points
        const auto canon = canonical_faces(cdt);
        if (run == 0)
            first = canon;
        else
            REQUIRE(canon == first);
    }
}

TEST_CASE("the full doubled 9x9 lattice is order independent and batch insertion agrees", "[kernel]") {
    std::vector<LatticePoint> pts;
    for (int y = 0; y <= 8; ++y)
        for (int x = 0; x <= 8; ++x) pts.push_back({x, y});
    std::mt19937 g(777);
    Cdt ref;
    must_reset(ref, 8, 8);
    REQUIRE(ref.insert_points(pts, nullptr).ok());
    must_verify(ref);
    CHECK(ref.vertex_count() == 81);
    const auto canon = canonical_faces(ref);
    for (int run = 0; run < 20; ++run) {
        shuffle(pts, g);
        Cdt cdt;
        must_reset(cdt, 8, 8);
        for (LatticePoint p : pts) must_insert(cdt, p);
        REQUIRE(canonical_faces(cdt) == canon);
    }
}

TEST_CASE("duplicates return the existing vertex and change nothing", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 20, 20);
    const VertInd v = must_insert(cdt, {7, 9});
    CHECK(v == 4);
    const size_t nf = cdt.face_count();
    CHECK(must_insert(cdt, {7, 9}) == v);
    CHECK(cdt.changes().created.empty());
    CHECK(cdt.changes().destroyed.empty());
    CHECK(must_insert(cdt, {20, 20}) == 2);
    CHECK(must_insert(cdt, {0, 20}) == 3);
    CHECK(cdt.vertex_count() == 5);
    CHECK(cdt.face_count() == nf);
    VertInd w = 99;
    CHECK_FALSE(cdt.insert_point({21, 3}, &w).ok());
    CHECK_FALSE(cdt.insert_point({-1, 3}, &w).ok());
    must_verify(cdt);
}

TEST_CASE("points on edges and on the hull split them; changes() lists the slots", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 20, 20);
    must_insert(cdt, {10, 10});  // interior: +2 faces
    CHECK(cdt.face_count() == 4);
    must_insert(cdt, {10, 0});  // on the hull: +1 face
    CHECK(cdt.face_count() == 5);
    const auto& ch = cdt.changes();
    CHECK(ch.old_face_count == 4);
    CHECK(std::find(ch.created.begin(), ch.created.end(), FaceInd(4)) != ch.created.end());
    for (FaceInd f : ch.destroyed) CHECK(std::find(ch.created.begin(), ch.created.end(), f) != ch.created.end());
    must_insert(cdt, {5, 5});  // on the interior edge (0,0)-(10,10) if it exists, else in a face
    must_verify(cdt);
    const Location loc = cdt.locate({15, 15});
    CHECK(loc.kind == Location::Kind::on_edge);
    CHECK(cdt.locate({10, 10}).kind == Location::Kind::on_vertex);
    CHECK(cdt.locate({10, 10}).vertex == 4);
    CHECK(cdt.locate({11, 10}).kind == Location::Kind::in_face);
    CHECK(cdt.locate({21, 10}).kind == Location::Kind::outside);
    // Every created face is reported once; every face not reported is unchanged.
    std::vector<std::array<std::int32_t, 6>> before;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) before.push_back(face_coords(cdt, f));
    must_insert(cdt, {13, 4});
    std::set<FaceInd> created(cdt.changes().created.begin(), cdt.changes().created.end());
    CHECK(created.size() == cdt.changes().created.size());
    for (FaceInd f = 0; f < before.size(); ++f)
        if (!created.count(f)) CHECK(face_coords(cdt, f) == before[f]);
    CHECK(cdt.face_count() == before.size() + 2);
}

TEST_CASE("a point on a constrained edge splits it and finds its conflicts on both sides (thesis A.6)", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 40, 40);
    const VertInd a = must_insert(cdt, {0, 20});
    const VertInd b = must_insert(cdt, {40, 20});
    // Points close above and below the middle: their faces' circumcircles contain (20,20).
    must_insert(cdt, {16, 23});
    must_insert(cdt, {24, 23});
    must_insert(cdt, {18, 16});
    must_insert(cdt, {23, 17});
    must_insert(cdt, {20, 30});
    must_insert(cdt, {20, 9});
    ConstraintReport rep;
    REQUIRE(cdt.insert_constraint(a, b, &rep).ok());
    CHECK(rep.inserted == 1);
    must_verify(cdt);
    const LatticePoint p{20, 20};
    // Faces whose circumcircle strictly contains p; nothing blocks visibility but the constraint p
    // lies on, so all of them must be destroyed.
    std::set<std::array<std::int32_t, 6>> conflict_above, conflict_below;
    std::vector<std::array<std::int32_t, 6>> before;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        before.push_back(face_coords(cdt, f));
        const LatticePoint q0 = cdt.point(cdt.face_vertex(f, 0)), q1 = cdt.point(cdt.face_vertex(f, 1)),
                           q2 = cdt.point(cdt.face_vertex(f, 2));
        if (incircle(q0, q1, q2, p) > 0) {
            const int ymax = std::max({q0.y, q1.y, q2.y}), ymin = std::min({q0.y, q1.y, q2.y});
            if (ymax > 20) conflict_above.insert(face_coords(cdt, f));
            if (ymin < 20) conflict_below.insert(face_coords(cdt, f));
        }
    }
    REQUIRE(conflict_above.size() >= 2);
    REQUIRE(conflict_below.size() >= 2);
    const VertInd v = must_insert(cdt, p);
    must_verify(cdt);
    std::set<std::array<std::int32_t, 6>> destroyed;
    for (FaceInd f : cdt.changes().destroyed) destroyed.insert(before[f]);
    for (const auto& f : conflict_above) CHECK(destroyed.count(f) == 1);
    for (const auto& f : conflict_below) CHECK(destroyed.count(f) == 1);
    // Every created face has the new vertex (the cavity is star-shaped from p).
    for (FaceInd f : cdt.changes().created) {
        const bool has = cdt.face_vertex(f, 0) == v || cdt.face_vertex(f, 1) == v || cdt.face_vertex(f, 2) == v;
        CHECK(has);
    }
    // Both halves constrained.
    const EdgeInd ea = cdt.find_edge(a, v), eb = cdt.find_edge(v, b);
    REQUIRE(ea != noEdge);
    REQUIRE(eb != noEdge);
    CHECK(cdt.constrained(ea));
    CHECK(cdt.constrained(eb));
    // The same sets inserted in another order give the same triangulation.
    Cdt other;
    must_reset(other, 40, 40);
    for (LatticePoint q : {LatticePoint{20, 9}, LatticePoint{20, 20}, LatticePoint{0, 20}, LatticePoint{23, 17},
                           LatticePoint{40, 20}, LatticePoint{16, 23}, LatticePoint{24, 23}, LatticePoint{18, 16},
                           LatticePoint{20, 30}})
        must_insert(other, q);
    REQUIRE(other.insert_constraint(other.locate({40, 20}).vertex, other.locate({0, 20}).vertex).ok());
    CHECK(canonical_faces(other) == canonical_faces(cdt));
    CHECK(constraint_coords(other) == constraint_coords(cdt));
}

TEST_CASE("constraints are split at the vertices lying on them", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 20, 20);
    must_insert(cdt, {5, 5});
    must_insert(cdt, {10, 10});
    must_insert(cdt, {15, 15});
    must_insert(cdt, {3, 14});
    must_insert(cdt, {16, 2});
    must_insert(cdt, {10, 4});
    ConstraintReport rep;
    REQUIRE(cdt.insert_constraint(0, 2, &rep).ok());
    CHECK(rep.pieces == 4);
    CHECK(rep.inserted == 4);
    CHECK(rep.dropped_crossing == 0);
    must_verify(cdt);
    const auto cc = constraint_coords(cdt);
    const std::vector<std::array<std::int32_t, 4>> expect = {{0, 0, 5, 5}, {5, 5, 10, 10}, {10, 10, 15, 15}, {15, 15, 20, 20}};
    CHECK(cc == expect);
    // Again: everything already there.
    ConstraintReport again;
    REQUIRE(cdt.insert_constraint(2, 0, &again).ok());
    CHECK(again.already == 4);
    CHECK(again.inserted == 0);
    // A constraint along the rectangle boundary through a boundary vertex.
    const VertInd m = must_insert(cdt, {10, 0});
    ConstraintReport side;
    REQUIRE(cdt.insert_constraint(0, 1, &side).ok());
    CHECK(side.pieces == 2);
    CHECK(side.inserted == 2);
    CHECK(cdt.constrained(cdt.find_edge(0, m) != noEdge ? cdt.find_edge(0, m) : cdt.find_edge(m, 0)));
    must_verify(cdt);
    CHECK_FALSE(cdt.insert_constraint(0, 999).ok());
    REQUIRE(cdt.insert_constraint(3, 3, &side).ok());
}

TEST_CASE("a constraint crossing an existing one is dropped piece by piece and counted", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 20, 20);
    const VertInd m = must_insert(cdt, {15, 5});  // on the anti-diagonal (0,20)-(20,0)
    ConstraintReport r1;
    REQUIRE(cdt.insert_constraint(0, 2, &r1).ok());  // main diagonal
    CHECK(r1.inserted == 1);
    ConstraintReport r2;
    REQUIRE(cdt.insert_constraint(3, 1, &r2).ok());  // anti-diagonal: (0,20)-(15,5) crosses, (15,5)-(20,0) does not
    CHECK(r2.pieces == 2);
    CHECK(r2.dropped_crossing == 1);
    CHECK(r2.inserted == 1);
    must_verify(cdt);
    const auto cc = constraint_coords(cdt);
    CHECK(cc.size() == 2);
    CHECK(std::find(cc.begin(), cc.end(), std::array<std::int32_t, 4>{20, 0, 15, 5}) != cc.end());
    (void)m;
    // Inserting a point at the would-be crossing splits only the kept constraint.
    const VertInd c = must_insert(cdt, {10, 10});
    must_verify(cdt);
    CHECK(constraint_coords(cdt).size() == 3);
    CHECK(cdt.wedge_count(c) == 2);
}

TEST_CASE("wedges: open fans on the boundary, k constraints, ids stable under splits", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 20, 20);
    // The thesis example (A.4.2): a diagonal constraint between two corners.
    REQUIRE(cdt.insert_constraint(0, 2).ok());
    CHECK(cdt.wedge_count(0) == 2);
    CHECK(cdt.wedge_count(2) == 2);
    CHECK(cdt.wedge_count(1) == 1);
    CHECK(cdt.wedge_count(3) == 1);
    std::vector<Wedge> w;
    cdt.wedges(0, &w);
    REQUIRE(w.size() == 2);
    CHECK(w[0].id != w[1].id);
    CHECK(w[0].id != kOnlyWedge);
    // An interior vertex on the constraint: 2 wedges; at the end of one constraint: 1.
    const VertInd c = must_insert(cdt, {10, 10});
    CHECK(cdt.wedge_count(c) == 2);
    const VertInd e = must_insert(cdt, {4, 12});
    REQUIRE(cdt.insert_constraint(c, e).ok());
    CHECK(cdt.wedge_count(c) == 3);
    CHECK(cdt.wedge_count(e) == 1);
    must_verify(cdt);
    // Record the wedge id of every face corner at c.
    std::vector<EdgeInd> corners;
    cdt.corners_around(c, &corners);
    CHECK(corners.size() >= 3);
    std::set<WedgeId> ids;
    for (EdgeInd k : corners) ids.insert(cdt.wedge_id(k));
    CHECK(ids.size() == 3);
    // Split the constraints at c's neighbours and insert points elsewhere: the ids stay the same.
    must_insert(cdt, {15, 15});
    must_insert(cdt, {7, 11});  // on c-e
    must_insert(cdt, {2, 17});
    must_insert(cdt, {18, 3});
    must_insert(cdt, {13, 9});
    must_verify(cdt);
    cdt.corners_around(c, &corners);
    std::set<WedgeId> ids2;
    for (EdgeInd k : corners) ids2.insert(cdt.wedge_id(k));
    CHECK(ids2 == ids);
    cdt.wedges(c, &w);
    CHECK(w.size() == 3);
    std::uint32_t total = 0;
    for (const Wedge& x : w) total += x.count;
    CHECK(total == corners.size());
    // Each face corner's wedge agrees with the wedge run it is listed in.
    for (const Wedge& x : w) {
        EdgeInd k = x.first;
        for (std::uint32_t i = 0; i < x.count; ++i) {
            CHECK(cdt.wedge_id(k) == x.id);
            k = cdt.rot_next(k);
        }
    }
    // A boundary vertex with no interior constraint has one wedge, its fan is open.
    const VertInd bnd = must_insert(cdt, {20, 10});
    CHECK(cdt.wedge_count(bnd) == 1);
    cdt.corners_around(bnd, &corners);
    CHECK(cdt.on_hull(corners.front()));
    CHECK(cdt.rot_next(corners.back()) == noEdge);
    CHECK(cdt.wedge_id(corners.front()) == kOnlyWedge);
}

TEST_CASE("random points and constraints keep every invariant after every operation", "[kernel]") {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
        std::mt19937 g(seed);
        Cdt cdt;
        const int W = 16 + int(seed) * 4, H = 12 + int(seed) * 3;
        must_reset(cdt, W, H);
        std::vector<VertInd> verts = {0, 1, 2, 3};
        for (int op = 0; op < 150; ++op) {
            const std::size_t nf = cdt.face_count();
            if (rnd(g, 4) != 0 || verts.size() < 6) {
                const LatticePoint p{int(rnd(g, std::uint32_t(W + 1))), int(rnd(g, std::uint32_t(H + 1)))};
                const FaceInd hint = rnd(g, 2) ? FaceInd(rnd(g, std::uint32_t(nf))) : noFace;
                const VertInd v = must_insert(cdt, p, hint);
                CHECK(cdt.point(v) == p);
                verts.push_back(v);
                const auto& ch = cdt.changes();
                CHECK(ch.created.size() == ch.destroyed.size() + (cdt.face_count() - nf));
            } else {
                const VertInd a = verts[rnd(g, std::uint32_t(verts.size()))], b = verts[rnd(g, std::uint32_t(verts.size()))];
                ConstraintReport rep;
                const Status s = cdt.insert_constraint(a, b, &rep);
                INFO(s.message);
                REQUIRE(s.ok());
                CHECK(cdt.face_count() == nf);
                CHECK(rep.pieces == rep.inserted + rep.already + rep.dropped_crossing);
            }
            std::string why;
            const bool ok = cdt.verify(&why);
            INFO("seed " << seed << " op " << op << ": " << why);
            REQUIRE(ok);
        }
    }
}

TEST_CASE("the CDT of random points and constraints does not depend on the insertion order", "[kernel]") {
    int compared = 0;
    for (std::uint32_t seed = 10; seed < 40; ++seed) {
        std::mt19937 g(seed);
        const int W = 24, H = 20;
        std::vector<LatticePoint> pts;
        std::set<std::pair<int, int>> seen;
        while (pts.size() < 40) {
            const LatticePoint p{int(rnd(g, W + 1)), int(rnd(g, H + 1))};
            if (seen.insert({p.x, p.y}).second) pts.push_back(p);
        }
        std::vector<std::pair<LatticePoint, LatticePoint>> segs;
        for (int i = 0; i < 6; ++i) segs.push_back({pts[rnd(g, 40)], pts[rnd(g, 40)]});
        auto build = [&](bool points_first, std::mt19937& og, Cdt& cdt, ConstraintReport& total) {
            must_reset(cdt, W, H);
            std::vector<LatticePoint> p = pts;
            std::vector<std::pair<LatticePoint, LatticePoint>> s = segs;
            shuffle(p, og);
            shuffle(s, og);
            if (points_first) {
                for (LatticePoint q : p) must_insert(cdt, q);
                for (auto& sg : s) {
                    REQUIRE(cdt.insert_constraint(cdt.locate(sg.first).vertex, cdt.locate(sg.second).vertex, &total).ok());
                }
            } else {
                // Each segment as soon as its endpoints exist; then the rest of the points.
                std::vector<LatticePoint> order;
                for (auto& sg : s) {
                    must_insert(cdt, sg.first);
                    must_insert(cdt, sg.second);
                    REQUIRE(cdt.insert_constraint(cdt.locate(sg.first).vertex, cdt.locate(sg.second).vertex, &total).ok());
                }
                for (LatticePoint q : p) must_insert(cdt, q);
            }
            must_verify(cdt);
        };
        std::mt19937 o1(seed * 7), o2(seed * 11);
        Cdt c1, c2;
        ConstraintReport r1, r2;
        build(true, o1, c1, r1);
        build(false, o2, c2, r2);
        if (r1.dropped_crossing == 0 && r2.dropped_crossing == 0) {
            ++compared;
            CHECK(canonical_faces(c1) == canonical_faces(c2));
            CHECK(constraint_coords(c1) == constraint_coords(c2));
        }
    }
    CHECK(compared >= 5);
}

TEST_CASE("insert_points maps every input (duplicates too) and reports the whole batch", "[kernel]") {
    Cdt cdt;
    must_reset(cdt, 30, 20);
    must_insert(cdt, {3, 3});
    const std::size_t nf = cdt.face_count();
    std::vector<LatticePoint> pts = {{10, 10}, {3, 3}, {29, 1}, {10, 10}, {0, 7}, {15, 20}, {21, 13}, {30, 20}};
    std::vector<VertInd> v;
    REQUIRE(cdt.insert_points(pts, &v).ok());
    REQUIRE(v.size() == pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) CHECK(cdt.point(v[i]) == pts[i]);
    CHECK(v[0] == v[3]);
    CHECK(v[1] == 4);
    CHECK(v[7] == 2);
    CHECK(cdt.vertex_count() == 10);
    const auto& ch = cdt.changes();
    CHECK(ch.old_face_count == nf);
    std::set<FaceInd> created(ch.created.begin(), ch.created.end());
    CHECK(created.size() == ch.created.size());
    for (FaceInd f = FaceInd(nf); f < cdt.face_count(); ++f) CHECK(created.count(f) == 1);
    for (FaceInd f : ch.destroyed) CHECK(created.count(f) == 1);
    CHECK(ch.created.size() == ch.destroyed.size() + (cdt.face_count() - nf));
    must_verify(cdt);
    std::vector<LatticePoint> bad = {{1, 1}, {31, 0}};
    CHECK_FALSE(cdt.insert_points(bad, &v).ok());
    CHECK(cdt.vertex_count() == 10);  // checked before anything is inserted
}

TEST_CASE("incircle_small agrees with the 128-bit incircle up to the small-coordinate bound", "[kernel]") {
    const std::int32_t M = kSmallCoord - 1;
    // Extremes: a right triangle on three corners of the largest small square, d at the fourth
    // corner (cocircular), just inside and outside.
    const LatticePoint a{0, 0}, b{M, 0}, c{M, M};
    for (const LatticePoint d : {LatticePoint{0, M}, LatticePoint{1, M - 1}, LatticePoint{1, M}, LatticePoint{M / 2, M / 2}})
        CHECK(__int128(incircle_small(a, b, c, d)) == incircle(a, b, c, d));
    CHECK(incircle_small(a, b, c, LatticePoint{0, M}) == 0);
    std::mt19937 g(7);
    int mismatches = 0, ties = 0;
    for (int i = 0; i < 200000; ++i) {
        // Small spans make ties and near-ties common; large ones reach the bound.
        const std::int32_t span = (i & 1) ? M + 1 : 6;
        const std::int32_t ox = std::int32_t(g() % std::uint32_t(kSmallCoord - span + 1));
        const std::int32_t oy = std::int32_t(g() % std::uint32_t(kSmallCoord - span + 1));
        LatticePoint q[4];
        for (auto& p : q) p = {ox + std::int32_t(g() % std::uint32_t(span)), oy + std::int32_t(g() % std::uint32_t(span))};
        const __int128 wide = incircle(q[0], q[1], q[2], q[3]);
        if (__int128(incircle_small(q[0], q[1], q[2], q[3])) != wide) ++mismatches;
        if (wide == 0) ++ties;
        if (orient2d(q[0], q[1], q[2]) > 0 &&
            incircle_perturbed(q[0], q[1], q[2], q[3], true) != incircle_perturbed(q[0], q[1], q[2], q[3]))
            ++mismatches;
    }
    CHECK(mismatches == 0);
    CHECK(ties > 1000);
}

TEST_CASE("insert_points without a change report builds the same mesh slot for slot", "[kernel]") {
    std::mt19937 g(11);
    std::vector<LatticePoint> pts;
    for (int i = 0; i < 3000; ++i) pts.push_back({std::int32_t(g() % 201), std::int32_t(g() % 121)});
    Cdt with, without;
    must_reset(with, 200, 120);
    must_reset(without, 200, 120);
    std::vector<VertInd> v1, v2;
    REQUIRE(with.insert_points(pts, &v1).ok());
    REQUIRE(without.insert_points(pts, &v2, false).ok());
    CHECK(v1 == v2);
    CHECK_FALSE(with.changes().created.empty());
    CHECK(without.changes().created.empty());
    CHECK(without.changes().destroyed.empty());
    std::vector<std::array<VertInd, 3>> f1, f2;
    with.export_faces(&f1);
    without.export_faces(&f2);
    CHECK(f1 == f2);
    must_verify(without);
    // Single insertions afterwards report again.
    must_insert(without, {1, 119});
    CHECK_FALSE(without.changes().created.empty());
    REQUIRE(without.insert_points({}, &v2).ok());
    CHECK(v2.empty());
}

TEST_CASE("insert_points on a huge rectangle (keys too wide to pack) agrees with one-by-one insertion", "[kernel]") {
    // 2^24 - 1 needs 48 Hilbert bits; with 20,000 points and their rounds the packed key would
    // need more than 64 bits, so the pair-sorting path runs.
    const std::int32_t M = kMaxCoord - 1;
    std::mt19937 g(5);
    std::vector<LatticePoint> pts;
    auto coord = [&g, M] { return std::int32_t(g() % std::uint32_t(M + 1)); };
    for (int i = 0; i < 20000; ++i) pts.push_back({coord(), coord()});
    pts.push_back(pts[17]);  // a duplicate
    Cdt batch, single;
    must_reset(batch, M, M);
    must_reset(single, M, M);
    std::vector<VertInd> v;
    REQUIRE(batch.insert_points(pts, &v).ok());
    for (std::size_t i = 0; i < pts.size(); ++i) CHECK(batch.point(v[i]) == pts[i]);
    CHECK(v[17] == v.back());
    for (const LatticePoint& p : pts) must_insert(single, p);
    CHECK(canonical_faces(batch) == canonical_faces(single));
    must_verify(batch);
}

TEST_CASE("hilbert_index walks the whole square in unit steps", "[kernel]") {
    for (int order = 1; order <= 6; ++order) {
        const std::uint32_t side = 1u << order;
        std::vector<std::array<std::uint32_t, 2>> at(std::size_t(side) * side, {side, side});
        for (std::uint32_t y = 0; y < side; ++y)
            for (std::uint32_t x = 0; x < side; ++x) {
                const std::uint64_t d = hilbert_index(x, y, order);
                REQUIRE(d < at.size());
                REQUIRE(at[d][0] == side);  // a bijection: no index taken twice
                at[d] = {x, y};
            }
        for (std::size_t d = 1; d < at.size(); ++d) {  // consecutive indices are 4-neighbours
            const int dx = int(at[d][0]) - int(at[d - 1][0]), dy = int(at[d][1]) - int(at[d - 1][1]);
            INFO("order " << order << " index " << d);
            REQUIRE(std::abs(dx) + std::abs(dy) == 1);
        }
    }
}

TEST_CASE("brio_order is a permutation in rounds of doubling size, each in Hilbert order", "[kernel]") {
    std::mt19937 rng(11);
    for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(64), std::size_t(65), std::size_t(1000)}) {
        std::vector<LatticePoint> pts(n);
        for (LatticePoint& p : pts) p = {int(rng() % 200), int(rng() % 120)};
        std::vector<std::uint64_t> order, tmp;
        brio_order(pts, 8, &order, &tmp);
        REQUIRE(order.size() == n);
        std::vector<bool> seen(n, false);
        for (const std::uint64_t i : order) {
            REQUIRE(i < n);
            REQUIRE_FALSE(seen[i]);
            seen[i] = true;
        }
        std::size_t round_begin = 0, round_end = 64;
        for (std::size_t j = 1; j < n; ++j) {
            if (j == round_end) {
                round_begin = j;
                round_end *= 2;
                continue;
            }
            const LatticePoint a = pts[order[j - 1]], b = pts[order[j]];
            INFO("n " << n << " position " << j << " round from " << round_begin);
            REQUIRE(hilbert_index(std::uint32_t(a.x), std::uint32_t(a.y), 8) <=
                    hilbert_index(std::uint32_t(b.x), std::uint32_t(b.y), 8));
        }
        std::vector<std::uint64_t> again, tmp2;
        brio_order(pts, 8, &again, &tmp2);
        REQUIRE(again == order);  // deterministic
    }
}
