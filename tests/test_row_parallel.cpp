// Threads of the image stages (kernel/row_parallel.h): the parts cover their range, and every
// stage that uses them gives the same bytes at 1, 2 and 3 threads (MMSODD, the ED density, the
// PSNR, both reconstructions, the four methods' models in gray and colour, `erd generate`,
// `erd reconstruct` and `erd psnr` -j), on odd sizes down to 1 x N and N x 1; two API calls on two
// threads equal the same calls made one after the other. `make tsan` builds this file alone with
// ThreadSanitizer (build-tsan/erd_tsan_tests, a stage of make test).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "api/erd.h"
#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/imaging/synth.h"
#include "algorithms/imaging/synth_dem.h"
#include "algorithms/methods/flips.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/methods/greedy_models.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "kernel/cdt.h"
#include "kernel/row_parallel.h"
#include "tests/erd_run.h"
#include "tests/synth_util.h"

using namespace erd;
using erd_test::synth_image;

namespace {

// The thread counts compared with one thread. Under the sanitizers (ERD_SANITIZED, ~20x slower)
// 3 alone: its parts run the same code on both sides of every cut (the unequal split included)
// that 2's do, and the unsanitized run compares both.
std::vector<int> other_threads() {
    if (std::getenv("ERD_SANITIZED")) return {3};
    return {2, 3};
}

std::vector<int> with_one_thread() {
    std::vector<int> t = other_threads();
    t.insert(t.begin(), 1);
    return t;
}

// A colour image from three synth images of different seeds (different noise in each channel).
Image synth_colour(int w, int h) {
    Image out(w, h, 255, 3);
    for (int c = 0; c < 3; ++c) {
        const Image g = synth_image(w, h, 8, std::uint64_t(c + 3));
        for (std::size_t i = 0; i < g.samples.size(); ++i) out.samples[i * 3 + std::size_t(c)] = g.samples[i];
    }
    return out;
}

bool same_bits(const Grid<double>& a, const Grid<double>& b) {
    return a.width == b.width && a.height == b.height && a.data.size() == b.data.size() &&
           (a.data.empty() || std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(double)) == 0);
}

bool same_image(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels && a.maxval == b.maxval &&
           a.samples == b.samples;
}

std::string model_text(const Model& m) {
    std::string s;
    REQUIRE(write_model(m, &s).ok());
    return s;
}

// Small sizes (one part: the stages give small inputs a single thread) and sizes of several
// parts at 2 and 3 threads (MMSODD parts hold 2^15 pixels at least, the density's 2^18).
const int kSizes[][2] = {{1, 1}, {1, 37}, {41, 1}, {2, 2}, {17, 33}, {1, 200000}, {3, 40000}, {700, 160}, {257, 401}};

// Pseudo-random samples (a fixed LCG): images of more than 2^19 samples for the PSNR's parts.
Image noise_image(int w, int h, int channels, std::uint32_t seed) {
    Image im(w, h, 65535, channels);
    std::uint32_t x = seed;
    for (auto& v : im.samples) {
        x = x * 1664525u + 1013904223u;
        v = std::uint16_t(x >> 16);
    }
    return im;
}

}  // namespace

TEST_CASE("row parts: contiguous, cover the range, at most the threads asked for, min size kept", "[threads]") {
    for (std::size_t n : {0u, 1u, 2u, 7u, 64u, 1000u})
        for (int threads : {1, 2, 3, 8})
            for (std::size_t min_items : {1u, 16u}) {
                const RowParts parts(5, 5 + n, threads, min_items);
                INFO(n << " items, " << threads << " threads, min " << min_items);
                REQUIRE(parts.count >= 1);
                CHECK(parts.count <= std::size_t(threads));
                if (parts.count > 1) CHECK(n / parts.count >= min_items);
                CHECK(parts.part_begin(0) == 5);
                CHECK(parts.part_end(parts.count - 1) == 5 + n);
                for (std::size_t k = 0; k < parts.count; ++k) {
                    CHECK(parts.part_begin(k) <= parts.part_end(k));
                    if (k + 1 < parts.count) CHECK(parts.part_end(k) == parts.part_begin(k + 1));
                }
                std::vector<int> seen(n, 0);
                run_parts(parts, [&](std::size_t, std::size_t b, std::size_t e) {
                    for (std::size_t i = b; i < e; ++i) ++seen[i - 5];
                });
                for (int s : seen) CHECK(s == 1);
            }
    CHECK(resolve_threads(3) == 3);
    CHECK(resolve_threads(0) >= 1);
}

