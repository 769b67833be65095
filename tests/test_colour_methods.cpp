// The four methods on colour images (issue 17): one mesh shared by the channels, exact N, every
// channel's ERD model consistent (check_model: verify(), each corner the value of its wedge), the
// basic model's vertex values the samples in every channel and reproduced by reconstruction, and
// a colour image with three equal channels meshed as its gray image.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/methods/colour_scan.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/reconstruct.h"
#include "tests/erd_check.h"

using namespace erd;

namespace {

// Three different channels: a bump, a diagonal step in red and blue only, a vertical step in
// green, mild noise.
Image colour_synthetic(int w, int h, unsigned seed) {
    Image im(w, h, 255, 3);
    std::mt19937 rng(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double bump = 60.0 * std::sin(x / 5.0) * std::cos(y / 7.0);
            const double v[3] = {90.0 + bump + (x + y > w ? 70.0 : 0.0), 120.0 - bump + (x > w / 3 ? 60.0 : 0.0),
                                 60.0 + 0.5 * bump + (x + y > w ? -40.0 : 40.0)};
            for (int c = 0; c < 3; ++c)
                im.at(x, y, c) = std::uint16_t(std::clamp(std::lround(v[c] + double(rng() % 7) - 3.0), 0L, 255L));
        }
    return im;
}

// Channel c of a colour model as a gray model.
Model channel_of(const Model& m, int c) {
    Model g = m;
    const std::size_t C = std::size_t(m.channels);
    g.channels = 1;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) g.values[v] = m.values[v * C + std::size_t(c)];
    g.values.resize(m.vertices.size());
    for (std::size_t f = 0; f < m.corner_values.size() / C; ++f) g.corner_values[f] = m.corner_values[f * C + std::size_t(c)];
    g.corner_values.resize(m.corner_values.size() / C);
    return g;
}

GenerateResult run(const char* method, const Image& im, double density, ColourGradient edges = ColourGradient::luma,
                   int moves = GenerateOptions().moves) {
    GenerateOptions o;
    o.moves = moves;
    if (moves == 0) o.flip_min_share = 0;
    o.density = density;
    o.density_given = true;
    o.colour.edges = edges;
    GenerateResult r;
    const Status st = find_method(method)->run(im, o, &r);
    INFO(st.message);
    REQUIRE(st.ok());
    return r;
}

}  // namespace

TEST_CASE("colour methods: one mesh, exact N, every channel consistent", "[colour][methods]") {
    const Image im = colour_synthetic(48, 40, 7);
    const auto method = GENERATE(as<std::string>(), "ed", "gpi", "erded", "erdgpi");
    const double density = GENERATE(3.0, 8.0);
    INFO(method << " at " << density << "%");
    const GenerateResult r = run(method.c_str(), im, density);
    const Model& m = r.model;
    REQUIRE(m.channels == 3);
    CHECK(m.size() == std::size_t(std::llround(density * 48 * 40 / 100.0)));
    REQUIRE(m.values.size() == 3 * m.size());
    if (m.kind == ModelKind::erd) {
        REQUIRE(m.corner_values.size() == 3 * m.faces.size());
        CHECK(!m.constraints.empty());
        for (int c = 0; c < 3; ++c) test::check_model(channel_of(m, c));
        return;
    }
    REQUIRE(m.corner_values.empty());
    Image rec;
    REQUIRE(reconstruct(m, false, &rec).ok());
    REQUIRE(rec.channels == 3);
    for (int c = 0; c < 3; ++c)
        for (std::size_t v = 0; v < m.size(); ++v) {
            const LatticePoint p = m.vertices[v];
            REQUIRE(m.values[3 * v + std::size_t(c)] == double(im.at(p.x / 2, p.y / 2, c)));
            CHECK(rec.at(p.x / 2, p.y / 2, c) == im.at(p.x / 2, p.y / 2, c));
        }
}

