// Image analysis for step 1 of the ERD methods (algorithms/imaging: filters, bilinear, canny,
// thinning, polylines, douglas_peucker): hand-worked values. MMSODD and error diffusion:
// test_error_diffusion.cpp.
#include <catch2/catch.hpp>
#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/bilinear.h"
#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/cell_list.h"
#include "algorithms/imaging/douglas_peucker.h"
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/point_rings.h"
#include "algorithms/imaging/polylines.h"
#include "algorithms/imaging/thinning.h"
#include "tests/test_grid_util.h"

using namespace erd;
using erd_test::Lcg;
using erd_test::make_grid;

namespace {

Grid<std::uint8_t> make_map(const std::vector<const char*>& rows) {
    Grid<std::uint8_t> m(int(std::string(rows[0]).size()), int(rows.size()), 0);
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x) m(x, y) = rows[std::size_t(y)][x] == '#' ? 1 : 0;
    return m;
}

bool has_full_2x2(const Grid<std::uint8_t>& m) {
    for (int y = 0; y + 1 < m.height; ++y)
        for (int x = 0; x + 1 < m.width; ++x)
            if (m(x, y) && m(x + 1, y) && m(x, y + 1) && m(x + 1, y + 1)) return true;
    return false;
}

// Component label of every set point (8-connectivity), 0 for unset.
std::vector<int> components(const Grid<std::uint8_t>& m) {
    std::vector<int> lab(m.size(), 0);
    int next = 0;
    std::vector<int> stack;
    for (int i = 0; i < int(m.size()); ++i) {
        if (!m.data[std::size_t(i)] || lab[std::size_t(i)]) continue;
        lab[std::size_t(i)] = ++next;
        stack.push_back(i);
        while (!stack.empty()) {
            int p = stack.back();
            stack.pop_back();
            int x = p % m.width, y = p / m.width;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int qx = x + dx, qy = y + dy;
                    if (!m.inside(qx, qy)) continue;
                    int q = qy * m.width + qx;
                    if (m.data[std::size_t(q)] && !lab[std::size_t(q)]) { lab[std::size_t(q)] = next; stack.push_back(q); }
                }
        }
    }
    return lab;
}

}  // namespace

TEST_CASE("binomial taps are rows of Pascal's triangle and sum to one", "[imaging]") {
    CHECK(binomial_taps(1) == std::vector<double>{1.0});
    CHECK(binomial_taps(3) == std::vector<double>{0.25, 0.5, 0.25});
    CHECK(binomial_taps(5) == std::vector<double>{1 / 16.0, 4 / 16.0, 6 / 16.0, 4 / 16.0, 1 / 16.0});
    CHECK(binomial_taps(7) == std::vector<double>{1 / 64.0, 6 / 64.0, 15 / 64.0, 20 / 64.0, 15 / 64.0, 6 / 64.0, 1 / 64.0});
    for (int n = 1; n <= 31; n += 2) {
        std::vector<double> t = binomial_taps(n);
        REQUIRE(int(t.size()) == n);
        double sum = 0;
        for (double v : t) sum += v;
        CHECK(sum == 1.0);
    }
    CHECK(binomial_taps(4).empty());
    CHECK(binomial_taps(0).empty());
    CHECK(binomial_taps(-3).empty());
    CHECK(compose_taps(derivative1_taps(), binomial_taps(3)) == std::vector<double>{0.125, 0.25, 0.0, -0.25, -0.125});
}