TEST_CASE("MMSODD and the ED density: the same bits at 1, 2 and 3 threads, odd sizes", "[threads][mmsodd]") {
    for (const auto& wh : kSizes) {
        const Image im = noise_image(wh[0], wh[1], 1, 1);
        const Image deep = noise_image(wh[0], wh[1], 1, 5);
        const Grid<double> plane = to_grid(deep);
        for (int order : {1, 3, 5, 7}) {
            INFO(wh[0] << " x " << wh[1] << ", order " << order);
            const Grid<double> one = mmsodd(im, order, 1);
            const Grid<double> plane_one = mmsodd(plane, order, Border::zero, 1);
            // The banded sweep is the unbanded one: also against the definition (integer samples).
            CHECK(same_bits(one, mmsodd_separable(to_grid(im), order, Border::zero)));
            for (int threads : other_threads()) {
                INFO(threads << " threads");
                CHECK(same_bits(one, mmsodd(im, order, threads)));
                CHECK(same_bits(plane_one, mmsodd(plane, order, Border::zero, threads)));
            }
        }
    }
    for (const auto& wh : {std::make_pair(1, 800000), std::make_pair(1000, 801), std::make_pair(5, 3)}) {
        Grid<double> d(wh.first, wh.second);
        std::uint32_t x = 9;
        for (double& v : d.data) {
            x = x * 1664525u + 1013904223u;
            v = double(x >> 8) / 3.0;
        }
        d.data[d.data.size() - 1] = 1e9;  // the maximum in the last part
        for (int threads : other_threads())
            for (double gamma : {0.5, 1.0, 0.7}) {
                INFO(wh.first << " x " << wh.second << ", " << threads << " threads, gamma " << gamma);
                CHECK(same_bits(ed_density(d, gamma, 1), ed_density(d, gamma, threads)));
            }
    }
    const Image colour = synth_colour(300, 260);
    for (ColourDensity how : {ColourDensity::sum, ColourDensity::max, ColourDensity::luma})
        for (int threads : other_threads()) CHECK(same_bits(colour_mmsodd(colour, 5, how, 1), colour_mmsodd(colour, 5, how, threads)));
}

TEST_CASE("error diffusion's count search: the same points at 1, 2 and 3 threads", "[threads][diffusion]") {
    // Above 2^16 pixels the 16-lane sweeps run as two halves side by side.
    for (const auto& wh : {std::make_pair(300, 260), std::make_pair(1, 70000), std::make_pair(40, 30)}) {
        const Image im = noise_image(wh.first, wh.second, 1, 4);
        const Grid<double> density = ed_density(mmsodd(im, 3), 1.0);
        for (Startup startup : {Startup::none, Startup::mirror, Startup::force})
            for (std::size_t k : {std::size_t(7), density.size() / 50}) {
                DiffusionParams p;
                p.startup = startup;
                DiffusionResult one;
                REQUIRE(select_points(density, k, p, &one).ok());
                for (int threads : other_threads()) {
                    INFO(wh.first << " x " << wh.second << ", K " << k << ", " << threads << " threads");
                    p.threads = threads;
                    DiffusionResult other;
                    REQUIRE(select_points(density, k, p, &other).ok());
                    CHECK(other.points == one.points);
                    CHECK(other.rho == one.rho);
                    CHECK(other.passes == one.passes);
                    CHECK(other.exact == one.exact);
                }
            }
    }
}

