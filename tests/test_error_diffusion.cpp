// ED's sample points (thesis 3.2.1): the MMSODD density (hand-worked values, and the one-sweep
// MMSODD against the three separable filters) and error diffusion (exact counts, masks, bad
// input, and the 16-lane sweep of the count search against single passes).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/mmsodd.h"
#include "tests/test_grid_util.h"

using namespace erd;
using erd_test::Lcg;
using erd_test::make_grid;

namespace {

// Deterministic pseudo-random values in [0, 1).
struct Rng {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(s >> 11) / 9007199254740992.0;
    }
};

Grid<double> random_grid(int w, int h, std::uint64_t seed, double scale, bool integers) {
    Rng rng{seed};
    Grid<double> g(w, h);
    for (double& v : g.data) v = integers ? std::floor(rng.next() * scale) : rng.next() * scale;
    return g;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("MMSODD of x^2 + y^2, x*y, and a constant at the border", "[imaging]") {
    CHECK(mmsodd_value(2, 2, 0) == 2.0);
    CHECK(mmsodd_value(0, 0, 1) == 1.0);
    CHECK(mmsodd_value(3, -1, 0) == 3.0);  // eigenvalues 3 and -1
    CHECK(mmsodd_value(0, 0, -2) == 2.0);
    const Grid<double> bowl = make_grid(16, 14, [](double x, double y) { return x * x + y * y; });
    const Grid<double> saddle = make_grid(16, 14, [](double x, double y) { return x * y; });
    for (int order : {1, 3, 5}) {
        const int margin = order / 2 + 1;
        const Grid<double> db = mmsodd(bowl, order), ds = mmsodd(saddle, order);
        for (int y = margin; y < 14 - margin; ++y)
            for (int x = margin; x < 16 - margin; ++x) {
                CHECK(db(x, y) == Approx(2.0).epsilon(1e-12));
                CHECK(ds(x, y) == Approx(1.0).epsilon(1e-12));
            }
    }
    // Constant 10, no smoothing, zero extension: at the corner fxx = fyy = 10(0 - 2 + 1) = -10,
    // fxy = (5 - 0)/2 = 2.5, so l1 = -10, l2 = 2.5 and d = 12.5. Inside: 0.
    const Grid<double> flat(6, 5, 10.0);
    const Grid<double> df = mmsodd(flat, 1);
    CHECK(df(0, 0) == 12.5);
    CHECK(df(2, 2) == 0.0);
}

TEST_CASE("MMSODD from one smoothing equals the three separable filters", "[imaging]") {
    // The reference is the definition: three separable filter pairs (mmsodd_separable).
    // Integer samples (what the methods pass) up to 16 bits: bit for bit, since both ways are
    // exact up to the formula. Non-integer samples: equal to rounding. Sizes below, at and
    // above the block of the vectorised row sum (64) and the filter lengths.
    // (Border::replicate is served by mmsodd_separable itself, so only the zero border is new.)
    for (int order : {1, 3, 5, 7, 9})
        for (int size : {1, 2, 5, 9, 64, 67, 130}) {
            INFO("order " << order << " size " << size);
            const int h = size / 2 + 1;
            const Grid<double> ints = random_grid(size, h, std::uint64_t(order * 1000 + size), 65536.0, true);
            const Grid<double> d = mmsodd(ints, order), want = mmsodd_separable(ints, order, Border::zero);
            REQUIRE(d.width == ints.width);
            REQUIRE(d.height == ints.height);
            std::size_t differ = 0;
            for (std::size_t i = 0; i < d.data.size(); ++i) differ += !same_bits(d.data[i], want.data[i]);
            CHECK(differ == 0);
            const Grid<double> reals = random_grid(size, h, std::uint64_t(order * 1000 + size + 7), 300.0, false);
            const Grid<double> dr = mmsodd(reals, order), wr = mmsodd_separable(reals, order, Border::zero);
            double worst = 0;
            for (std::size_t i = 0; i < dr.data.size(); ++i)
                worst = std::max(worst, std::fabs(dr.data[i] - wr.data[i]));
            CHECK(worst <= 1e-9);
        }
    // A corner at full scale and a single spike: values on and next to the frame.
    Grid<double> spike(9, 7, 0.0);
    spike(0, 0) = 65535;
    spike(4, 3) = 1;
    for (int order : {3, 5}) CHECK(mmsodd(spike, order).data == mmsodd_separable(spike, order, Border::zero).data);
}

TEST_CASE("MMSODD of an image's samples equals that of its grid", "[imaging]") {
    for (int order : {1, 3, 5}) {
        Image im(37, 23, 65535);
        Rng rng{std::uint64_t(order)};
        for (auto& v : im.samples) v = std::uint16_t(rng.next() * 65536.0);
        im.at(0, 0) = 65535;
        const Grid<double> a = mmsodd(im, order), b = mmsodd(to_grid(im), order);
        REQUIRE(a.width == 37);
        REQUIRE(a.height == 23);
        CHECK(a.data == b.data);
    }
    CHECK(mmsodd(Image(0, 0, 255), 3).data.empty());
}

TEST_CASE("mmsodd_value is the larger magnitude of l1 +- l2", "[imaging]") {
    Rng rng{11};
    for (int i = 0; i < 10000; ++i) {
        const double fxx = (rng.next() - 0.5) * 1e3, fyy = (rng.next() - 0.5) * 1e3, fxy = (rng.next() - 0.5) * 1e3;
        const double l1 = 0.5 * (fxx + fyy), hd = 0.5 * (fxx - fyy), l2 = std::sqrt(hd * hd + fxy * fxy);
        REQUIRE(same_bits(mmsodd_value(fxx, fyy, fxy), std::fmax(std::fabs(l1 + l2), std::fabs(l1 - l2))));
    }
    CHECK(mmsodd_value(-0.0, 0.0, -0.0) == 0.0);
    CHECK(mmsodd_value(2.0, 2.0, 0.0) == 2.0);
    CHECK(mmsodd_value(2.0, -2.0, 0.0) == 2.0);
}

TEST_CASE("the count search's lanes choose what single passes choose", "[imaging]") {
    // select_points runs 4 thresholds in its first sweep and 16 in each later one; the pass it
    // returns must be exactly the single pass diffuse() makes at the returned threshold (same
    // arithmetic per lane), points included.
    const Grid<double> smooth = random_grid(53, 41, 3, 1.0, false);
    Grid<double> ramp(70, 33);
    for (int y = 0; y < ramp.height; ++y)
        for (int x = 0; x < ramp.width; ++x) ramp(x, y) = double(x * y) / double(70 * 33);
    Grid<std::uint8_t> forbid(70, 33, 0);
    for (int y = 0; y < 33; y += 3) forbid(y % 70, y) = forbid(69, y) = 1;
    struct Case {
        const Grid<double>* density;
        const Grid<std::uint8_t>* forbidden;
        std::size_t k;
    };
    const Case cases[] = {{&smooth, nullptr, 40}, {&smooth, nullptr, 500}, {&ramp, &forbid, 77}, {&ramp, nullptr, 300}};
    for (const Case& c : cases)
        for (Startup mode : {Startup::none, Startup::mirror, Startup::force}) {
            DiffusionParams dp;
            dp.startup = mode;
            dp.forbidden = c.forbidden;
            DiffusionResult r;
            REQUIRE(select_points(*c.density, c.k, dp, &r).ok());
            INFO("k " << c.k << " mode " << int(mode));
            CHECK(r.exact);
            CHECK(r.sweeps >= 1);
            CHECK(r.passes == 4 + 16 * (r.sweeps - 1));
            std::vector<LatticePoint> single;
            CHECK(diffuse(*c.density, r.rho, dp, &single) == r.points.size());
            CHECK(single == r.points);
            if (c.forbidden)
                for (LatticePoint p : r.points) CHECK(!(*c.forbidden)(p.x / 2, p.y / 2));
        }
}

TEST_CASE("ed_density in place equals the formula", "[imaging]") {
    Grid<double> d(3, 2);
    d.data = {0.0, 1.0, 4.0, 2.0, -1.0, 3.0};
    const Grid<double> one = ed_density(d, 1.0), half = ed_density(d, 0.5), other = ed_density(d, 2.0);
    const std::vector<double> want1 = {0.0, 0.25, 1.0, 0.5, 0.0, 0.75};
    CHECK(one.data == want1);
    CHECK(half(1, 0) == std::sqrt(0.25));
    CHECK(other(0, 1) == std::pow(0.5, 2.0));
    CHECK(d(1, 0) == 1.0);  // an lvalue argument is copied, not changed
    const Grid<double> moved = ed_density(Grid<double>(2, 2, -5.0), 1.0);
    CHECK(moved.data == std::vector<double>(4, 0.0));
}

TEST_CASE("error diffusion returns the exact count from 4 to W*H/2", "[imaging]") {
    const int w = 40, h = 30;
    Lcg rng{99};
    const std::vector<Grid<double>> densities = {
        make_grid(w, h, [](double x, double y) { return (x + 1) * (y + 2) / (w * double(h + 1)); }),
        make_grid(w, h, [](double x, double y) { return std::exp(-((x - 20) * (x - 20) + (y - 12) * (y - 12)) / 60.0); }),
        make_grid(w, h, [&](double, double) { return rng.next(); }),
        make_grid(w, h, [](double x, double y) { return (int(x) / 5 + int(y) / 5) % 2 ? 1.0 : 0.1; }),
    };
    std::vector<std::size_t> counts = {4, 5, 7, 12, 30, 57, 100, 150, 222, 300, 451, 599, 600};
    for (std::size_t img = 0; img < densities.size(); ++img)
        for (Startup mode : {Startup::none, Startup::mirror, Startup::force})
            for (std::size_t k : counts) {
                DiffusionParams dp;
                dp.startup = mode;
                DiffusionResult r;
                REQUIRE(select_points(densities[img], k, dp, &r).ok());
                INFO("image " << img << " mode " << int(mode) << " count " << k << " got " << r.points.size());
                CHECK(r.exact);
                CHECK(r.points.size() == k);
                CHECK(std::is_sorted(r.points.begin(), r.points.end(), [](LatticePoint a, LatticePoint b) {
                    return a.y != b.y ? a.y < b.y : a.x < b.x;
                }));
            }
}

TEST_CASE("error diffusion: density, mask, pass counts, bad input", "[imaging]") {
    const Grid<double> d = make_grid(4, 1, [](double x, double) { return x; });
    const Grid<double> s = ed_density(d, 1.0);
    CHECK(s(1, 0) == Approx(1.0 / 3));
    CHECK(ed_density(d, 0.5)(1, 0) == Approx(std::sqrt(1.0 / 3)));
    CHECK(ed_density(Grid<double>(3, 3, 0.0), 1.0)(1, 1) == 0.0);
    // One row of density 1/2 with rho 1/2: v = 1/2 fires, error -1/2 carried 7/16 ahead, so the
    // next pixel has 1/2 - 7/32 < 1/2 and stays off; the third fires again.
    const Grid<double> half(3, 1, 0.5);
    std::vector<LatticePoint> pts;
    CHECK(diffuse(half, 0.5, DiffusionParams(), &pts) == 2);
    CHECK(pts == std::vector<LatticePoint>{{0, 0}, {4, 0}});
    // Forbidden points are never chosen.
    Lcg rng{5};
    const Grid<double> dens = make_grid(30, 20, [&](double, double) { return rng.next(); });
    Grid<std::uint8_t> forbid(30, 20, 0);
    for (int y = 0; y < 20; ++y) forbid(10, y) = forbid(11, y) = 1;
    DiffusionParams dp;
    dp.forbidden = &forbid;
    DiffusionResult r;
    REQUIRE(select_points(dens, 120, dp, &r).ok());
    CHECK(r.exact);
    for (LatticePoint q : r.points) CHECK(!forbid(q.x / 2, q.y / 2));
    // Bad input.
    Grid<std::uint8_t> wrong(3, 3, 0);
    dp.forbidden = &wrong;
    CHECK(select_points(dens, 10, dp, &r).code == Code::input);
    Grid<double> neg(3, 3, 1.0);
    neg(1, 1) = -1;
    CHECK(select_points(neg, 2, DiffusionParams(), &r).code == Code::input);
    CHECK(select_points(Grid<double>(), 2, DiffusionParams(), &r).code == Code::input);
    // Zero count is trivially exact; an all-zero density cannot give points.
    REQUIRE(select_points(dens, 0, DiffusionParams(), &r).ok());
    CHECK(r.exact);
    CHECK(r.points.empty());
    REQUIRE(select_points(Grid<double>(5, 5, 0.0), 3, DiffusionParams(), &r).ok());
    CHECK_FALSE(r.exact);
}
