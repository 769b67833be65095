// Tiles (issue 48): the grid, the border profiles' vertices, the budget split, and a method run
// with its sides fixed (GenerateOptions::lock_border): no vertex on a side but the given ones.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/synth.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/tiles.h"
#include "imageio/png.h"
#include "imageio/raster_window.h"

using namespace erd;

TEST_CASE("tile grid: lines shared, the last at W - 1", "[tiles]") {
    const TileGrid g = make_tile_grid(1025, 600, 256);
    CHECK(g.nx == 4);
    CHECK(g.ny == 3);
    CHECK(g.column(0) == 0);
    CHECK(g.column(4) == 1024);
    CHECK(g.row(2) == 512);
    CHECK(g.row(3) == 599);
    const TileGrid one = make_tile_grid(100, 100, 4096);
    CHECK(one.nx == 1);
    CHECK(one.column(1) == 99);
}

TEST_CASE("border profile: the 1-D greedy under the error bound and the count", "[tiles]") {
    // A ramp with a step: the bound puts vertices at both sides of the step and nowhere on the ramps.
    std::vector<double> z;
    for (int i = 0; i <= 100; ++i) z.push_back(i < 50 ? i : i + 1000);
    ProfileRule r;
    r.max_error = 0.5;
    const std::vector<int> v = simplify_profile(z, r);
    CHECK(v.front() == 0);
    CHECK(v.back() == 100);
    CHECK(std::find(v.begin(), v.end(), 49) != v.end());
    CHECK(std::find(v.begin(), v.end(), 50) != v.end());
    for (std::size_t k = 1; k < v.size(); ++k)
        for (int i = v[k - 1] + 1; i < v[k]; ++i) {
            const double t = double(i - v[k - 1]) / double(v[k] - v[k - 1]);
            CHECK(std::fabs(z[std::size_t(v[k - 1])] * (1 - t) + z[std::size_t(v[k])] * t - z[std::size_t(i)]) <= 0.5);
        }
    ProfileRule capped;
    capped.max_interior = 1;
    CHECK(simplify_profile(z, capped).size() == 3);
    // A line needs no interior vertex; two samples are the ends.
    CHECK(simplify_profile({0, 1, 2, 3, 4}, ProfileRule()).size() == 2);
    CHECK(simplify_profile({7, 9}, ProfileRule()) == std::vector<int>{0, 1});
}

TEST_CASE("budget split: proportional, exact sum, deterministic ties", "[tiles]") {
    const std::vector<std::int64_t> a = split_budget(10, {1, 1, 2});
    CHECK(a == std::vector<std::int64_t>{3, 2, 5});  // 2.5, 2.5, 5: the first remainder wins
    CHECK(split_budget(7, {0, 0}) == std::vector<std::int64_t>{4, 3});
    std::int64_t sum = 0;
    for (std::int64_t x : split_budget(1000003, {0.1, 3.7, 2.2, 9.9, 0})) sum += x;
    CHECK(sum == 1000003);
}

TEST_CASE("a method with its sides fixed adds no vertex on a side", "[tiles]") {
    SynthParams sp;
    sp.width = 97;
    sp.height = 65;
    Image im;
    REQUIRE(synth(sp, &im));
    const std::int32_t mx = 2 * 96, my = 2 * 64;
    for (const char* name : {"gpi", "erdgpi"}) {
        GenerateOptions o;
        o.density = 4;
        o.density_given = true;
        o.lock_border = true;
        o.border_points = {{0, 20}, {0, 60}, {mx, 100}, {40, 0}, {120, my}};
        GenerateResult res;
        REQUIRE(find_method(name)->run(im, o, &res));
        pin_side_values(im, &res.model);
        std::size_t on_side = 0;
        for (std::size_t v = 0; v < res.model.vertices.size(); ++v) {
            const LatticePoint p = res.model.vertices[v];
            if (p.x == 0 || p.y == 0 || p.x == mx || p.y == my) {
                ++on_side;
                CHECK(res.model.values[v] == double(im.samples[std::size_t(p.y / 2) * 97 + std::size_t(p.x / 2)]));
            }
        }
        INFO(name);
        CHECK(on_side == 4 + o.border_points.size());
        CHECK(res.model.vertices.size() == res.requested);
        // Off, the same run puts vertices on the sides.
        GenerateOptions free = o;
        free.lock_border = false;
        GenerateResult r2;
        REQUIRE(find_method(name)->run(im, free, &r2));
        std::size_t free_side = 0;
        for (LatticePoint p : r2.model.vertices) free_side += (p.x == 0 || p.y == 0 || p.x == mx || p.y == my);
        CHECK(free_side > 4);
    }
}