TEST_CASE("PSNR, MSE and channel MSE: the same at 1, 2 and 3 threads", "[threads][metrics]") {
    for (const auto& wh : {std::make_pair(1, 1), std::make_pair(3, 1), std::make_pair(1, 1600000), std::make_pair(1300, 1300)}) {
        const Image a = noise_image(wh.first, wh.second, 1, 1), b = noise_image(wh.first, wh.second, 1, 2);
        double e1 = 0, p1 = 0;
        REQUIRE(mse(a, b, &e1, 1).ok());
        REQUIRE(psnr(a, b, &p1, 1).ok());
        for (int threads : other_threads()) {
            double e = -1, p = -1;
            REQUIRE(mse(a, b, &e, threads).ok());
            REQUIRE(psnr(a, b, &p, threads).ok());
            CHECK(std::memcmp(&e, &e1, sizeof e) == 0);
            CHECK(std::memcmp(&p, &p1, sizeof p) == 0);
        }
    }
    const Image a = noise_image(800, 700, 3, 1), c = noise_image(800, 700, 3, 2);
    double one[3], three[3], e1 = 0, e3 = 0;
    REQUIRE(channel_mse(a, c, one, 1).ok());
    REQUIRE(channel_mse(a, c, three, 3).ok());
    REQUIRE(mse(a, c, &e1, 1).ok());
    REQUIRE(mse(a, c, &e3, 3).ok());
    CHECK(std::memcmp(one, three, sizeof one) == 0);
    CHECK(e1 == e3);
    CHECK(e1 > 0);
    // Sizes that differ still fail, threads or not.
    double e = 0;
    CHECK_FALSE(mse(synth_image(5, 4), synth_image(4, 5), &e, 3).ok());
}

// Edge detection's gradient pass in row bands (canny_pass.cpp stream_bands): the same edges and
// thresholds at 1, 2 and 3 threads. 700 x 400 has a 1399 x 799 half-pixel grid, cut into 2 and 3
// bands (bands hold 2^18 points at least); the striped image puts all its texture in the rows
// the pass's sample reads (pixel rows 8 + 16 k), so the sampled guess is above the final bound
// and the pass runs again without it; the flat image has no gradient at all.
TEST_CASE("edge detection: the same edges at 1, 2 and 3 threads", "[threads][canny]") {
    Image striped = noise_image(700, 400, 1, 7);
    for (int y = 0; y < striped.height; ++y)
        if (y % 16 != 8)
            for (int x = 0; x < striped.width; ++x) striped.samples[std::size_t(y) * 700 + std::size_t(x)] = 30000;
    const Image images[] = {synth_image(700, 400), striped, Image(700, 400, 255, 1), synth_colour(700, 400)};
    for (const Image& im : images) {
        // Under the sanitizers the thesis's beta alone (each detection there takes a second).
        const std::vector<double> betas = std::getenv("ERD_SANITIZED") ? std::vector<double>{0.055}
                                                                        : std::vector<double>{0.01, 0.055, 0.3};
        for (double beta : betas) {
            INFO(im.channels << " channels, beta " << beta);
            CannyParams p;
            p.beta = beta;
            Grid<std::uint8_t> first;
            CannyStats first_stats;
            for (int threads : with_one_thread()) {
                p.threads = threads;
                EdgeDetector detector(im);
                Grid<std::uint8_t> edges;
                CannyStats stats;
                REQUIRE(detector.detect(p, &edges, &stats).ok());
                if (threads == 1) {
                    first = edges;
                    first_stats = stats;
                    continue;
                }
                INFO(threads << " threads");
                CHECK(edges.data == first.data);
                CHECK(stats.tau_high == first_stats.tau_high);
                CHECK(stats.edge_points == first_stats.edge_points);
            }
            if (im.channels == 1 && im.samples[0] != 0) CHECK(first_stats.edge_points > 0);
        }
    }
}

TEST_CASE("methods and reconstruction: the same model and images at 1, 2 and 3 threads", "[threads][methods]") {
    struct Case {
        int w, h, channels;
    };
    // 2 x N and N x 2 are the smallest images a method meshes.
    // 560 x 480 and 300 x 260 give the MMSODD, the density and both reconstructions several parts.
    const Case cases[] = {{2, 2, 1}, {2, 23, 1}, {29, 2, 1}, {67, 45, 1}, {560, 480, 1}, {300, 260, 3}};
    for (const Case& c : cases) {
        const Image im = c.channels == 3 ? synth_colour(c.w, c.h) : synth_image(c.w, c.h);
        for (const char* method : {"ed", "gpi", "erded", "erdgpi"}) {
            INFO(method << " on " << c.w << " x " << c.h << " x " << c.channels);
            std::string first;
            Model first_model;
            for (int threads : with_one_thread()) {
                GenerateOptions o;
                o.points = std::max(std::int64_t(4), std::int64_t(c.w) * c.h / 40);
                o.threads = threads;
                GenerateResult r;
                const Status st = find_method(method)->run(im, o, &r);
                INFO(threads << " threads: " << st.message);
                REQUIRE(st.ok());
                const std::string text = model_text(r.model);
                if (threads == 1) {
                    first = text;
                    first_model = r.model;
                } else {
                    CHECK(text == first);
                }
            }
            for (bool supersample : {false, true}) {
                Image one, other;
                REQUIRE(reconstruct(first_model, supersample, &one, {}, 1).ok());
                for (int threads : other_threads()) {
                    INFO((supersample ? "4x4, " : "point, ") << threads << " threads");
                    REQUIRE(reconstruct(first_model, supersample, &other, {}, threads).ok());
                    CHECK(same_image(one, other));
                }
            }
        }
    }
}

