// erd's Cdt against CGAL's Constrained_Delaunay_triangulation_2 (tests/cgal/cgal_diff.h says what
// is compared). Its own binary, build/cgal_tests (`make cgal-test`, a stage of `make test`), so
// that erd_tests never needs CGAL. Every comparison is one "case" in the counts printed at the end.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>

#include "tests/cgal/cgal_diff.h"

using namespace cgal_diff;

namespace {

std::size_t g_cases = 0, g_tie_cases = 0, g_removals = 0, g_same = 0, g_same_ties = 0;

// The counts, printed once at exit (for docs/DECISIONS.md): comparisons, of which with cocircular
// ties, and removals compared.
struct Counts {
    ~Counts() {
        std::printf("cgal differential: %zu comparisons (%zu with cocircular ties), %zu removals compared; "
                    "the same triangles in %zu (%zu with ties)\n",
                    g_cases, g_tie_cases, g_removals, g_same, g_same_ties);
    }
} g_counts;

void must_match(const Differential& d) {
    const Result r = d.compare();
    INFO(r.difference);
    REQUIRE(r.difference.empty());
    ++g_cases;
    if (r.tie_edges > 0) ++g_tie_cases;
    if (r.same_triangles) ++g_same;
    if (r.same_triangles && r.tie_edges > 0) ++g_same_ties;
}

void must(const std::string& what) {
    INFO(what);
    REQUIRE(what.empty());
}

std::int32_t rnd(std::mt19937& g, std::int32_t n) { return std::int32_t(g() % std::uint32_t(n)); }

// Removes every removable vertex in a random order, comparing after each.
void remove_all(Differential& d, std::mt19937& g) {
    std::vector<LatticePoint> pts;
    for (erd::VertInd v = 4; v < d.cdt().vertex_count(); ++v)
        if (d.cdt().vertex_live(v)) pts.push_back(d.cdt().point(v));
    std::shuffle(pts.begin(), pts.end(), g);
    for (const LatticePoint p : pts) {
        bool removed = false;
        must(d.remove(p, &removed));
        if (!removed) continue;
        ++g_removals;
        must_match(d);
    }
}

// The points of the lattice circle x^2 + y^2 = r^2 around c.
std::vector<LatticePoint> circle(LatticePoint c, int r) {
    std::vector<LatticePoint> out;
    for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
            if (x * x + y * y == r * r) out.push_back({c.x + x, c.y + y});
    return out;
}

}  // namespace

TEST_CASE("CGAL: random points and crossing constraints, then every vertex removed", "[cgal]") {
    const std::size_t before = g_cases;
    std::mt19937 g(49);
    for (int trial = 0; trial < 300; ++trial) {
        const std::int32_t W = trial % 3 == 0 ? 12 : trial % 3 == 1 ? 200 : 60000, H = W - trial % 5;
        Differential d(W, H, trial % 2 ? 10 : 0);
        std::vector<LatticePoint> pts;
        for (int op = 0; op < 80; ++op) {
            if (op % 5 == 4 && pts.size() >= 2) {
                must(d.insert_constraint(pts[std::size_t(rnd(g, std::int32_t(pts.size())))], pts[std::size_t(rnd(g, std::int32_t(pts.size())))]));
            } else {
                const LatticePoint p{rnd(g, W + 1), rnd(g, H + 1)};
                must(d.insert_point(p));
                pts.push_back(p);
            }
            must_match(d);
        }
        remove_all(d, g);
    }
    CHECK(g_cases - before > 30000);
}

TEST_CASE("CGAL: full lattices with constraints along rows, diagonals and the rectangle sides", "[cgal]") {
    const std::size_t before = g_cases;
    std::mt19937 g(50);
    for (const int n : {4, 7, 10, 16}) {
        Differential d(n, n);
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x) must(d.insert_point({x, y}));
        must_match(d);
        must(d.insert_constraint({0, n / 2}, {n, n / 2}));  // a row through n + 1 vertices
        must(d.insert_constraint({0, 0}, {n, n}));          // the diagonal: crosses the row at a vertex
        must(d.insert_constraint({0, n}, {n, 0}));          // the other diagonal
        must(d.insert_constraint({0, 1}, {0, n - 1}));      // along the left side
        must(d.insert_constraint({1, 0}, {n - 1, 2}));      // through no vertex or some
        must_match(d);
        remove_all(d, g);
    }
    CHECK(g_cases - before > 300);
}

