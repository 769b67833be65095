// Reconstruction (imgsyn, imgsyn_aa) against hand-computed values and a brute-force evaluator of
// the approximating function that shares no code with algorithms/model/reconstruct.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "kernel/predicates.h"
#include "tests/test_raster_util.h"

using erd::Image;
using erd::LatticePoint;
using erd::Model;
using erd::ModelKind;

namespace {

// The approximating function at fine point (X, Y) (units of 1/8 pixel = doubled * 4), by
// definition (thesis 3.3): inside a face its plane; on an edge the mean of the faces whose
// closure holds the point (one face on the border); at a vertex the mean of the values of its
// wedges. `vertex_mean` gives the last (the caller knows the wedges of its model).
long double brute(const Model& m, const std::vector<long double>& vertex_mean, std::int64_t X, std::int64_t Y) {
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
        if (4 * std::int64_t(m.vertices[v].x) == X && 4 * std::int64_t(m.vertices[v].y) == Y) return vertex_mean[v];
    long double sum = 0;
    int n = 0;
    const LatticePoint p{std::int32_t(X), std::int32_t(Y)};
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        LatticePoint q[3];
        long double z[3];
        for (int k = 0; k < 3; ++k) {
            const LatticePoint v = m.vertices[m.faces[f][std::size_t(k)]];
            q[k] = LatticePoint{4 * v.x, 4 * v.y};
            z[k] = m.kind == ModelKind::erd ? m.corner_values[f][std::size_t(k)] : m.values[m.faces[f][std::size_t(k)]];
        }
        const std::int64_t e0 = erd::orient2d(q[1], q[2], p), e1 = erd::orient2d(q[2], q[0], p), e2 = erd::orient2d(q[0], q[1], p);
        if (e0 < 0 || e1 < 0 || e2 < 0) continue;
        const std::int64_t d = erd::orient2d(q[0], q[1], q[2]);
        sum += (z[0] * e0 + z[1] * e1 + z[2] * e2) / (long double)d;
        ++n;
    }
    REQUIRE(n >= 1);
    REQUIRE(n <= 2);
    return sum / n;
}

int round_clamp(long double v, int maxval) {
    const long double r = std::floor(v + 0.5L);
    return r < 0 ? 0 : (r > maxval ? maxval : int(r));
}

bool near_tie(long double v) { return std::fabs(v - std::floor(v) - 0.5L) < 1e-7L; }

// Compares reconstruct() with the brute-force function, pixel by pixel (near-ties skipped).
void compare(const Model& m, const std::vector<long double>& vmean, bool supersample) {
    Image im;
    const erd::Status st = erd::reconstruct(m, supersample, &im);
    REQUIRE(st.ok());
    REQUIRE(im.width == m.width);
    REQUIRE(im.height == m.height);
    const std::int64_t mx = 8 * std::int64_t(m.width - 1), my = 8 * std::int64_t(m.height - 1);
    int bad = 0, checked = 0;
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x) {
            long double v = 0;
            if (!supersample) {
                v = brute(m, vmean, 8 * x, 8 * y);
            } else {
                for (int l = 0; l < 4; ++l)
                    for (int k = 0; k < 4; ++k) {
                        const std::int64_t X = std::min(mx, std::max<std::int64_t>(0, 8 * x + 2 * k - 3));
                        const std::int64_t Y = std::min(my, std::max<std::int64_t>(0, 8 * y + 2 * l - 3));
                        v += brute(m, vmean, X, Y);
                    }
                v /= 16;
            }
            if (near_tie(v)) continue;
            ++checked;
            if (im.at(x, y) != round_clamp(v, int(m.maxval))) {
                ++bad;
                UNSCOPED_INFO("pixel (" << x << ", " << y << "): got " << im.at(x, y) << " expected " << double(v));
            }
        }
    CHECK(checked > 0);
    CHECK(bad == 0);
}

const char* kThesisErd =
    "# the example of thesis A.4.2 in doubled coordinates: a 50 x 50 image cut by a\n"
    "# constrained diagonal from (0, 49) to (49, 0)\n"
    "255\n4\n0 0 127\n0 98 64\n98 0 64\n98 98 0\n"
    "2\n0 1 2\n1 2 3\n"
    "4\n1 0 73\n1 1 54\n2 0 73\n2 1 54\n";

}  // namespace