// The greedy loop's re-scans on a second thread (kernel/step_helper.h): images of at least
// kTwoThreadPixels (gray, colour, real), no supersampling. The helper must take part (its
// step count), and the triangulation, sums and candidates must be the same bits as on one thread.
TEST_CASE("greedy re-scans on a second thread: the same mesh, error and models at 1, 2 and 3 threads", "[threads][greedy]") {
    const erd::Image im = synth_image(1024, 1024);
    const Image colour = synth_colour(1024, 1024);
    const Image real_colour = erd::real_copy(colour);
    REQUIRE(real_colour.real());
    REQUIRE(std::size_t(im.width) * std::size_t(im.height) >= erd::kTwoThreadPixels);
    for (const erd::Image* image : {&im, &colour, &real_colour}) {
        std::vector<std::array<std::int32_t, 6>> first;
        double first_sse = 0;
        for (int threads : with_one_thread()) {
            INFO(image->channels << " channels" << (image->real() ? ", real" : "") << ", " << threads << " threads");
            erd::BasicGreedyModel model(*image);
            erd::GreedyOptions go;
            go.target_vertices = 1500;
            go.threads = threads;
            erd::Cdt cdt;
            REQUIRE(cdt.reset(2 * (image->width - 1), 2 * (image->height - 1)).ok());
            erd::GreedyStats gs;
            REQUIRE(erd::greedy_refine(cdt, *image, model, go, &gs).ok());
            REQUIRE(cdt.vertex_count() == 1500);
            if (threads == 1) {
                CHECK(gs.two_thread_steps == 0);
                first = erd::canonical_faces(cdt);
                first_sse = gs.total_squared_error;
            } else {
#ifndef ERD_NO_THREADS
                CHECK(gs.two_thread_steps > 0);
#endif
                CHECK(erd::canonical_faces(cdt) == first);
                CHECK(gs.total_squared_error == first_sse);
            }
        }
    }
    // The ERD model's planes (8-bit) and a real DEM with nodata (its own scan, and the owner map
    // ERDGPI keeps there), through the methods: the same model at every thread count.
    erd::DemParams dp;
    dp.width = dp.height = 1024;
    std::vector<double> heights(std::size_t(dp.width) * std::size_t(dp.height));
    for (int y = 0; y < dp.height; ++y) erd::dem_row(dp, y, &heights[std::size_t(y) * std::size_t(dp.width)]);
    erd::Image dem;
    REQUIRE(erd::make_real_image(dp.width, dp.height, 1, std::move(heights), erd::RasterMeta(), &dem).ok());
    REQUIRE(dem.has_holes());
    // Colour too (its own scan, each thread its own span scratch): GPI's planes and the ERD model's.
    struct Run {
        const char* what;
        const erd::Image* image;
        const char* method;
    };
    const Run runs[] = {{"8-bit", &im, "erdgpi"}, {"DEM", &dem, "erdgpi"}, {"colour", &colour, "gpi"}, {"colour", &colour, "erdgpi"}};
    for (const Run& run : runs) {
        std::string first_text;
        for (int threads : with_one_thread()) {
            INFO(run.what << ", " << run.method << ", " << threads << " threads");
            GenerateOptions o;
            o.points = 1500;
            o.threads = threads;
            GenerateResult r;
            REQUIRE(find_method(run.method)->run(*run.image, o, &r).ok());
            if (threads == 1) first_text = model_text(r.model);
            else CHECK(model_text(r.model) == first_text);
        }
    }
}