TEST_CASE("derivatives of polynomials: exact inside, zero extension at the border", "[imaging]") {
    // f(x) = x^2 on x = 0..9, one row.
    const Grid<double> sq = make_grid(10, 1, [](double x, double) { return x * x; });
    const Grid<double> d1 = convolve_rows(sq, derivative1_taps());
    for (int x = 1; x < 9; ++x) CHECK(d1(x, 0) == 2.0 * x);
    CHECK(d1(0, 0) == 0.5);    // (f(1) - 0) / 2
    CHECK(d1(9, 0) == -32.0);  // (0 - f(8)) / 2
    const Grid<double> d2 = convolve_rows(sq, derivative2_taps());
    for (int x = 1; x < 9; ++x) CHECK(d2(x, 0) == 2.0);
    CHECK(d2(0, 0) == 1.0);    // f(1) - 2 f(0) + 0
    CHECK(d2(9, 0) == -98.0);  // 0 - 2*81 + 64
    // Replicated border instead: f(10) := f(9).
    CHECK(convolve_rows(sq, derivative1_taps(), Border::replicate)(9, 0) == 8.5);
    // Cubic: the central difference gives 3x^2 + 1 exactly.
    const Grid<double> cube = make_grid(10, 1, [](double x, double) { return x * x * x; });
    const Grid<double> c1 = convolve_rows(cube, derivative1_taps());
    for (int x = 1; x < 9; ++x) CHECK(c1(x, 0) == 3.0 * x * x + 1.0);
    // Columns behave like rows on the transposed signal; y grows downward.
    const Grid<double> col = make_grid(1, 10, [](double, double y) { return y * y; });
    const Grid<double> dc = convolve_cols(col, derivative1_taps());
    for (int y = 1; y < 9; ++y) CHECK(dc(0, y) == 2.0 * y);
    CHECK(dc(0, 9) == -32.0);
    // Binomial smoothing keeps linear functions inside and adds the variance to a quadratic:
    // [1 2 1]/4 has variance 1/2.
    const Grid<double> s3 = convolve_rows(sq, binomial_taps(3));
    for (int x = 1; x < 9; ++x) CHECK(s3(x, 0) == x * x + 0.5);
    // The composed filter equals filtering twice where no border is involved.
    const std::vector<double> comp = compose_taps(derivative1_taps(), binomial_taps(5));
    const Grid<double> once = convolve_rows(cube, comp);
    const Grid<double> twice = convolve_rows(convolve_rows(cube, binomial_taps(5)), derivative1_taps());
    for (int x = 3; x < 7; ++x) CHECK(once(x, 0) == Approx(twice(x, 0)).epsilon(1e-12));
}

TEST_CASE("phi_bar interpolates the samples and resamples onto the half-pixel grid", "[imaging]") {
    Lcg rng{7};
    const Grid<double> im = make_grid(7, 5, [&](double, double) { return std::floor(rng.next() * 256) + rng.next(); });
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            CHECK(bilinear(im, x, y) == im(x, y));
            CHECK(bilinear_doubled(im, 2 * x, 2 * y) == im(x, y));
        }
    CHECK(bilinear(im, 2.5, 1) == Approx(0.5 * (im(2, 1) + im(3, 1))));
    CHECK(bilinear(im, 2.5, 1.5) == Approx(0.25 * (im(2, 1) + im(3, 1) + im(2, 2) + im(3, 2))));
    CHECK(bilinear(im, 2.25, 3.0) == Approx(0.75 * im(2, 3) + 0.25 * im(3, 3)));
    CHECK(bilinear(im, -3, -1) == im(0, 0));  // clamped onto Gamma
    CHECK(bilinear(im, 99, 4.0) == im(6, 4));
    const Grid<double> hp = half_pixel(im);
    REQUIRE(hp.width == 13);
    REQUIRE(hp.height == 9);
    for (int Y = 0; Y < 9; ++Y)
        for (int X = 0; X < 13; ++X) CHECK(hp(X, Y) == Approx(bilinear(im, X / 2.0, Y / 2.0)).epsilon(1e-12));
}