TEST_CASE("colour methods: three equal channels give the gray mesh and values", "[colour][methods]") {
    const Image colour = colour_synthetic(40, 32, 3);
    const Image gray = channel_plane(colour, 1);
    Image same(gray.width, gray.height, 255, 3);
    for (std::size_t i = 0; i < gray.samples.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) same.samples[3 * i + c] = gray.samples[i];
    for (const char* method : {"ed", "gpi", "erded", "erdgpi"}) {
        INFO(method);
        // The colour ERD methods flip but neither move vertices nor skip low-error quadrilaterals
        // (issue 16's moves and flip skip are gray only): the gray mesh to match has neither.
        const Model a = run(method, gray, 6.0, ColourGradient::luma, 0).model, b = run(method, same, 6.0).model;
        if (std::string(method) == "gpi") {
            // Colour GPI's greedy scan rounds each channel's plane in 16.16 fixed point
            // (colour_scan.h), gray GPI's exactly: they may round a pixel whose value is a half
            // differently, and so pick another candidate now and then. The same size and quality.
            REQUIRE(a.size() == b.size());
            Image ra, rb;
            REQUIRE(reconstruct(a, false, &ra).ok());
            REQUIRE(reconstruct(b, false, &rb).ok());
            double sa = 0, sb = 0;
            for (std::size_t i = 0; i < gray.samples.size(); ++i) {
                const double ea = double(ra.samples[i]) - gray.samples[i], eb = double(rb.samples[3 * i + 1]) - gray.samples[i];
                sa += ea * ea;
                sb += eb * eb;
            }
            CHECK(std::fabs(10.0 * std::log10(sb / sa)) < 0.1);  // dB
            continue;
        }
        REQUIRE(a.vertices == b.vertices);
        REQUIRE(a.faces == b.faces);
        for (std::size_t v = 0; v < a.size(); ++v)
            for (std::size_t c = 0; c < 3; ++c) CHECK(b.values[3 * v + c] == Approx(a.values[v]).margin(1e-9));
    }
}

TEST_CASE("colour methods: edges on the colour gradients", "[colour][methods]") {
    const Image im = colour_synthetic(48, 40, 5);
    for (const ColourGradient g : {ColourGradient::dizenzo, ColourGradient::max})
        for (const char* method : {"erded", "erdgpi"}) {
            INFO(method << (g == ColourGradient::max ? " max" : " dizenzo"));
            const Model m = run(method, im, 5.0, g).model;
            CHECK(m.size() == std::size_t(std::llround(5.0 * 48 * 40 / 100.0)));
            CHECK(!m.constraints.empty());
            for (int c = 0; c < 3; ++c) test::check_model(channel_of(m, c));
        }
    // Three equal channels: the largest channel's gradient is the gray image's, so are the edges.
    const Image gray = channel_plane(im, 0);
    Image same(gray.width, gray.height, 255, 3);
    for (std::size_t i = 0; i < gray.samples.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) same.samples[3 * i + c] = gray.samples[i];
    CannyParams p;
    Grid<std::uint8_t> a, b;
    EdgeDetector one(gray), three(same, ColourGradient::max);
    REQUIRE(one.detect(p, &a).ok());
    REQUIRE(three.detect(p, &b).ok());
    CHECK(std::count(a.data.begin(), a.data.end(), 1) > 0);
    CHECK(a.data == b.data);
}

TEST_CASE("colour methods: luma plane and combined MMSODD", "[colour][imaging]") {
    Image im(2, 1, 255, 3);
    const std::uint16_t px[6] = {255, 0, 0, 10, 200, 30};
    std::copy(px, px + 6, im.samples.begin());
    const Image y = luma_of(im);
    REQUIRE(y.channels == 1);
    CHECK(y.samples[0] == 76);   // 0.299 * 255 = 76.245
    CHECK(y.samples[1] == 124);  // 2.99 + 117.4 + 3.42 = 123.81
    const Image c = colour_synthetic(20, 16, 1);
    const Grid<double> sum = colour_mmsodd(c, 3, ColourDensity::sum), mx = colour_mmsodd(c, 3, ColourDensity::max);
    const Grid<double> r = colour_mmsodd(channel_plane(c, 0), 3, ColourDensity::sum);
    CHECK(mmsodd_channel(c, 0, 3).data == r.data);
    CHECK(mmsodd_channel(c, 2, 5).data == mmsodd(channel_plane(c, 2), 5).data);
    for (std::size_t i = 0; i < sum.size(); ++i) {
        CHECK(mx.data[i] >= r.data[i]);
        CHECK(sum.data[i] >= mx.data[i]);
    }
}