TEST_CASE("reconstruct: supersampling by hand on a 2x2 image", "[raster]") {
    // z = 10 + 8x (pixel units). Point evaluation: 10 and 18. Supersampling, pixel 0: sub-samples
    // at x = -0.375, -0.125 (clamped to 0), 0.125, 0.375 -> 10, 10, 11, 13 -> 11; pixel 1: 0.625,
    // 0.875, 1.125 and 1.375 (clamped to 1) -> 15, 17, 18, 18 -> 17.
    Model m;
    m.kind = ModelKind::basic;
    m.width = m.height = 2;
    m.vertices = {{0, 0}, {2, 0}, {0, 2}, {2, 2}};
    m.values = {10, 18, 10, 18};
    m.faces = {{0, 1, 3}, {0, 3, 2}};
    Image im;
    REQUIRE(erd::reconstruct(m, false, &im).ok());
    CHECK(im.samples == std::vector<std::uint16_t>{10, 18, 10, 18});
    REQUIRE(erd::reconstruct(m, true, &im).ok());
    CHECK(im.samples == std::vector<std::uint16_t>{11, 17, 11, 17});
}

TEST_CASE("reconstruct: basic model reproduces vertex values and planes", "[raster]") {
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 12; ++trial) {
        const int W = 3 + int(rng() % 20), H = 3 + int(rng() % 20);
        Model m = erd_test::random_model(rng, W, H, 5 + int(rng() % 40), true);
        m.kind = ModelKind::basic;
        std::vector<long double> vmean;
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            m.values.push_back(double(rng() % 256));
            vmean.push_back(m.values.back());
        }
        Image im;
        REQUIRE(erd::reconstruct(m, false, &im).ok());
        for (std::size_t v = 0; v < m.vertices.size(); ++v)
            CHECK(im.at(m.vertices[v].x / 2, m.vertices[v].y / 2) == m.values[v]);
        compare(m, vmean, false);
        compare(m, vmean, true);
    }
}

TEST_CASE("reconstruct: a linear function is reproduced exactly", "[raster]") {
    std::mt19937 rng(5);
    const int W = 17, H = 11;
    Model m = erd_test::random_model(rng, W, H, 30, true);
    for (const LatticePoint& p : m.vertices) m.values.push_back(3.0 * (p.x / 2) + 5.0 * (p.y / 2) + 7.0);
    Image im;
    REQUIRE(erd::reconstruct(m, false, &im).ok());
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) CHECK(im.at(x, y) == 3 * x + 5 * y + 7);
}

TEST_CASE("reconstruct: the thesis's .erd example (diagonal constraint)", "[raster]") {
    Model m;
    const erd::Status st = erd::read_model(kThesisErd, erd::ModelFileKind::erd, &m);
    REQUIRE(st.ok());
    REQUIRE(m.width == 50);
    REQUIRE(m.height == 50);
    // Above the diagonal x + y < 49: plane 127 -> 73; on it the mean 63.5 (rounds to 64); below
    // it plane 54 -> 0. The corners on the diagonal are vertices with two wedges: 63.5 too.
    Image im;
    REQUIRE(erd::reconstruct(m, false, &im).ok());
    int bad = 0;
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 50; ++x) {
            const int s = x + y;
            const double v = s < 49 ? 127.0 - 54.0 * s / 49.0 : s == 49 ? 63.5 : 54.0 - 54.0 * (s - 49) / 49.0;
            bad += im.at(x, y) != int(std::floor(v + 0.5));
        }
    CHECK(bad == 0);
    CHECK(im.at(0, 49) == 64);
    CHECK(im.at(10, 39) == 64);
    CHECK(im.at(10, 38) == 74);  // 127 - 54*48/49 = 74.10
    CHECK(im.at(10, 40) == 53);  // 54 - 54/49 = 52.90
    // Supersampled: against the brute-force function (wedges: the two faces at vertices 1, 2).
    compare(m, {127.0L, 63.5L, 63.5L, 0.0L}, true);
    // Pixel (0, 0): all sub-samples above the diagonal, clamped x in {0, 0, .125, .375} (mean
    // .125), the same in y: 127 - (54/49) * 0.25 = 126.72.
    REQUIRE(erd::reconstruct(m, true, &im).ok());
    CHECK(im.at(0, 0) == 127);
}

