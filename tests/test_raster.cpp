// Scan conversion: exact-once ownership over arbitrary triangulations of the rectangle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "kernel/predicates.h"
#include "kernel/raster.h"
#include "tests/test_raster_util.h"
#include "tests/test_rounding_util.h"

using erd::Lattice;
using erd::LatticePoint;
using erd::RasterDomain;
using erd::Span;

namespace {

using erd_test::Tri;
using erd_test::random_triangulation;

// Counts, for every lattice point of the index box [0,ni)x[0,nj), how many faces own it.
std::vector<int> coverage(const std::vector<Tri>& t, const Lattice& l, RasterDomain d, int ni, int nj,
                          std::int64_t* outside) {
    std::vector<int> cnt(std::size_t(ni) * std::size_t(nj), 0);
    std::vector<Span> spans;
    *outside = 0;
    for (const Tri& f : t) {
        const std::int64_t n = erd::scan_triangle(l, d, f[0], f[1], f[2], &spans);
        std::int64_t seen = 0;
        std::int32_t last_y = INT32_MIN;
        for (const Span& s : spans) {
            REQUIRE(s.x_begin <= s.x_end);
            REQUIRE(s.y > last_y);  // top to bottom, one span per row
            last_y = s.y;
            for (std::int32_t i = s.x_begin; i <= s.x_end; ++i) {
                ++seen;
                if (i < 0 || s.y < 0 || i >= ni || s.y >= nj) {
                    ++*outside;
                    continue;
                }
                ++cnt[std::size_t(s.y) * std::size_t(ni) + std::size_t(i)];
            }
        }
        REQUIRE(seen == n);
    }
    return cnt;
}

}  // namespace

TEST_CASE("raster: pixel lattice, every pixel owned exactly once", "[raster]") {
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 60; ++trial) {
        const int W = 2 + int(rng() % 14), H = 2 + int(rng() % 14);
        const RasterDomain d{2 * W - 2, 2 * H - 2};
        const bool even = trial % 2 == 0;
        const auto t = random_triangulation(rng, d.max_x, d.max_y, 4 + int(rng() % 40), even);
        std::int64_t outside = 0;
        const auto cnt = coverage(t, Lattice::pixels(), d, W, H, &outside);
        CHECK(outside == 0);
        int bad = 0;
        for (int c : cnt) bad += c != 1;
        INFO("trial " << trial << " W " << W << " H " << H << " faces " << t.size());
        CHECK(bad == 0);
    }
}

TEST_CASE("raster: supersampling lattice, every sub-sample inside the domain owned exactly once", "[raster]") {
    std::mt19937 rng(777);
    const Lattice l = Lattice::supersample();
    for (int trial = 0; trial < 40; ++trial) {
        const int W = 2 + int(rng() % 9), H = 2 + int(rng() % 9);
        const RasterDomain d{2 * W - 2, 2 * H - 2};
        const auto t = random_triangulation(rng, d.max_x, d.max_y, 4 + int(rng() % 30), trial % 3 == 0);
        std::int64_t outside = 0;
        const int ni = 4 * W, nj = 4 * H;
        const auto cnt = coverage(t, l, d, ni, nj, &outside);
        CHECK(outside == 0);
        int bad = 0;
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) {
                // Sub-samples 0,1 and 4W-2,4W-1 of a row lie outside Gamma (clamped by the caller).
                const bool in = l.fine_x(i) >= 0 && l.fine_x(i) <= 4 * d.max_x && l.fine_y(j) >= 0 &&
                                l.fine_y(j) <= 4 * d.max_y;
                bad += cnt[std::size_t(j) * std::size_t(ni) + std::size_t(i)] != (in ? 1 : 0);
            }
        INFO("trial " << trial);
        CHECK(bad == 0);
    }
}

TEST_CASE("raster: border lattices (clamped sub-samples) owned exactly once", "[raster]") {
    std::mt19937 rng(99);
    for (int trial = 0; trial < 30; ++trial) {
        const int W = 2 + int(rng() % 9), H = 2 + int(rng() % 9);
        const RasterDomain d{2 * W - 2, 2 * H - 2};
        const auto t = random_triangulation(rng, d.max_x, d.max_y, 4 + int(rng() % 30), false);
        // Columns x = 0 and x = max_x at sub-sample rows; rows y = 0, max_y at sub-sample columns;
        // the four corners.
        const Lattice cols{4, 4 * d.max_x, 2, 0, -3}, rows{4, 2, 4 * d.max_y, -3, 0},
            corners{4, 4 * d.max_x, 4 * d.max_y, 0, 0};
        std::int64_t outside = 0;
        auto c1 = coverage(t, cols, d, 2, 4 * H, &outside);
        for (int j = 0; j < 4 * H; ++j)
            for (int i = 0; i < 2; ++i) {
                const bool in = j >= 2 && j < 4 * H - 2;
                CHECK(c1[std::size_t(j * 2 + i)] == (in ? 1 : 0));
            }
        auto c2 = coverage(t, rows, d, 4 * W, 2, &outside);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 4 * W; ++i) CHECK(c2[std::size_t(j * 4 * W + i)] == ((i >= 2 && i < 4 * W - 2) ? 1 : 0));
        auto c3 = coverage(t, corners, d, 2, 2, &outside);
        for (int c : c3) CHECK(c == 1);
        CHECK(outside == 0);
    }
}