// The flips' first round measured ahead on a second thread (flips.cpp TestsAhead): the same
// flips and sums as on one thread, and the helper's sums taken (at least the loop's first test).
TEST_CASE("flip tests measured ahead on a second thread: the same flips, faces and sums at 1, 2 and 3 threads",
          "[threads][flips]") {
    // An ERD mesh of a large image (the helper's threshold) without edge detection: pseudo-random
    // pixels and a few constrained segments, so that some vertices have two wedges.
    const Image im = synth_image(1024, 1024);
    const Image colour = synth_colour(1024, 1024);
    REQUIRE(std::size_t(im.width) * std::size_t(im.height) >= erd::kTwoThreadPixels);
    erd::Cdt mesh;
    REQUIRE(mesh.reset(2 * (im.width - 1), 2 * (im.height - 1)).ok());
    std::uint32_t seed = 7;
    for (int i = 0; i < 2500; ++i) {
        seed = seed * 1664525u + 1013904223u;
        const erd::LatticePoint p{std::int32_t(2 * ((seed >> 8) % 1023u) + 2), std::int32_t(2 * ((seed >> 20) % 1023u) + 2)};
        erd::VertInd v = 0;
        REQUIRE(mesh.insert_point(p, &v).ok());
    }
    for (int k = 0; k < 6; ++k) {
        erd::VertInd a = 0, b = 0;
        REQUIRE(mesh.insert_point({200 + 300 * k, 100 + 40 * k}, &a).ok());
        REQUIRE(mesh.insert_point({260 + 300 * k, 1900 - 50 * k}, &b).ok());
        REQUIRE(mesh.insert_constraint(a, b).ok());
    }
    erd::ErdModel model(im, erd::WedgeValueOptions{});
    model.assign_all(mesh);
    std::vector<erd::ErdModel> channel;
    std::vector<erd::Image> planes;
    channel.reserve(3);
    for (int c = 0; c < 3; ++c) planes.push_back(erd::channel_plane(colour, c));
    for (int c = 0; c < 3; ++c) {
        channel.emplace_back(planes[std::size_t(c)], erd::WedgeValueOptions{});
        channel.back().assign_all(mesh);
    }
    // The refit's face systems: the loop's errors before a flip and its skip of small ones.
    erd::ErdModel fitted = model;
    erd::MeshSystems systems;
    erd::WedgeFitOptions wo;
    erd::fit_wedge_values(mesh, im, wo, &fitted, nullptr, nullptr, {}, &systems);
    REQUIRE(systems.matches(mesh));

    enum class Kind { gray, with_systems, rgb };
    for (Kind kind : {Kind::gray, Kind::with_systems, Kind::rgb}) {
        std::vector<std::array<std::int32_t, 6>> first;
        erd::FlipStats first_stats;
        for (int threads : with_one_thread()) {
            INFO(int(kind) << " kind, " << threads << " threads");
            erd::Cdt cdt = mesh;
            erd::FlipStats fs;
            if (kind == Kind::gray) {
                erd::improve_by_flips(&cdt, im, model, 1u << 20, &fs, nullptr, nullptr, 0.0, threads);
            } else if (kind == Kind::with_systems) {
                erd::MeshSystems own = systems;
                erd::improve_by_flips(&cdt, im, fitted, 1u << 20, &fs, nullptr, &own, 0.2, threads);
            } else {
                erd::improve_by_flips(&cdt, {&planes[0], &planes[1], &planes[2]}, {&channel[0], &channel[1], &channel[2]},
                                      1u << 20, &fs, nullptr, threads);
            }
            REQUIRE(fs.flips > 0);
            if (threads == 1) {
                CHECK(fs.ahead == 0);
                first = erd::canonical_faces(cdt);
                first_stats = fs;
                continue;
            }
#ifndef ERD_NO_THREADS
            CHECK(fs.ahead > 0);
#endif
            CHECK(erd::canonical_faces(cdt) == first);
            CHECK(fs.flips == first_stats.flips);
            CHECK(fs.tested == first_stats.tested);
            CHECK(fs.changed == first_stats.changed);
            CHECK(fs.sse_before == first_stats.sse_before);
            CHECK(fs.sse_after == first_stats.sse_after);
        }
    }
}