TEST_CASE("beta quantile: exactly round(beta * n) values at or above it", "[imaging]") {
    std::vector<float> v;
    for (int i = 1; i <= 100; ++i) v.push_back(float(i));
    CHECK(beta_quantile(v.data(), v.size(), 0.10) == 91.0);  // the 10th largest
    CHECK(beta_quantile(v.data(), v.size(), 0.004) == 100.0);  // k rounds to 0, at least 1
    CHECK(beta_quantile(v.data(), v.size(), 1.0) == 1.0);
    Lcg rng{12345};
    std::vector<float> r(50000);
    for (float& x : r) x = float(rng.next() * 1000.0);
    for (double beta : {0.0095, 0.028, 0.055, 0.5}) {
        const double t = beta_quantile(r.data(), r.size(), beta);
        const std::size_t k = std::size_t(std::nearbyint(beta * double(r.size())));
        std::size_t at_or_above = 0;
        for (float x : r) at_or_above += x >= float(t);
        std::size_t distinct_ties = 0;
        for (float x : r) distinct_ties += x == float(t);
        if (distinct_ties == 1) CHECK(at_or_above == k);
        CHECK(at_or_above >= k);
    }
    std::vector<float> same(40, 5.0f);  // ties all count
    CHECK(beta_quantile(same.data(), same.size(), 0.1) == 5.0);
    CHECK(beta_quantile(nullptr, 0, 0.1) == 0.0);
}

TEST_CASE("thinning leaves one-point-wide curves", "[imaging]") {
    Grid<std::uint8_t> bar = make_map({
        "..............",
        ".############.",
        ".############.",
        ".############.",
        "..............",
    });
    thin_edges(&bar);
    CHECK_FALSE(has_full_2x2(bar));
    int set = 0;
    for (auto v : bar.data) set += v;
    CHECK(set >= 8);
    for (int x = 3; x <= 10; ++x) {  // inside, one point per column
        int n = 0;
        for (int y = 0; y < bar.height; ++y) n += bar(x, y);
        CHECK(n == 1);
    }
    // A staircase keeps no corner points: every point has at most two neighbours.
    Grid<std::uint8_t> stairs = make_map({
        "##.....",
        ".##....",
        "..##...",
        "...##..",
        "....##.",
    });
    thin_edges(&stairs);
    for (int y = 0; y < stairs.height; ++y)
        for (int x = 0; x < stairs.width; ++x) {
            if (!stairs(x, y)) continue;
            int n = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if ((dx || dy) && stairs.inside(x + dx, y + dy)) n += stairs(x + dx, y + dy);
            CHECK(n <= 2);
        }
    CHECK(components(stairs) == components(stairs));  // still one piece:
    int comps = 0;
    for (int l : components(stairs)) comps = std::max(comps, l);
    CHECK(comps == 1);
}

TEST_CASE("a step edge at x = 9.8 is found within half a pixel and thinned", "[imaging]") {
    // Box-filtered step: pixel x covers [x - 1/2, x + 1/2]; the part right of 9.8 is bright.
    const double e = 9.8;
    const Grid<double> im = make_grid(24, 16, [&](double x, double) { return 100.0 * std::clamp(x + 0.5 - e, 0.0, 1.0); });
    CannyParams p;
    p.beta = 0.05;
    Grid<std::uint8_t> edges;
    CannyStats st;
    REQUIRE(detect_edges(im, p, &edges, &st).ok());
    REQUIRE(edges.width == 47);
    REQUIRE(edges.height == 31);
    CHECK_FALSE(has_full_2x2(edges));
    for (int Y = 0; Y < edges.height; ++Y) {
        int n = 0;
        for (int X = 0; X < edges.width; ++X)
            if (edges(X, Y)) {
                ++n;
                CHECK(std::fabs(X - 2 * e) <= 1.0);  // half-pixel grid units
            }
        CHECK(n == 1);
    }
    // A slanted edge x = 6 + 0.4 y: one point per row, within one grid unit.
    const Grid<double> slant = make_grid(24, 20, [](double x, double y) { return 200.0 * std::clamp(x + 0.5 - (6 + 0.4 * y), 0.0, 1.0); });
    REQUIRE(detect_edges(slant, p, &edges, &st).ok());
    CHECK_FALSE(has_full_2x2(edges));
    for (int Y = 4; Y < edges.height - 4; ++Y) {
        int n = 0;
        for (int X = 0; X < edges.width; ++X)
            if (edges(X, Y)) {
                ++n;
                CHECK(std::fabs(X - 2 * (6 + 0.4 * (Y / 2.0))) <= 1.0);
            }
        CHECK(n == 1);
    }
    // A flat image has no edges whatever beta is.
    REQUIRE(detect_edges(Grid<double>(9, 9, 42.0), p, &edges, &st).ok());
    CHECK(std::count(edges.data.begin(), edges.data.end(), 1) == 0);
    // Bad parameters are input errors.
    p.beta = 0;
    CHECK(detect_edges(im, p, &edges).code == Code::input);
    p.beta = 0.05;
    p.r = 1.5;
    CHECK(detect_edges(im, p, &edges).code == Code::input);
    CHECK(detect_edges(Grid<double>(), CannyParams(), &edges).code == Code::input);
}

