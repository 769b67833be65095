// Tests of Cdt::remove_vertex: after every removal verify() holds and the triangulation equals,
// face for face and constraint for constraint, a fresh build of the remaining points and
// constrained edges; both hole-filling methods (apex scan, CDT of the hole) are run on every case.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "kernel/cdt.h"
#include "tests/cdt_util.h"
#include "tests/test_cdt_util.h"

using namespace erd;

using cdt_util::constraint_coords;

namespace {

// The apex scan for every hole, and the CDT of the hole for every hole (kernel/cdt_remove.cpp).
constexpr std::uint32_t kScanAlways = 0xFFFFFFFFu, kScanNever = 0;

// A fresh build of cdt's live points (one batch) and of its constrained edges.
Cdt fresh_build(const Cdt& cdt) {
    Cdt f;
    REQUIRE(f.reset(cdt.max_x(), cdt.max_y()).ok());
    std::vector<LatticePoint> pts;
    for (VertInd v = 4; v < cdt.vertex_count(); ++v)
        if (cdt.vertex_live(v)) pts.push_back(cdt.point(v));
    std::vector<VertInd> ids;
    REQUIRE(f.insert_points(pts, &ids, false).ok());
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    for (const auto& e : cons) {
        const Location a = f.locate(cdt.point(e[0])), b = f.locate(cdt.point(e[1]));
        REQUIRE(a.kind == Location::Kind::on_vertex);
        REQUIRE(b.kind == Location::Kind::on_vertex);
        ConstraintReport rep;
        REQUIRE(f.insert_constraint(a.vertex, b.vertex, &rep).ok());
        REQUIRE(rep.dropped_crossing == 0);
    }
    return f;
}

void must_equal_fresh(const Cdt& cdt) {
    const Cdt f = fresh_build(cdt);
    REQUIRE(canonical_faces(cdt) == canonical_faces(f));
    REQUIRE(constraint_coords(cdt) == constraint_coords(f));
    REQUIRE(cdt.live_face_count() == f.face_count());
    REQUIRE(cdt.live_vertex_count() == f.vertex_count());
}

// Removes v (must be removable) and checks the change report against the star it had.
void must_remove(Cdt& cdt, VertInd v) {
    REQUIRE(cdt.can_remove(v));
    std::vector<EdgeInd> corners;
    cdt.corners_around(v, &corners);
    std::set<FaceInd> star;
    for (EdgeInd e : corners) star.insert(face_of(e));
    const bool side = cdt.on_boundary(v);
    const std::size_t live = cdt.live_face_count(), slots = cdt.face_count();
    const Status s = cdt.remove_vertex(v);
    INFO(s.message);
    REQUIRE(s.ok());
    REQUIRE_FALSE(cdt.vertex_live(v));
    REQUIRE(cdt.live_face_count() == live - (side ? 1 : 2));
    REQUIRE(cdt.face_count() == slots);
    const ChangeReport& ch = cdt.changes();
    REQUIRE(std::set<FaceInd>(ch.destroyed.begin(), ch.destroyed.end()) == star);
    REQUIRE(ch.destroyed.size() == star.size());
    REQUIRE(ch.created.size() == star.size() - (side ? 1 : 2));
    for (FaceInd f : ch.created) {
        REQUIRE(star.count(f) == 1);
        REQUIRE(cdt.face_live(f));
    }
    for (FaceInd f : ch.destroyed)
        REQUIRE(cdt.face_live(f) == (std::find(ch.created.begin(), ch.created.end(), f) != ch.created.end()));
}

// Removes every removable vertex of cdt in a random order, checking after each.
std::size_t remove_all(Cdt& cdt, std::mt19937& g) {
    std::vector<VertInd> order;
    for (VertInd v = 4; v < cdt.vertex_count(); ++v)
        if (cdt.can_remove(v)) order.push_back(v);
    std::shuffle(order.begin(), order.end(), g);
    for (VertInd v : order) {
        must_remove(cdt, v);
        must_verify(cdt);
        must_equal_fresh(cdt);
    }
    return order.size();
}

std::uint32_t scan_limit(int method) { return method == 0 ? kScanAlways : method == 1 ? kScanNever : 10; }

}  // namespace