TEST_CASE("raster: spans agree with the point-by-point rule", "[raster]") {
    std::mt19937 rng(4242);
    const Lattice lats[2] = {Lattice::pixels(), Lattice::supersample()};
    for (int trial = 0; trial < 20; ++trial) {
        const int W = 2 + int(rng() % 8), H = 2 + int(rng() % 8);
        const RasterDomain d{2 * W - 2, 2 * H - 2};
        const auto t = random_triangulation(rng, d.max_x, d.max_y, 10, false);
        for (const Lattice& l : lats) {
            const int ni = l.scale == 1 ? W : 4 * W, nj = l.scale == 1 ? H : 4 * H;
            std::vector<Span> spans;
            for (const Tri& f : t) {
                erd::scan_triangle(l, d, f[0], f[1], f[2], &spans);
                std::vector<char> mark(std::size_t(ni) * std::size_t(nj), 0);
                for (const Span& s : spans)
                    for (int i = s.x_begin; i <= s.x_end; ++i) mark[std::size_t(s.y * ni + i)] = 1;
                int mismatch = 0;
                for (int j = 0; j < nj; ++j)
                    for (int i = 0; i < ni; ++i)
                        mismatch += (erd::triangle_owns(l, d, f[0], f[1], f[2], i, j) ? 1 : 0) !=
                                    mark[std::size_t(j * ni + i)];
                CHECK(mismatch == 0);
                // Orientation does not matter.
                std::vector<Span> rev;
                erd::scan_triangle(l, d, f[0], f[2], f[1], &rev);
                REQUIRE(rev.size() == spans.size());
                for (std::size_t k = 0; k < rev.size(); ++k) {
                    CHECK(rev[k].y == spans[k].y);
                    CHECK(rev[k].x_begin == spans[k].x_begin);
                    CHECK(rev[k].x_end == spans[k].x_end);
                }
            }
        }
    }
}

TEST_CASE("raster: tie rule on a hand-made case", "[raster]") {
    // 3x3 pixels, domain [0,4]^2 doubled, split by the diagonal (0,0)-(4,4).
    const RasterDomain d{4, 4};
    const LatticePoint a{0, 0}, b{4, 0}, c{4, 4}, e{0, 4};
    std::vector<Span> s;
    // Upper-right triangle (y down): points with x > y, plus the diagonal (ties go right: it is
    // the face on the right of the diagonal), plus the border column x = 4 except the corner
    // (4,4), whose perturbation (-eps, -eps^2) falls below the diagonal.
    CHECK(erd::scan_triangle(Lattice::pixels(), d, a, b, c, &s) == 5);
    REQUIRE(s.size() == 2);
    CHECK((s[0].y == 0 && s[0].x_begin == 0 && s[0].x_end == 2));
    CHECK((s[1].y == 1 && s[1].x_begin == 1 && s[1].x_end == 2));
    CHECK(erd::scan_triangle(Lattice::pixels(), d, a, c, e, &s) == 4);
    REQUIRE(s.size() == 2);
    CHECK((s[0].y == 1 && s[0].x_begin == 0 && s[0].x_end == 0));
    CHECK((s[1].y == 2 && s[1].x_begin == 0 && s[1].x_end == 2));
    // Degenerate triangles own nothing.
    CHECK(erd::scan_triangle(Lattice::pixels(), d, a, c, LatticePoint{2, 2}, &s) == 0);
    CHECK(s.empty());
}