TEST_CASE("PNG read by rows: any window equals the whole decode (gray 8 and 16 bits, RGB)", "[tiles][io]") {
    for (int kind = 0; kind < 3; ++kind) {
        SynthParams sp;
        sp.width = 203;
        sp.height = 117;
        sp.bits = kind == 1 ? 16 : 8;
        Image im;
        REQUIRE(synth(sp, &im));
        if (kind == 2) {  // RGB: three different planes
            Image rgb(im.width, im.height, im.maxval, 3);
            for (std::size_t i = 0; i < im.samples.size(); ++i) {
                rgb.samples[3 * i] = im.samples[i];
                rgb.samples[3 * i + 1] = std::uint16_t(im.maxval - im.samples[i]);
                rgb.samples[3 * i + 2] = std::uint16_t((i * 7) % (im.maxval + 1));
            }
            im = rgb;
        }
        std::string bytes;
        REQUIRE(imageio::encode_png(im, &bytes));
        const std::string path = "build/test_png_rows.png";
        std::FILE* f = std::fopen(path.c_str(), "wb");
        REQUIRE(f);
        REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
        std::fclose(f);
        imageio::RasterWindow rw;
        REQUIRE(rw.open(path));
        CHECK(rw.width() == im.width);
        CHECK(rw.channels() == im.channels);
        // Forward, then back up (a restart), then the whole image.
        const int windows[][4] = {{0, 0, 10, 5}, {50, 40, 203, 90}, {3, 10, 100, 30}, {0, 116, 203, 117}, {0, 0, 203, 117}};
        for (const auto& w : windows) {
            Image win;
            REQUIRE(rw.read(w[0], w[1], w[2], w[3], &win));
            REQUIRE(win.width == w[2] - w[0]);
            bool same = true;
            const std::size_t C = std::size_t(im.channels);
            for (int y = w[1]; y < w[3]; ++y)
                for (int x = w[0]; x < w[2]; ++x)
                    for (std::size_t c = 0; c < C; ++c)
                        same = same && win.samples[(std::size_t(y - w[1]) * std::size_t(win.width) + std::size_t(x - w[0])) * C + c] ==
                                           im.samples[(std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * C + c];
            CHECK(same);
        }
        std::remove(path.c_str());
    }
}

TEST_CASE("border crossings: the strong step that is the largest of its neighbours and goes on across", "[tiles]") {
    const auto same = [](const std::vector<double>& z, double strong) { return profile_crossings(z, z, z, strong); };
    // A step of 100 between samples 5 and 6, a ramp of 30 a sample (no crossing), a step too weak.
    std::vector<double> z = {0, 0, 0, 0, 0, 0, 100, 100, 130, 160, 190, 190, 195, 195, 195};
    CHECK(same(z, 50) == std::vector<int>{5});
    CHECK(same(z, 20) == std::vector<int>{5});  // the ramp's equal differences: none the largest
    CHECK(same(z, 101).empty());
    // Not at the ends: a step between the first two samples or the last two is a corner's.
    CHECK(same({0, 100, 100, 100, 100}, 50).empty());
    CHECK(same({0, 0, 0, 0, 100}, 50).empty());
    // A blurred step: its middle difference.
    CHECK(same({0, 0, 0, 10, 60, 90, 100, 100, 100}, 40) == std::vector<int>{3});
    // Across the border: the parallel profiles step 3 samples earlier and 2 later (an oblique
    // edge) by at least half; not when one is flat, steps the other way, 5 samples off or too little.
    const std::vector<double> early = {0, 0, 0, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60};
    const std::vector<double> late = {0, 0, 0, 0, 0, 0, 0, 0, 100, 100, 100, 100, 100, 100, 100};
    CHECK(profile_crossings(z, early, late, 50) == std::vector<int>{5});
    CHECK(profile_crossings(z, early, std::vector<double>(z.size(), 7.0), 50).empty());
    std::vector<double> down(late);
    for (double& v : down) v = -v;
    CHECK(profile_crossings(z, early, down, 50).empty());
    const std::vector<double> far = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 100, 100, 100, 100};
    CHECK(profile_crossings(z, early, far, 50).empty());
    CHECK(profile_crossings(z, {0, 0, 0, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20}, late, 50).empty());  // 20 < 50 / 2
    CHECK(profile_crossings(z, {0, 0, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60, 60}, late, 50) == std::vector<int>{5});  // 4 off
}