TEST_CASE("a T-junction keeps its junction with the modified Canny and loses it with plain Canny", "[imaging]") {
    // Top: 0. Bottom left: 100, bottom right: 130; the strong bar y = 11.5 meets the weaker stem
    // x = 15.5. Plain Canny stops the stem two points short of the bar: those points lie on the
    // bar's flank, where the magnitude peaks in no direction along the stem's gradient.
    const Grid<double> im = make_grid(32, 24, [](double x, double y) { return y < 12 ? 0.0 : (x < 16 ? 100.0 : 130.0); });
    CannyParams p;
    p.beta = 0.12;
    Grid<std::uint8_t> modified, plain;
    CannyStats sm, sp;
    REQUIRE(detect_edges(im, p, &modified, &sm).ok());
    p.modified = false;
    REQUIRE(detect_edges(im, p, &plain, &sp).ok());
    // Points well inside the bar (left part) and the stem.
    const int bar_x = 10, stem_y = 40;
    auto find_in_column = [](const Grid<std::uint8_t>& m, int X) { for (int Y = 0; Y < m.height; ++Y) if (m(X, Y)) return Y * m.width + X; return -1; };
    auto find_in_row = [](const Grid<std::uint8_t>& m, int Y) { for (int X = 0; X < m.width; ++X) if (m(X, Y)) return Y * m.width + X; return -1; };
    const int bm = find_in_column(modified, bar_x), tm = find_in_row(modified, stem_y);
    const int bp = find_in_column(plain, bar_x), tp = find_in_row(plain, stem_y);
    REQUIRE(bm >= 0);
    REQUIRE(tm >= 0);
    REQUIRE(bp >= 0);
    REQUIRE(tp >= 0);
    const std::vector<int> lm = components(modified), lp = components(plain);
    CHECK(lm[std::size_t(bm)] == lm[std::size_t(tm)]);
    CHECK(lp[std::size_t(bp)] != lp[std::size_t(tp)]);
    CHECK(sm.added_points > 0);
    CHECK(sp.added_points == 0);
}

namespace {

// A detection by `detector` (reusing its pass when it can) against a fresh detect_edges: the same
// map and statistics, and some edge points.
void check_as_fresh(EdgeDetector* detector, const Image& im, double beta, double r) {
    CannyParams p;
    p.beta = beta;
    p.r = r;
    Grid<std::uint8_t> a, b;
    CannyStats sa, sb;
    REQUIRE(detector->detect(p, &a, &sa).ok());
    REQUIRE(detect_edges(im, p, &b, &sb).ok());
    CHECK(a.data == b.data);
    CHECK(sa.tau_high == sb.tau_high);
    CHECK(sa.above_high == sb.above_high);
    CHECK(sa.main_points == sb.main_points);
    CHECK(sa.added_points == sb.added_points);
    CHECK(sa.edge_points == sb.edge_points);
    CHECK(sa.edge_points > 0);
}

}  // namespace