TEST_CASE("raster: SpanPlane evaluates the plane along spans", "[raster]") {
    erd::SpanPlane p;
    REQUIRE(p.set({0, 0}, 10.0, {8, 0}, 50.0, {0, 6}, 4.0));
    CHECK(p.at(0, 0) == Approx(10.0));
    CHECK(p.at(8, 0) == Approx(50.0));
    CHECK(p.at(0, 6) == Approx(4.0));
    CHECK(p.at(4, 3) == Approx(10.0 + 20.0 - 3.0));
    const Lattice px = Lattice::pixels();
    double v = p.at(px, 1, 2);
    for (int i = 1; i <= 4; ++i, v += p.step_x(px)) CHECK(v == Approx(p.at(2.0 * i, 4.0)));
    const Lattice ss = Lattice::supersample();
    CHECK(p.at(ss, 0, 3) == Approx(p.at(-3.0 / 4, 3.0 / 4)));
    CHECK(p.step_x(ss) == Approx(5.0 / 2));
    erd::SpanPlane q;
    CHECK_FALSE(q.set({0, 0}, 1.0, {2, 2}, 2.0, {4, 4}, 3.0));
}

TEST_CASE("raster: a row window gives exactly the full scan's spans of those rows", "[raster]") {
    std::mt19937 rng(9090);
    const Lattice lats[2] = {Lattice::pixels(), Lattice::supersample()};
    std::int64_t windows_with_spans = 0;
    for (int trial = 0; trial < 15; ++trial) {
        const int W = 2 + int(rng() % 12), H = 2 + int(rng() % 12);
        const RasterDomain d{2 * W - 2, 2 * H - 2};
        const auto t = random_triangulation(rng, d.max_x, d.max_y, 12, trial % 2 == 0);
        for (const Lattice& l : lats) {
            const int nj = l.scale == 1 ? H : 4 * H;
            std::vector<Span> full, part;
            for (const Tri& f : t) {
                erd::scan_triangle(l, d, f[0], f[1], f[2], &full);
                for (int k = 0; k < 6; ++k) {
                    // Windows inside, across and outside the rows (also empty and reversed ones).
                    const std::int32_t jb = std::int32_t(rng() % std::uint32_t(nj + 4)) - 2;
                    const std::int32_t je = jb + std::int32_t(rng() % 7) - 1;
                    const std::int64_t n = erd::scan_triangle(l, d, f[0], f[1], f[2], &part, jb, je);
                    std::vector<Span> want;
                    std::int64_t count = 0;
                    for (const Span& s : full)
                        if (s.y >= jb && s.y <= je) {
                            want.push_back(s);
                            count += s.x_end - s.x_begin + 1;
                        }
                    CHECK(n == count);
                    REQUIRE(part.size() == want.size());
                    for (std::size_t i = 0; i < want.size(); ++i) {
                        CHECK(part[i].y == want[i].y);
                        CHECK(part[i].x_begin == want[i].x_begin);
                        CHECK(part[i].x_end == want[i].x_end);
                    }
                    windows_with_spans += !want.empty();
                }
            }
        }
    }
    CHECK(windows_with_spans > 100);
}