TEST_CASE("border crossings: a stub into the tile for each, the nearest polyline end joined to it", "[tiles]") {
    // A 21 x 11 tile (doubled 40 x 20): crossings on the left side at y = 7.5 and the bottom at x = 10.5.
    const std::vector<LatticePoint> crossings = {{0, 15}, {21, 20}};
    std::vector<Polyline> lines = {{{4, 14}, {20, 10}}, {{30, 2}, {24, 8}}};  // ends 4 units from the first
    std::size_t joined = 0;
    std::vector<Polyline> out = join_crossings(lines, crossings, 21, 11, &joined);
    CHECK(joined == 1);
    REQUIRE(out.size() == 4);
    CHECK(out[0] == Polyline{{0, 15}, {2, 15}});  // the stubs: one pixel straight in
    CHECK(out[1] == Polyline{{21, 20}, {21, 18}});
    CHECK(out[2] == Polyline{{2, 15}, {4, 14}, {20, 10}});
    CHECK(out[3] == lines[1]);
}

TEST_CASE("a tile with a crossing: the step kept on both sides of the crossing vertex", "[tiles]") {
    // A hard step along x = 20.5 + y / 4 on a 41 x 33 tile; its bottom side crosses it at x = 28.5.
    Image im(41, 33, 255, 1);
    for (int y = 0; y < 33; ++y)
        for (int x = 0; x < 41; ++x) im.at(x, y) = std::uint16_t(double(x) > 20.5 + y / 4.0 ? 200 : 40);
    const std::int32_t my = 2 * 32;
    GenerateOptions o;
    o.density = 5;
    o.density_given = true;
    o.lock_border = true;
    o.border_points = {{56, my}, {58, my}};
    o.border_crossings = {{57, my}};
    GenerateResult res;
    REQUIRE(find_method("erdgpi")->run(im, o, &res));
    pin_side_values(im, &res.model);
    const Model& m = res.model;
    std::uint32_t v = 0;
    while (v < m.vertices.size() && !(m.vertices[v].x == 57 && m.vertices[v].y == my)) ++v;
    REQUIRE(v < m.vertices.size());
    bool constrained = false;
    for (const auto& e : m.constraints) constrained |= e[0] == v || e[1] == v;
    CHECK(constrained);
    // The faces along the side: the one towards x = 28 takes 40, towards x = 29 takes 200.
    int towards_a = 0, towards_b = 0;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            if (m.faces[f][std::size_t(k)] != v) continue;
            for (int j = 1; j < 3; ++j) {
                const LatticePoint q = m.vertices[m.faces[f][std::size_t((k + j) % 3)]];
                if (q.y != my) continue;
                const double z = m.corner_values[f][std::size_t(k)];
                if (q.x < 57) {
                    ++towards_a;
                    CHECK(z == 40.0);
                } else {
                    ++towards_b;
                    CHECK(z == 200.0);
                }
            }
        }
    CHECK(towards_a == 1);
    CHECK(towards_b == 1);
}