TEST_CASE("remove_vertex: random points, every vertex removed, each step equal to a fresh build", "[kernel][remove]") {
    std::mt19937 g(11);
    std::size_t removed = 0;
    for (int method = 0; method < 3; ++method)
        for (int trial = 0; trial < 12; ++trial) {
            const int side = trial % 3 == 0 ? 6 : trial % 3 == 1 ? 40 : 4000;
            Cdt cdt;
            REQUIRE(cdt.reset(side, side - trial % 2).ok());
            cdt.set_removal_scan_limit(scan_limit(method));
            for (int i = 0; i < 60; ++i)
                REQUIRE(cdt.insert_point({std::int32_t(g() % std::uint32_t(side + 1)), std::int32_t(g() % std::uint32_t(side))}, nullptr).ok());
            removed += remove_all(cdt, g);
            REQUIRE(cdt.live_vertex_count() == 4);
            REQUIRE(cdt.live_face_count() == 2);
        }
    CHECK(removed > 1000);
}

TEST_CASE("remove_vertex: full lattices (collinear runs, cocircular squares) follow the tie rule", "[kernel][remove]") {
    std::mt19937 g(12);
    for (int method = 0; method < 3; ++method)
        for (const int n : {3, 5, 8}) {
            Cdt cdt;
            REQUIRE(cdt.reset(n, n + 1).ok());
            cdt.set_removal_scan_limit(scan_limit(method));
            std::vector<LatticePoint> pts;
            for (int y = 0; y <= n + 1; ++y)
                for (int x = 0; x <= n; ++x) pts.push_back({x, y});
            REQUIRE(cdt.insert_points(pts, nullptr).ok());
            const std::size_t removable = cdt.vertex_count() - 4;
            CHECK(remove_all(cdt, g) == removable);
        }
}

TEST_CASE("remove_vertex: the centre of a lattice circle (a star of 12 to 36 cocircular points)", "[kernel][remove]") {
    // x^2 + y^2 = r^2 has 12 lattice points for r = 5, 10, 13, 36 for r = 65; the centre's star is
    // all of them, a hole whose every triangulation is Delaunay: the tie rule alone decides.
    std::mt19937 g(13);
    for (const int r : {5, 10, 13, 25, 65})
        for (int method = 0; method < 3; ++method) {
            Cdt cdt;
            REQUIRE(cdt.reset(4 * r, 4 * r).ok());
            cdt.set_removal_scan_limit(scan_limit(method));
            std::vector<LatticePoint> pts;
            for (int x = -r; x <= r; ++x)
                for (int y = -r; y <= r; ++y)
                    if (x * x + y * y == r * r) pts.push_back({2 * r + x, 2 * r + y});
            VertInd centre = noVertex;
            REQUIRE(cdt.insert_points(pts, nullptr).ok());
            REQUIRE(cdt.insert_point({2 * r, 2 * r}, &centre).ok());
            std::vector<EdgeInd> corners;
            cdt.corners_around(centre, &corners);
            CHECK(corners.size() == pts.size());
            must_remove(cdt, centre);
            must_verify(cdt);
            must_equal_fresh(cdt);
            remove_all(cdt, g);
        }
}

TEST_CASE("remove_vertex: vertices on the rectangle sides (open fans) become one hull edge", "[kernel][remove]") {
    std::mt19937 g(14);
    for (int method = 0; method < 3; ++method)
        for (int trial = 0; trial < 10; ++trial) {
            const int W = 10 + trial, H = 7 + trial;
            Cdt cdt;
            REQUIRE(cdt.reset(W, H).ok());
            cdt.set_removal_scan_limit(scan_limit(method));
            std::vector<VertInd> side;
            for (int i = 0; i < 30; ++i) {
                LatticePoint p{std::int32_t(g() % std::uint32_t(W + 1)), std::int32_t(g() % std::uint32_t(H + 1))};
                if (i % 2 == 0) (i % 4 == 0 ? p.x : p.y) = i % 8 == 0 ? 0 : (i % 4 == 0 ? W : H);
                VertInd v = noVertex;
                REQUIRE(cdt.insert_point(p, &v).ok());
                if (cdt.on_boundary(v) && v >= 4) side.push_back(v);
            }
            REQUIRE_FALSE(side.empty());
            std::sort(side.begin(), side.end());
            side.erase(std::unique(side.begin(), side.end()), side.end());
            for (VertInd v : side) {
                must_remove(cdt, v);
                must_verify(cdt);
                must_equal_fresh(cdt);
            }
            remove_all(cdt, g);
        }
}