TEST_CASE("raster: RoundedPlane rounds half up exactly, stepped over its run", "[raster]") {
    using erd::RoundedPlane;
    std::mt19937 rng(2027);
    // Faces from tiny to the largest the kernel allows (doubled coordinates up to 65534), values
    // anywhere in [0, maxval] with the extremes and equal values (flat faces, many exact .5s).
    for (int iter = 0; iter < 3000; ++iter) {
        const std::int64_t maxval = iter % 3 == 0 ? 65535 : 255;
        const std::int32_t span = iter % 4 == 0 ? 65534 : iter % 4 == 1 ? 2000 : 40;
        LatticePoint p[3];
        std::int64_t z[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = {2 * std::int32_t(rng() % std::uint64_t(span / 2 + 1)), 2 * std::int32_t(rng() % std::uint64_t(span / 2 + 1))};
            const std::uint64_t pick = rng() % 6;
            z[k] = pick == 0 ? 0 : pick == 1 ? maxval : pick == 2 && k > 0 ? z[0] : std::int64_t(rng() % std::uint64_t(maxval + 1));
        }
        if (iter % 7 == 0) {  // a face with an edge midpoint on the lattice: v there is exactly (z0 + z1) / 2
            p[1] = {p[0].x + 4, p[0].y};
            p[2] = {p[0].x, p[0].y + 4};
        }
        RoundedPlane rp;
        const bool ok = rp.set(p[0], z[0], p[1], z[1], p[2], z[2], maxval);
        if (erd::orient2d(p[0], p[1], p[2]) == 0) {
            CHECK_FALSE(ok);
            continue;
        }
        REQUIRE(ok);
        REQUIRE(rp.run >= 1);
        // Rows of pixels in the closed face, each checked from its first pixel over the run.
        const std::int32_t ymin = std::min({p[0].y, p[1].y, p[2].y}) / 2, ymax = std::max({p[0].y, p[1].y, p[2].y}) / 2;
        const std::int32_t xmin = std::min({p[0].x, p[1].x, p[2].x}) / 2, xmax = std::max({p[0].x, p[1].x, p[2].x}) / 2;
        const std::int64_t o = erd::orient2d(p[0], p[1], p[2]);
        auto inside = [&](std::int32_t i, std::int32_t j) {
            const LatticePoint q{2 * i, 2 * j};
            const std::int64_t a = erd::orient2d(p[0], p[1], q), b = erd::orient2d(p[1], p[2], q), c = erd::orient2d(p[2], p[0], q);
            return o > 0 ? (a >= 0 && b >= 0 && c >= 0) : (a <= 0 && b <= 0 && c <= 0);
        };
        for (int row = 0; row < 6; ++row) {
            const std::int32_t j = ymin + std::int32_t(rng() % std::uint64_t(ymax - ymin + 1));
            std::int32_t i0 = xmin;
            while (i0 <= xmax && !inside(i0, j)) ++i0;
            if (i0 > xmax) continue;
            // Every pixel is checked; the assertion is per row (Catch2's per-pixel assertions were
            // most of the unit tests' time), naming the first pixel that differs.
            double v = rp.p_pixel(i0, j);
            std::int64_t bad_pixel = -1, checked = 0;
            for (std::int32_t i = i0, k = 0; i <= xmax && inside(i, j) && k < rp.run && k < 3000; ++i, ++k, v += rp.dp) {
                const std::int64_t want = erd_test::exact_rounded(p, z, 2 * std::int64_t(i), 2 * std::int64_t(j));
                const bool good = want >= 0 && want <= maxval && std::int64_t(std::int32_t(v)) == want &&
                                  std::int64_t(std::int32_t(rp.p_pixel(i, j))) == want;
                ++checked;
                if (!good) {
                    bad_pixel = i;
                    break;
                }
            }
            INFO("face " << p[0].x << "," << p[0].y << " " << p[1].x << "," << p[1].y << " " << p[2].x << ","
                         << p[2].y << " values " << z[0] << " " << z[1] << " " << z[2] << " row " << j
                         << " first wrong pixel " << bad_pixel);
            REQUIRE(checked >= 1);
            REQUIRE(bad_pixel == -1);
        }
    }
    // pieces() with short runs: every column once, in order, each piece from an exact start.
    for (int iter = 0; iter < 200; ++iter) {
        const LatticePoint p[3] = {{0, 0}, {2 * std::int32_t(20 + rng() % 60), 2 * std::int32_t(rng() % 10)},
                                   {2 * std::int32_t(rng() % 10), 2 * std::int32_t(20 + rng() % 40)}};
        const std::int64_t z[3] = {std::int64_t(rng() % 256), std::int64_t(rng() % 256), std::int64_t(rng() % 256)};
        RoundedPlane rp;
        REQUIRE(rp.set(p[0], z[0], p[1], z[1], p[2], z[2], 255));
        rp.run = std::int32_t(1 + iter % 5);
        std::vector<Span> spans;
        erd::scan_triangle(Lattice::pixels(), RasterDomain{2000, 2000}, p[0], p[1], p[2], &spans);
        for (const Span& s : spans) {
            std::int32_t next = s.x_begin;
            rp.pieces(s.x_begin, s.x_end, s.y, [&](std::int32_t first, std::int32_t last, double v) {
                REQUIRE(first == next);
                REQUIRE(last - first < rp.run);
                for (std::int32_t i = first; i <= last; ++i, v += rp.dp)
                    REQUIRE(std::int32_t(v) == erd_test::exact_rounded(p, z, 2 * std::int64_t(i), 2 * std::int64_t(s.y)));
                next = last + 1;
            });
            REQUIRE(next == s.x_end + 1);
        }
    }
    // Ties go up: the midpoint of values 73 and 54 is exactly 63.5, and 64 is its rounding.
    RoundedPlane rp;
    REQUIRE(rp.set(LatticePoint{0, 0}, 73, LatticePoint{4, 0}, 54, LatticePoint{0, 4}, 73, 255));
    CHECK(std::int32_t(rp.p_pixel(1, 0)) == 64);
    // Values outside [0, maxval] and collinear points are refused.
    CHECK_FALSE(rp.set(LatticePoint{0, 0}, -1, LatticePoint{4, 0}, 5, LatticePoint{0, 4}, 5, 255));
    CHECK_FALSE(rp.set(LatticePoint{0, 0}, 1, LatticePoint{4, 0}, 256, LatticePoint{0, 4}, 5, 255));
    CHECK_FALSE(rp.set(LatticePoint{0, 0}, 1, LatticePoint{2, 2}, 5, LatticePoint{4, 4}, 5, 255));
}