// Two calls of the public API at once (a program meshing on two threads): no state shared
// between calls, so each equals the same call made alone. Under ThreadSanitizer (make tsan) this
// also finds any write two calls would share.
TEST_CASE("public API: two meshes on two threads equal the same meshes made one after the other", "[threads][api]") {
    const erd::Image a = synth_image(96, 64, 8, 11);
    const erd::Image b = synth_image(80, 72, 8, 12);
    erd::api::Options opt;
    opt.generate.density = 2.0;
    opt.generate.density_given = true;
    for (auto method : {erd::api::Method::erdgpi, erd::api::Method::erded, erd::api::Method::gpi, erd::api::Method::ed}) {
        INFO(erd::api::method_name(method));
        erd::Model seq_a, seq_b, par_a, par_b;
        erd::Image seq_ra, seq_rb, par_ra, par_rb;
        REQUIRE(erd::api::generate(method, erd::api::view_of(a), opt, &seq_a));
        REQUIRE(erd::api::reconstruct(seq_a, true, &seq_ra));
        REQUIRE(erd::api::generate(method, erd::api::view_of(b), opt, &seq_b));
        REQUIRE(erd::api::reconstruct(seq_b, true, &seq_rb));

        erd::Status st_a, st_b;
        std::thread ta([&] {
            st_a = erd::api::generate(method, erd::api::view_of(a), opt, &par_a);
            if (st_a) st_a = erd::api::reconstruct(par_a, true, &par_ra);
        });
        std::thread tb([&] {
            st_b = erd::api::generate(method, erd::api::view_of(b), opt, &par_b);
            if (st_b) st_b = erd::api::reconstruct(par_b, true, &par_rb);
        });
        ta.join();
        tb.join();
        REQUIRE(st_a);
        REQUIRE(st_b);
        CHECK(model_text(seq_a) == model_text(par_a));
        CHECK(model_text(seq_b) == model_text(par_b));
        CHECK(seq_ra.samples == par_ra.samples);
        CHECK(seq_rb.samples == par_rb.samples);
        CHECK(model_text(par_a) != model_text(par_b));
    }
}

TEST_CASE("erd generate, reconstruct and psnr: -j 1, 2 and 3 write the same bytes; -j alone is no batch", "[threads][cli]") {
    REQUIRE(erd_test::binary_available());
    erd_test::TempDir t;
    const auto run = [&](const std::string& args) {
        return erd_test::run_erd(args, "cd " + erd_test::sh_quote(t.path) + " && ");
    };
    REQUIRE(run("synth -q -W 611 -H 467 -o a.pgm").status == 0);
    for (const char* method : {"ed", "erded", "erdgpi"}) {
        INFO(method);
        std::string model, image, db;
        const std::string m = method, ext = m == "ed" ? ".model" : ".erd";
        for (int j : with_one_thread()) {
            const std::string n = std::to_string(j);
            auto r = run("generate -q -m " + m + " -d 3 -i a.pgm -o m" + n + ext + " -j " + n);
            INFO(r.err);
            REQUIRE(r.status == 0);
            REQUIRE(run("reconstruct m" + n + ext + " -o r" + n + ".pgm -j " + n).status == 0);
            r = run("psnr a.pgm r" + n + ".pgm -j " + n);
            REQUIRE(r.status == 0);
            if (j == 1) {
                model = erd_test::slurp(t.file("m1" + ext));
                image = erd_test::slurp(t.file("r1.pgm"));
                db = r.out;
                REQUIRE(!model.empty());
            } else {
                CHECK(erd_test::slurp(t.file("m" + n + ext)) == model);
                CHECK(erd_test::slurp(t.file("r" + n + ".pgm")) == image);
                CHECK(r.out == db);
            }
        }
    }
    // One file with -j prints no batch line; a bad -j is a usage error.
    auto r = run("generate -m gpi -d 3 -i a.pgm -o g.model -j 2");
    CHECK(r.status == 0);
    CHECK(r.err.find("files") == std::string::npos);
    CHECK(run("generate -m gpi -d 3 -i a.pgm -o g.model -j x").status == 2);
    CHECK(run("psnr a.pgm a.pgm -j 300").status == 2);
}