TEST_CASE("remove_vertex interleaved with insertions and constraints; constrained vertices stay", "[kernel][remove]") {
    std::mt19937 g(15);
    std::size_t removals = 0, refusals = 0;
    for (int method = 0; method < 3; ++method)
        for (int trial = 0; trial < 20; ++trial) {
            const int W = trial % 2 ? 12 : 300, H = trial % 2 ? 9 : 200;
            Cdt cdt;
            REQUIRE(cdt.reset(W, H).ok());
            cdt.set_removal_scan_limit(scan_limit(method));
            for (int op = 0; op < 120; ++op) {
                const std::uint32_t r = std::uint32_t(g() % 10);
                if (r < 5) {
                    REQUIRE(cdt.insert_point({std::int32_t(g() % std::uint32_t(W + 1)), std::int32_t(g() % std::uint32_t(H + 1))}, nullptr).ok());
                } else if (r < 6) {
                    const VertInd a = VertInd(g() % cdt.vertex_count()), b = VertInd(g() % cdt.vertex_count());
                    if (cdt.vertex_live(a) && cdt.vertex_live(b)) REQUIRE(cdt.insert_constraint(a, b).ok());
                } else {
                    const VertInd v = VertInd(g() % cdt.vertex_count());
                    if (cdt.can_remove(v)) {
                        must_remove(cdt, v);
                        ++removals;
                    } else {
                        const auto before = canonical_faces(cdt);
                        REQUIRE_FALSE(cdt.remove_vertex(v).ok());
                        REQUIRE(cdt.changes().created.empty());
                        REQUIRE(cdt.changes().destroyed.empty());
                        REQUIRE(canonical_faces(cdt) == before);
                        ++refusals;
                    }
                }
                must_verify(cdt);
                must_equal_fresh(cdt);
            }
            // Everything removable: what is left is the corners and the constrained vertices.
            remove_all(cdt, g);
            for (VertInd v = 4; v < cdt.vertex_count(); ++v)
                if (cdt.vertex_live(v)) REQUIRE_FALSE(cdt.can_remove(v));
        }
    CHECK(removals > 500);
    CHECK(refusals > 100);
}

TEST_CASE("remove_vertex refuses corners, removed vertices and vertices on constrained edges", "[kernel][remove]") {
    Cdt cdt;
    REQUIRE(cdt.reset(20, 20).ok());
    VertInd a, b, mid, free1, edge_side, side_end;
    REQUIRE(cdt.insert_point({4, 4}, &a).ok());
    REQUIRE(cdt.insert_point({16, 16}, &b).ok());
    REQUIRE(cdt.insert_point({10, 10}, &mid).ok());  // inside the constraint a-b: splits it
    REQUIRE(cdt.insert_point({15, 5}, &free1).ok());
    REQUIRE(cdt.insert_point({0, 8}, &edge_side).ok());
    REQUIRE(cdt.insert_point({0, 14}, &side_end).ok());
    REQUIRE(cdt.insert_constraint(a, b).ok());
    REQUIRE(cdt.insert_constraint(edge_side, side_end).ok());  // along the rectangle side
    const auto before = canonical_faces(cdt);
    for (VertInd v : {VertInd(0), VertInd(1), VertInd(2), VertInd(3), a, b, mid, edge_side, side_end, VertInd(99)}) {
        INFO(v);
        CHECK_FALSE(cdt.can_remove(v));
        const Status s = cdt.remove_vertex(v);
        CHECK(s.code == Code::input);
        CHECK_FALSE(s.message.empty());
        CHECK(cdt.changes().created.empty());
    }
    CHECK(canonical_faces(cdt) == before);
    CHECK(cdt.remove_vertex(0).message.find("corner") != std::string::npos);
    CHECK(cdt.remove_vertex(mid).message.find("constrained") != std::string::npos);
    REQUIRE(cdt.can_remove(free1));
    must_remove(cdt, free1);
    CHECK(cdt.remove_vertex(free1).message.find("removed") != std::string::npos);
    CHECK(cdt.insert_constraint(free1, a).code == Code::input);
    must_verify(cdt);
    must_equal_fresh(cdt);
}