TEST_CASE("EdgeDetector reuses its gradient pass and gives what detect_edges gives", "[imaging]") {
    // Disks, a ramp and hashed noise, so that many points sit near every threshold.
    Image im(61, 47, 255);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double d1 = std::hypot(x - 20.3, y - 17.6), d2 = std::hypot(x - 44.1, y - 30.2);
            double v = 40 + 1.5 * x + (d1 < 11 ? 90 : 0) + (d2 < 8 ? -35 : 0);
            v += double((std::uint32_t(x) * 2654435761u ^ std::uint32_t(y) * 40503u) % 17u);
            im.at(x, y) = std::uint16_t(std::min(255.0, v));
        }
    EdgeDetector detector(im);
    // Falling beta with r fixed (ERD's loop) reuses the pass; a lower r or a larger beta needs
    // thresholds below what the pass kept and makes a new one; both must match a fresh detection.
    const double runs[][2] = {{0.055, 0.4}, {0.028, 0.4}, {0.021, 0.4}, {0.028, 0.1}, {0.2, 0.4}, {0.02, 0.9}};
    for (const auto& run : runs) check_as_fresh(&detector, im, run[0], run[1]);
    detector.release();
    CannyParams bad;
    bad.beta = 0;
    Grid<std::uint8_t> e;
    CHECK(detector.detect(bad, &e).code == Code::input);
}

TEST_CASE("a narrowed pass keeps what the detections it covers need", "[imaging]") {
    Image im(64, 52, 255);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            double v = 60 + 1.2 * y + (std::hypot(x - 30.5, y - 24.2) < 15 ? 70 : 0);
            v += double((std::uint32_t(x) * 2654435761u ^ std::uint32_t(y) * 40503u) % 29u);
            im.at(x, y) = std::uint16_t(std::min(255.0, v));
        }
    EdgeDetector detector(im);
    CannyParams widest;
    widest.beta = 0.055;
    widest.r = 0.4;
    REQUIRE(detector.prepare(widest).ok());
    const std::size_t wide = detector.pass_points();
    CannyParams cut = widest;
    cut.beta = 0.028;
    detector.narrow(cut);
    CHECK(detector.pass_points() == wide);  // cut when the next detection runs
    std::size_t narrow = 0;
    // Covered detections (beta at most 0.028, r 0.4) match fresh ones without a new pass; the
    // others (a larger beta, a lower r) make one, and match too.
    const double runs[][2] = {{0.028, 0.4}, {0.02, 0.4}, {0.011, 0.4}, {0.055, 0.4}, {0.028, 0.2}};
    for (const auto& run : runs) {
        check_as_fresh(&detector, im, run[0], run[1]);
        if (narrow == 0) {
            narrow = detector.pass_points();
            CHECK(narrow > 0);
            CHECK(narrow < wide * 3 / 4);
        }
        if (run[0] <= 0.028 && run[1] == 0.4) CHECK(detector.pass_points() == narrow);  // served by it
        else CHECK(detector.pass_points() > narrow);  // a new, wider pass
    }
    // Narrowing to a beta the pass does not cover changes nothing.
    CannyParams wider = widest;
    wider.beta = 0.5;
    const std::size_t before = detector.pass_points();
    detector.narrow(wider);
    CHECK(detector.pass_points() == before);
}

TEST_CASE("PointBits::remove_unless keeps the other points and their ranks", "[imaging]") {
    std::vector<std::uint32_t> at;
    for (std::uint32_t c = 11; c < 4000; c += 1 + (c * 7u) % 5u) at.push_back(c);
    PointBits bits;
    bits.build(at.data(), at.size(), 100);
    std::vector<std::uint32_t> left;
    bits.remove_unless([&](std::uint32_t k, std::uint32_t p) {
        CHECK(p == at[k]);
        if (k % 3 == 1) return false;
        left.push_back(p);
        return true;
    });
    REQUIRE(bits.size() == left.size());
    for (std::uint32_t k = 0; k < left.size(); ++k) CHECK(bits.index(left[k]) == k);
    std::vector<std::uint32_t> seen;
    bits.for_each([&](std::uint32_t k, std::uint32_t p) {
        CHECK(k == seen.size());
        seen.push_back(p);
    });
    CHECK(seen == left);
}

