// Speed-round checks of the error-diffusion and MMSODD implementations (helper "diffusion"):
// the one-sweep MMSODD against the separable filters it replaced, and the 16-lane diffusion
// sweep of the count search against single passes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/mmsodd.h"

using namespace erd;

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

TEST_CASE("MMSODD from one smoothing equals the three separable filters", "[diffusion]") {
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

TEST_CASE("MMSODD of an image's samples equals that of its grid", "[diffusion]") {
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

TEST_CASE("mmsodd_value is the larger magnitude of l1 +- l2", "[diffusion]") {
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

TEST_CASE("the count search's lanes choose what single passes choose", "[diffusion]") {
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

TEST_CASE("ed_density in place equals the formula", "[diffusion]") {
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
