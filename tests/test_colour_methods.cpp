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

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/mmsodd.h"
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

GenerateResult run(const char* method, const Image& im, double density) {
    GenerateOptions o;
    o.density = density;
    o.density_given = true;
    o.flips = 0;  // colour does not flip yet (DECISIONS.md "Colour methods"): gray compared without
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
        const Model a = run(method, gray, 6.0).model, b = run(method, same, 6.0).model;
        REQUIRE(a.vertices == b.vertices);
        REQUIRE(a.faces == b.faces);
        for (std::size_t v = 0; v < a.size(); ++v)
            for (std::size_t c = 0; c < 3; ++c) CHECK(b.values[3 * v + c] == Approx(a.values[v]).margin(1e-9));
    }
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