TEST_CASE("CellList gives back the cells pushed, near or far, and truncates", "[imaging]") {
    for (const std::ptrdiff_t stride : {std::ptrdiff_t(3), std::ptrdiff_t(24), std::ptrdiff_t(2051), std::ptrdiff_t(65538)}) {
        CellList list(stride);
        std::vector<std::uint32_t> cells;
        std::uint32_t c = 5, state = 12345;
        for (int k = 0; k < 5000; ++k) {
            state = state * 1103515245u + 12345u;
            const int kind = int(state >> 28) % 4;
            const int dx = int((state >> 8) % 31u) - 15, dy = int((state >> 16) % 13u) - 6;
            if (kind == 0) c = state;  // anywhere, the largest cells too
            else c = std::uint32_t(std::int64_t(c) + std::int64_t(dy) * stride + dx);
            cells.push_back(c);
            list.push_back(c);
        }
        cells.push_back(0xFFFFFFFFu);
        list.push_back(0xFFFFFFFFu);
        cells.push_back(0);
        list.push_back(0);
        REQUIRE(list.size() == cells.size());
        CellList::Cursor cur, half;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            if (k == cells.size() / 2) half = cur;
            REQUIRE(list.next(&cur) == cells[k]);
        }
        CHECK(cur.index == list.end().index);
        CHECK(cur.byte == list.end().byte);
        // Steps within 5 rows and 11 columns take one byte each (rows wider than the window).
        if (stride >= 24) {
            CellList near(stride);
            std::uint32_t q = 1u << 31;
            near.push_back(q);  // from 0: far
            for (int dy = -5; dy <= 5; ++dy)
                for (int dx = -11; dx <= 11; ++dx) near.push_back(q = std::uint32_t(std::int64_t(q) + dy * stride + dx));
            CHECK(near.end().byte == 5 + 11 * 23);
        }
        list.truncate(half);
        REQUIRE(list.size() == cells.size() / 2);
        list.push_back(7);
        list.push_back(7 + std::uint32_t(stride) + 1);
        CellList::Cursor again;
        for (std::size_t k = 0; k < cells.size() / 2; ++k) REQUIRE(list.next(&again) == cells[k]);
        CHECK(list.next(&again) == 7);
        CHECK(list.next(&again) == 7 + std::uint32_t(stride) + 1);
    }
}

namespace {

// Plain Canny without thinning, the straightforward way: the whole gradient and magnitude planes,
// the quantile over all of them, suppression on the plane with its frame replicated, then a flood
// from the seeds. The streamed pass (suppression row by row, points kept above a rising bound)
// must give exactly this.
Grid<std::uint8_t> plain_canny_reference(const Image& im, double beta, double r, double* tau_high) {
    Grid<double> f0(im.width, im.height);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) f0(x, y) = im.at(x, y);
    const Grid<double> f = half_pixel(f0);
    Grid<float> gx, gy;
    canny_gradient(f, 5, Border::replicate, &gx, &gy);
    const int W = f.width, H = f.height;
    Grid<float> g(W, H);
    for (std::size_t i = 0; i < g.size(); ++i) {
        const float sq = gx.data[i] * gx.data[i] + gy.data[i] * gy.data[i];
        g.data[i] = std::sqrt(sq);
    }
    *tau_high = beta_quantile(g.data.data(), g.size(), beta);
    const float th = float(*tau_high), tl = float(r * *tau_high);
    auto at = [&](int X, int Y) { return g(std::min(std::max(X, 0), W - 1), std::min(std::max(Y, 0), H - 1)); };
    Grid<std::uint8_t> cand(W, H, 0), out(W, H, 0);
    for (int Y = 0; Y < H; ++Y)
        for (int X = 0; X < W; ++X) {
            const float m = g(X, Y), ux = gx(X, Y), uy = gy(X, Y);
            if (!(m >= tl) || m <= 0.0f) continue;
            const int sx = ux > 0 ? 1 : -1, sy = uy > 0 ? 1 : -1;
            float ahead, behind;
            if (std::fabs(ux) >= std::fabs(uy)) {
                const float w = std::fabs(uy) / std::fabs(ux);
                ahead = (1.0f - w) * at(X + sx, Y) + w * at(X + sx, Y + sy);
                behind = (1.0f - w) * at(X - sx, Y) + w * at(X - sx, Y - sy);
            } else {
                const float w = std::fabs(ux) / std::fabs(uy);
                ahead = (1.0f - w) * at(X, Y + sy) + w * at(X + sx, Y + sy);
                behind = (1.0f - w) * at(X, Y - sy) + w * at(X - sx, Y - sy);
            }
            cand(X, Y) = m > ahead && m >= behind;
        }
    std::vector<int> stack;
    for (int i = 0; i < int(g.size()); ++i) {
        if (!cand.data[std::size_t(i)] || out.data[std::size_t(i)] || !(g.data[std::size_t(i)] >= th)) continue;
        out.data[std::size_t(i)] = 1;
        stack.push_back(i);
        while (!stack.empty()) {
            const int p = stack.back(), x = p % W, y = p / W;
            stack.pop_back();
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= W || qy >= H || !cand(qx, qy) || out(qx, qy)) continue;
                    out(qx, qy) = 1;
                    stack.push_back(qy * W + qx);
                }
        }
    }
    return out;
}

}  // namespace