TEST_CASE("CGAL: lattice circles with their centres, diameters through vertices", "[cgal]") {
    const std::size_t before = g_cases;
    std::mt19937 g(51);
    for (const int r : {5, 25, 65, 85}) {
        const LatticePoint c{2 * r, 2 * r};
        for (int variant = 0; variant < 3; ++variant) {
            Differential d(4 * r, 4 * r, variant == 2 ? 0 : 10);
            for (const LatticePoint p : circle(c, r)) must(d.insert_point(p));
            for (const LatticePoint p : circle(c, r / 5)) must(d.insert_point(p));  // a second, concentric
            must(d.insert_point(c));
            must_match(d);
            if (variant == 1) {
                must(d.insert_constraint({c.x - r, c.y}, {c.x + r, c.y}));  // a diameter through the centre
                must(d.insert_constraint({c.x, c.y - r}, {c.x, c.y + r}));  // crosses it at the centre: split
                must_match(d);
            }
            bool removed = false;
            must(d.remove(c, &removed));
            must_match(d);
            remove_all(d, g);
        }
    }
    CHECK(g_cases - before > 400);
}

TEST_CASE("CGAL: points inserted after constraints, on them and beside them", "[cgal]") {
    const std::size_t before = g_cases;
    std::mt19937 g(52);
    for (int trial = 0; trial < 100; ++trial) {
        const std::int32_t W = 24, H = 18;
        Differential d(W, H, trial % 2 ? 10 : 0);
        std::vector<LatticePoint> pts;
        for (int i = 0; i < 12; ++i) {
            const LatticePoint p{rnd(g, W + 1), rnd(g, H + 1)};
            must(d.insert_point(p));
            pts.push_back(p);
        }
        for (int i = 0; i < 6; ++i) must(d.insert_constraint(pts[std::size_t(rnd(g, 12))], pts[std::size_t(rnd(g, 12))]));
        must_match(d);
        // Points on the segment between two earlier points (a constrained edge or not), then others.
        for (int i = 0; i < 20; ++i) {
            const LatticePoint a = pts[std::size_t(rnd(g, 12))], b = pts[std::size_t(rnd(g, 12))];
            const std::int32_t k = std::gcd(std::abs(b.x - a.x), std::abs(b.y - a.y));
            if (k < 2) continue;
            const std::int32_t t = 1 + rnd(g, k - 1);
            must(d.insert_point({a.x + (b.x - a.x) / k * t, a.y + (b.y - a.y) / k * t}));
            must_match(d);
        }
        remove_all(d, g);
    }
    CHECK(g_cases - before > 1500);
}

TEST_CASE("CGAL: large coordinates (the 128-bit in-circle path), near-degenerate", "[cgal]") {
    const std::size_t before = g_cases;
    std::mt19937 g(53);
    const std::int32_t M = erd::kMaxCoord - 1;
    for (int trial = 0; trial < 100; ++trial) {
        Differential d(M, M - trial, trial % 2 ? 10 : 0);
        std::vector<LatticePoint> pts;
        for (int i = 0; i < 40; ++i) {
            // A coarse lattice (ties) and its neighbours one unit off (near-ties only exact
            // arithmetic separates), all far from the origin.
            LatticePoint p{M - rnd(g, 8) * (1 << 21), M - trial - rnd(g, 8) * (1 << 21)};
            if (i % 3 == 0) p.x -= 1;
            must(d.insert_point(p));
            pts.push_back(p);
        }
        for (int i = 0; i < 5; ++i) must(d.insert_constraint(pts[std::size_t(rnd(g, 40))], pts[std::size_t(rnd(g, 40))]));
        must_match(d);
        remove_all(d, g);
    }
    CHECK(g_cases - before > 2000);
}