TEST_CASE("freed face slots: reused by the next insertions, listed as created only", "[kernel][remove]") {
    std::mt19937 g(16);
    Cdt cdt;
    REQUIRE(cdt.reset(100, 100).ok());
    std::vector<LatticePoint> pts;
    for (int i = 0; i < 50; ++i) pts.push_back({std::int32_t(1 + g() % 99), std::int32_t(1 + g() % 99)});
    std::vector<VertInd> ids;
    REQUIRE(cdt.insert_points(pts, &ids).ok());
    const auto full = canonical_faces(cdt);
    const std::size_t slots = cdt.face_count();
    // Remove 10 interior vertices: 20 slots freed, none of them live.
    std::vector<VertInd> gone;
    for (VertInd v : ids)
        if (gone.size() < 10 && cdt.vertex_live(v) && std::find(gone.begin(), gone.end(), v) == gone.end()) {
            must_remove(cdt, v);
            gone.push_back(v);
        }
    REQUIRE(cdt.live_face_count() == slots - 20);
    std::size_t dead = 0;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) dead += !cdt.face_live(f);
    REQUIRE(dead == 20);
    // The removed points are no vertices now.
    for (VertInd v : gone) CHECK(cdt.locate(cdt.point(v)).kind != Location::Kind::on_vertex);
    // Put them back one by one: the slot count stays, each insertion takes 2 freed slots, reported as created only.
    for (VertInd v : gone) {
        const std::size_t live = cdt.live_face_count();
        VertInd nv = noVertex;
        REQUIRE(cdt.insert_point(cdt.point(v), &nv).ok());
        CHECK(nv != v);  // indices are never reused
        const ChangeReport& ch = cdt.changes();
        CHECK(ch.created.size() == ch.destroyed.size() + (cdt.live_face_count() - live));
        for (FaceInd f : ch.destroyed) CHECK(std::find(ch.created.begin(), ch.created.end(), f) != ch.created.end());
        for (FaceInd f : ch.created) CHECK(cdt.face_live(f));
        must_verify(cdt);
    }
    CHECK(cdt.face_count() == slots);
    CHECK(canonical_faces(cdt) == full);
    // And a batch: insert_points' report lists freed slots taken as created only.
    std::vector<LatticePoint> back;
    for (const LatticePoint p : pts) {
        const Location loc = cdt.locate(p);
        REQUIRE(loc.kind == Location::Kind::on_vertex);
        if (back.size() < 5 && std::find(back.begin(), back.end(), p) == back.end()) {
            must_remove(cdt, loc.vertex);
            back.push_back(p);
        }
    }
    const std::size_t live = cdt.live_face_count();
    REQUIRE(cdt.insert_points(back, nullptr).ok());
    const ChangeReport& ch = cdt.changes();
    CHECK(ch.created.size() == ch.destroyed.size() + (cdt.live_face_count() - live));
    CHECK(ch.created.size() == std::set<FaceInd>(ch.created.begin(), ch.created.end()).size());
    for (FaceInd f : ch.destroyed) CHECK(std::find(ch.created.begin(), ch.created.end(), f) != ch.created.end());
    CHECK(canonical_faces(cdt) == full);
    must_verify(cdt);
}

TEST_CASE("remove_vertex near the coordinate bound (the 128-bit predicates)", "[kernel][remove]") {
    std::mt19937 g(17);
    const std::int32_t M = kMaxCoord - 1;
    for (int method = 0; method < 3; ++method) {
        Cdt cdt;
        REQUIRE(cdt.reset(M, M).ok());
        cdt.set_removal_scan_limit(scan_limit(method));
        for (int i = 0; i < 40; ++i) {
            // Clustered near the far corner and on a coarse lattice, so ties occur too.
            const std::int32_t x = M - std::int32_t(g() % 9) * (1 << 20), y = M - std::int32_t(g() % 9) * (1 << 20);
            REQUIRE(cdt.insert_point({x, y}, nullptr).ok());
        }
        remove_all(cdt, g);
    }
}

TEST_CASE("remove_vertex on a data-dependent mesh (after flip_edge) keeps a valid triangulation", "[kernel][remove]") {
    std::mt19937 g(18);
    for (int trial = 0; trial < 20; ++trial) {
        Cdt cdt;
        REQUIRE(cdt.reset(60, 60).ok());
        for (int i = 0; i < 40; ++i)
            REQUIRE(cdt.insert_point({std::int32_t(g() % 61), std::int32_t(g() % 61)}, nullptr).ok());
        for (int i = 0; i < 30; ++i) {
            const EdgeInd e = EdgeInd(g() % (3 * cdt.face_count()));
            if (cdt.can_flip(e)) cdt.flip_edge(e);
        }
        for (VertInd v = 4; v < cdt.vertex_count(); ++v) {
            if (!cdt.can_remove(v)) continue;
            const Status s = cdt.remove_vertex(v);
            INFO(s.message);
            REQUIRE(s.ok());
            std::string why;
            INFO(why);
            REQUIRE(cdt.verify_topology(&why));
        }
        REQUIRE(cdt.live_vertex_count() == 4);
    }
}