TEST_CASE("the streamed edge pass equals plain Canny computed on whole planes", "[imaging]") {
    // Shapes, a ramp and hashed noise; a flat image (no edges); one-row, one-column and one-pixel
    // images; a 12-bit image; a large flat part first, so the bound stays low for many rows.
    // Images of 129 rows or more are tall enough for the pass to start from a bound guessed from
    // a sample of rows (half-pixel rows 16, 17, 48, 49, ...); on the last one the noise lies only
    // on the pixel rows the sample sees (8, 24, 40, ...), so the guess is too high and the pass
    // must notice and run again.
    auto make = [](int w, int h, std::uint32_t maxval, int kind) {
        Image im(w, h, maxval);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = std::hypot(x - 0.4 * w, y - 0.6 * h);
                double v = kind == 1 ? 77.0 : 30 + 0.8 * x + (d < 0.3 * std::min(w, h) ? 0.5 * maxval : 0.0);
                if (kind == 0) v += double((std::uint32_t(x) * 2654435761u ^ std::uint32_t(y) * 40503u) % 23u);
                if (kind == 2 && y < h / 2) v = 9.0;
                if (kind == 3) v = 100.0 + (y % 16 == 8 ? 5.0 * double((std::uint32_t(x) * 2654435761u) % 23u) : 0.0);
                im.at(x, y) = std::uint16_t(std::min(double(maxval), v));
            }
        return im;
    };
    const Image images[] = {make(37, 29, 255, 0), make(23, 41, 4095, 0), make(16, 16, 255, 1), make(19, 1, 255, 0),
                            make(1, 17, 255, 0),  make(1, 1, 255, 0),    make(45, 60, 255, 2),
                            make(40, 140, 255, 0), make(40, 140, 255, 2), make(36, 150, 255, 3)};
    const double betas[] = {0.01, 0.055, 0.3, 1.0};
    const double rs[] = {0.0, 0.4, 1.0};
    int with_edges = 0;
    for (const Image& im : images) {
        EdgeDetector detector(im);
        for (const double beta : betas)
            for (const double r : rs) {
                CannyParams p;
                p.beta = beta;
                p.r = r;
                p.modified = false;
                p.thin = false;
                double tau = 0;
                const Grid<std::uint8_t> want = plain_canny_reference(im, beta, r, &tau);
                Grid<std::uint8_t> got, reused;
                CannyStats st;
                REQUIRE(detect_edges(im, p, &got, &st).ok());
                REQUIRE(detector.detect(p, &reused).ok());
                CHECK(st.tau_high == tau);
                CHECK(got.data == want.data);
                CHECK(reused.data == want.data);
                with_edges += std::count(want.data.begin(), want.data.end(), 1) > 0;
            }
    }
    CHECK(with_edges > 40);  // the comparisons are not all between empty maps
}