TEST_CASE("reconstruct: random ERD models (every edge a discontinuity)", "[raster]") {
    std::mt19937 rng(31337);
    std::uniform_real_distribution<double> val(-20.0, 275.0);
    for (int trial = 0; trial < 10; ++trial) {
        const int W = 3 + int(rng() % 10), H = 3 + int(rng() % 10);
        Model m = erd_test::random_model(rng, W, H, 5 + int(rng() % 25), false);
        m.kind = ModelKind::erd;
        m.values.assign(m.vertices.size(), 0.0);
        std::vector<long double> vmean(m.vertices.size(), 0.0L);
        std::vector<int> deg(m.vertices.size(), 0);
        for (const auto& f : m.faces) {
            std::array<double, 3> c{val(rng), val(rng), val(rng)};
            m.corner_values.push_back(c);
            for (int k = 0; k < 3; ++k) {
                vmean[f[std::size_t(k)]] += c[std::size_t(k)];
                ++deg[f[std::size_t(k)]];
            }
        }
        for (std::size_t v = 0; v < vmean.size(); ++v) {
            vmean[v] /= deg[v];
            m.values[v] = double(vmean[v]);
        }
        compare(m, vmean, false);
        compare(m, vmean, true);
        // The same model through an .erd file gives the same images.
        std::string text;
        REQUIRE(erd::write_model(m, &text).ok());
        Model r;
        REQUIRE(erd::read_model(text, erd::ModelFileKind::erd, &r).ok());
        for (bool ss : {false, true}) {
            Image a, b;
            REQUIRE(erd::reconstruct(m, ss, &a).ok());
            REQUIRE(erd::reconstruct(r, ss, &b).ok());
            CHECK(a.samples == b.samples);
        }
    }
}

TEST_CASE("reconstruct: refuses what is not a triangulation of the domain", "[raster]") {
    Model m;
    m.kind = ModelKind::basic;
    m.width = m.height = 3;
    m.vertices = {{0, 0}, {4, 0}, {0, 4}, {4, 4}, {2, 2}};
    m.values = {1, 2, 3, 4, 5};
    m.faces = {{0, 1, 4}, {1, 3, 4}, {3, 2, 4}, {2, 0, 4}};
    REQUIRE(erd::check_triangulation(m).ok());
    Image im;
    SECTION("a hole") {
        m.faces.pop_back();
        const auto st = erd::reconstruct(m, false, &im);
        CHECK(st.code == erd::Code::input);
        CHECK(st.message.find("not a triangulation of the image domain") == 0);
    }
    SECTION("an overlap") {
        m.faces.push_back({0, 1, 3});
        const auto st = erd::reconstruct(m, true, &im);
        CHECK(st.message.find("not a triangulation of the image domain") == 0);
    }
    SECTION("a fold (same area, wrong cover)") {
        m.faces = {{0, 1, 3}, {0, 1, 3}};
        CHECK(erd::reconstruct(m, false, &im).message.find("not a triangulation of the image domain") == 0);
    }
    SECTION("a vertex outside") {
        m.vertices[4] = {2, 6};
        CHECK(erd::reconstruct(m, false, &im).message.find("not a triangulation of the image domain") == 0);
    }
    SECTION("inconsistent sizes") {
        m.values.pop_back();
        CHECK(erd::reconstruct(m, false, &im).code == erd::Code::input);
        m.values.push_back(NAN);
        CHECK(erd::reconstruct(m, false, &im).message.find("finite") != std::string::npos);
    }
}

TEST_CASE("reconstruct: wide images are supersampled in several bands of rows", "[raster]") {
    // 256 KiB of pixel sums per band: 6000 pixels a row gives 5 rows a band, so faces of a random
    // triangulation with few points span up to eight bands and are rasterised in pieces.
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> val(0.0, 255.0);
    const int W = 6000, H = 37;
    Model m = erd_test::random_model(rng, W, H, 12, false);
    m.kind = ModelKind::erd;
    std::vector<long double> vmean(m.vertices.size(), 0.0L);
    std::vector<int> deg(m.vertices.size(), 0);
    for (const auto& f : m.faces) {
        const std::array<double, 3> c{val(rng), val(rng), val(rng)};
        m.corner_values.push_back(c);
        for (int k = 0; k < 3; ++k) {
            vmean[f[std::size_t(k)]] += c[std::size_t(k)];
            ++deg[f[std::size_t(k)]];
        }
    }
    for (std::size_t v = 0; v < vmean.size(); ++v) vmean[v] /= deg[v];
    for (long double z : vmean) m.values.push_back(double(z));
    compare(m, vmean, true);
}