TEST_CASE("colour methods: the fixed-point colour scan against a plain loop", "[colour][greedy]") {
    // scan_span (algorithms/methods/colour_scan.h) on random spans of random 8-bit samples: the
    // sum of the squared channel errors and the candidate (first pixel of the largest channel
    // error, banned pixels skipped) as a scalar loop over the same 16.16 values computes them.
    // The interleaved samples end exactly at the last pixel (spans reach it: the end guard, which
    // the sanitizer builds check for reads past it).
    std::mt19937 rng(11);
    const int n = 41;
    std::vector<std::uint16_t> rgb(3 * n);
    for (auto& v : rgb) v = std::uint16_t(rng() % 256);
    const auto sample = [&](int c, std::int32_t x) { return std::int32_t(rgb[3 * std::size_t(x) + std::size_t(c)]); };
    std::vector<std::uint8_t> banned(n);
    for (int trial = 0; trial < 400; ++trial) {
        for (auto& b : banned) b = rng() % 5 == 0;
        const std::int32_t x0 = std::int32_t(rng() % 20), x1 = x0 + std::int32_t(rng() % 21);
        const bool clamp = trial % 2 == 1;
        std::int32_t V0[3], dV[3];
        for (int c = 0; c < 3; ++c) {
            // Unclamped spans stay in [0, 256) * 2^16; clamped ones may leave it.
            const std::int32_t lo = clamp ? -(40 << 16) : 0, hi = clamp ? (300 << 16) : (256 << 16) - 1;
            const std::int32_t a = lo + std::int32_t(rng() % std::uint32_t(hi - lo)), b = lo + std::int32_t(rng() % std::uint32_t(hi - lo));
            V0[c] = a;
            dV[c] = (b - a) / std::max(1, x1 - x0);
        }
        colour_scan::Steps steps;
        steps.set(dV);
        const std::uint16_t* s = rgb.data() + 3 * x0;
        const std::uint16_t* end = rgb.data() + rgb.size();
        std::uint64_t sum = 0;
        std::int32_t best = trial % 3 == 0 ? 400 : -1, bx = -7;
        const std::int32_t best0 = best;
        const bool moved = clamp ? colour_scan::scan_span<true>(s, end, banned.data(), x0, x1, V0, steps, 255, &sum, &best, &bx)
                                 : colour_scan::scan_span<false>(s, end, banned.data(), x0, x1, V0, steps, 255, &sum, &best, &bx);
        std::uint64_t rsum = 0;
        std::int32_t rbest = best0, rbx = -7;
        for (std::int32_t x = x0; x <= x1; ++x) {
            std::int32_t m = 0;
            for (int c = 0; c < 3; ++c) {
                const std::int64_t v = std::int64_t(V0[c]) + std::int64_t(x - x0) * dV[c];
                const std::int64_t r = std::clamp<std::int64_t>(v >> 16, 0, 255);
                const std::int32_t e = sample(c, x) - std::int32_t(r);
                rsum += std::uint64_t(e * e);
                m = std::max(m, e * e);
            }
            if (m > rbest && !banned[std::size_t(x)]) {
                rbest = m;
                rbx = x;
            }
        }
        INFO("trial " << trial);
        CHECK(sum == rsum);
        CHECK(best == rbest);
        CHECK(bx == rbx);
        CHECK(moved == (rbx != -7));
    }
}