TEST_CASE("tracing splits at junctions and keeps closed loops", "[imaging]") {
    // A T of three arms, a ring without nodes, an isolated point.
    const Grid<std::uint8_t> m = make_map({
        "#####.......",
        "..#.....###.",
        "..#....#...#",
        "..#.....###.",
        "............",
        "..........#.",
    });
    const PolylineList lines = trace_polylines(m);
    REQUIRE(lines.points() == 3 + 3 + 4 + 1 + 9);
    REQUIRE(lines.size() == 5);
    // Node order is row-major: (0,0) first, then the junction (2,0).
    CHECK(lines[0] == Polyline{{0, 0}, {1, 0}, {2, 0}});
    CHECK(lines[1] == Polyline{{2, 0}, {3, 0}, {4, 0}});
    CHECK(lines[2] == Polyline{{2, 0}, {2, 1}, {2, 2}, {2, 3}});
    CHECK(lines[3] == Polyline{{10, 5}});
    const Polyline ring = lines[4];
    CHECK(ring.size() == 9);  // 8 points, first repeated
    CHECK(ring.front() == ring.back());
    CHECK(ring.front() == LatticePoint{8, 1});
}

TEST_CASE("Douglas-Peucker keeps exactly the expected points", "[imaging]") {
    const Polyline line{{0, 0}, {4, 1}, {8, 0}, {12, 6}, {16, 0}, {20, 0}};
    // eps 2: (12,6) is 6 off the chord; then (8,0) is 3.58 off (0,0)-(12,6) and (4,1) 1 off
    // (0,0)-(8,0); (16,0) is 2.4 off (12,6)-(20,0).
    CHECK(douglas_peucker(line, 2.0) == Polyline{{0, 0}, {8, 0}, {12, 6}, {16, 0}, {20, 0}});
    CHECK(douglas_peucker(line, 3.0) == Polyline{{0, 0}, {8, 0}, {12, 6}, {20, 0}});
    CHECK(douglas_peucker(line, 0.5) == line);
    CHECK(douglas_peucker(line, 7.0) == Polyline{{0, 0}, {20, 0}});
    // A closed square loop keeps its corners and its repeated start.
    const Polyline loop{{0, 0}, {4, 0}, {8, 0}, {8, 4}, {8, 8}, {4, 8}, {0, 8}, {0, 4}, {0, 0}};
    CHECK(douglas_peucker(loop, 1.0) == Polyline{{0, 0}, {8, 0}, {8, 8}, {0, 8}, {0, 0}});
    // The length filter counts traced points by default, simplified points on request.
    PolylineList lines(64);
    lines.add(line);
    lines.add(Polyline{{0, 0}, {2, 0}, {4, 0}, {6, 0}});
    CHECK(simplify_polylines(lines, 2.0, 5).size() == 1);
    CHECK(simplify_polylines(lines, 2.0, 4).size() == 2);
    CHECK(simplify_polylines(lines, 2.0, 4, LengthRule::after_simplification).size() == 1);
    // Long lines need no recursion: a zigzag of growing amplitude keeps every point and splits
    // next to the last point each time, 10000 levels deep (a recursive version's non-tail call),
    // run on a thread with a 128 KiB stack, which such a version overflows (it does, at -O2).
    // The zigzag costs n^2/2 distances: 10000 points, not more.
    struct Job {
        Polyline zig;
        std::size_t kept = 0;
    } job;
    for (int i = 0; i < 10000; ++i) job.zig.push_back({i, (i % 2) * (i + 4)});
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    REQUIRE(pthread_attr_setstacksize(&attr, 128 * 1024) == 0);
    pthread_t thread;
    auto body = [](void* p) -> void* {
        Job* j = static_cast<Job*>(p);
        j->kept = douglas_peucker(j->zig, 1.0).size();
        return nullptr;
    };
    REQUIRE(pthread_create(&thread, &attr, body, &job) == 0);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    CHECK(job.kept == job.zig.size());
}