TEST_CASE("reconstruct: an output image that holds samples already gives the same image", "[raster]") {
    // reconstruct() fills *out in its own memory when it has the model's size: none of the old
    // samples and not its maxval may survive; another size is made anew.
    std::mt19937 rng(21);
    const int W = 19, H = 13;
    Model m = erd_test::random_model(rng, W, H, 20, false);
    m.maxval = 1000;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) m.values.push_back(double((v * 37) % 1001));
    for (bool ss : {false, true}) {
        INFO("supersampled " << ss);
        Image fresh;
        REQUIRE(erd::reconstruct(m, ss, &fresh).ok());
        Image used(W, H, 65535);
        std::fill(used.samples.begin(), used.samples.end(), std::uint16_t(54321));
        REQUIRE(erd::reconstruct(m, ss, &used).ok());
        CHECK(used.maxval == 1000);
        CHECK(used.samples == fresh.samples);
        Image other(W + 1, H, 255, 3);  // another size: made anew
        REQUIRE(erd::reconstruct(m, ss, &other).ok());
        CHECK(other.width == W);
        CHECK(other.channels == 1);
        CHECK(other.samples == fresh.samples);
    }
}

TEST_CASE("reconstruct: a given adjacency gives the same image; one that does not fit is rebuilt", "[raster]") {
    std::mt19937 rng(8);
    const int W = 23, H = 14;
    Model m = erd_test::random_model(rng, W, H, 25, false);
    m.kind = ModelKind::erd;
    for (std::size_t f = 0; f < m.faces.size(); ++f) m.corner_values.push_back({double(f % 7) * 30, 100.0, 200.0 - double(f)});
    m.values.assign(m.vertices.size(), 0.0);
    std::string text;
    REQUIRE(erd::write_model(m, &text).ok());
    Model r;
    erd::ModelTopology topo;
    REQUIRE(erd::read_model(text, erd::ModelFileKind::erd, &r, &topo).ok());
    CHECK(topo.twin.size() == 3 * r.faces.size());
    for (bool ss : {false, true}) {
        Image a, b, c;
        REQUIRE(erd::reconstruct(r, ss, &a).ok());
        REQUIRE(erd::reconstruct(r, topo, ss, &b).ok());
        REQUIRE(erd::reconstruct(r, erd::ModelTopology{}, ss, &c).ok());
        CHECK(a.samples == b.samples);
        CHECK(a.samples == c.samples);
    }
}

TEST_CASE("reconstruct: faces much taller than the bands", "[raster]") {
    // 64 x 4000 pixels cut into 126 slivers from the top row to the bottom row: every face spans
    // all eight bands of 512 rows. One plane everywhere, so away from the border every pixel is
    // the plane at its centre (the 16 offsets are symmetric); a lost or doubled span would show.
    const int W = 64, H = 4000;
    Model m;
    m.kind = ModelKind::basic;
    m.width = W;
    m.height = H;
    const auto z = [](double x, double y) { return 0.37 * x + 0.0151 * y + 10.3; };
    for (int i = 0; i < W; ++i) {
        m.vertices.push_back({2 * i, 0});
        m.values.push_back(z(i, 0));
        m.vertices.push_back({2 * i, 2 * H - 2});
        m.values.push_back(z(i, H - 1));
    }
    for (std::uint32_t i = 0; i + 1 < std::uint32_t(W); ++i) {
        const std::uint32_t top = 2 * i, bottom = 2 * i + 1;
        m.faces.push_back({top, bottom + 2, bottom});
        m.faces.push_back({top, top + 2, bottom + 2});
    }
    Image im;
    REQUIRE(erd::reconstruct(m, true, &im).ok());
    int bad = 0, checked = 0;
    for (int y = 1; y + 1 < H; ++y)
        for (int x = 1; x + 1 < W; ++x) {
            const double v = z(x, y);
            if (std::fabs(v - std::floor(v) - 0.5) < 1e-6) continue;
            ++checked;
            bad += im.at(x, y) != int(std::floor(v + 0.5));
        }
    CHECK(checked > 200000);
    CHECK(bad == 0);
}
