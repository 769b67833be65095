// The shared parts of the four methods: the registry and what reads it (API, thesis names), the
// exact-count rules and policy, the thesis preset, step 1 in one home, the typed statistics.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/exact_count.h"
#include "algorithms/methods/memory_estimate.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/scaffold.h"
#include "api/erd.h"
#include "tests/erd_run.h"
#include "tests/output_util.h"

using namespace erd;

TEST_CASE("method registry: one row per method, read by the API and the thesis names", "[methods]") {
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    REQUIRE(count == 8);
    CHECK(method_names() == "ed, gpi, erded, erdgpi, gpr, gprfs, id, erdgpr");
    const api::Method ids[] = {api::Method::ed,  api::Method::gpi,   api::Method::erded, api::Method::erdgpi,
                               api::Method::gpr, api::Method::gprfs, api::Method::id,    api::Method::erdgpr};
    for (std::size_t i = 0; i < count; ++i) {
        INFO(table[i].name);
        CHECK(find_method(table[i].name) == &table[i]);
        CHECK(std::string(api::method_name(ids[i])) == table[i].name);
        // The thesis's four have its program names; the removal methods (issue 45) none.
        CHECK((table[i].thesis_program != nullptr) == (i < 4));
        if (i < 4) CHECK(std::string(table[i].thesis_flags).rfind("idnotpx", 0) == 0);
        CHECK(table[i].bytes_per_pixel > 0);
        CHECK(table[i].run != nullptr);
        api::Options o;
        o.generate.points = 100;
        CHECK(api::memory_estimate(ids[i], 100, 100, o) ==
              10000 * table[i].bytes_per_pixel + 100 * table[i].bytes_per_point + kMemoryBoundFixed);
    }
    CHECK(table[0].model == ModelKind::basic);
    CHECK(table[3].model == ModelKind::erd);
    CHECK(table[4].model == ModelKind::basic);
    CHECK(table[7].model == ModelKind::erd);
    CHECK(find_method("erd_gpi") == nullptr);  // the thesis's name is not a method name
}

TEST_CASE("exact count: the two tie rules and the top-up", "[methods]") {
    Grid<double> density(4, 1, 0.5);
    density(3, 0) = 0.9;
    const std::vector<LatticePoint> pts = {{0, 0}, {2, 0}, {4, 0}, {6, 0}};  // densities .5 .5 .5 .9
    std::vector<LatticePoint> a = pts, b = pts;
    CHECK(drop_least_dense(density, 2, DropTies::later_first, &a) == 2);
    CHECK(a == std::vector<LatticePoint>{{0, 0}, {6, 0}});
    CHECK(drop_least_dense(density, 2, DropTies::earlier_first, &b) == 2);
    CHECK(b == std::vector<LatticePoint>{{4, 0}, {6, 0}});
    CHECK(drop_least_dense(density, 5, DropTies::later_first, &b) == 0);

    Grid<double> d2(3, 2, 0.1);
    d2(2, 1) = 0.8;
    d2(0, 1) = 0.8;
    Grid<std::uint8_t> occupied(3, 2, 0);
    occupied(1, 1) = 1;
    std::vector<LatticePoint> c = {{0, 0}};
    CHECK(adjust_to_exact(d2, occupied, 4, &c) == 3);
    // The two densest (ties in row-major order), then the first of the 0.1 pixels left.
    CHECK(c == std::vector<LatticePoint>{{0, 0}, {0, 2}, {4, 2}, {2, 0}});
    CHECK(adjust_to_exact(d2, occupied, 2, &c) == 2);
    CHECK(c.size() == 2);
    // More wanted than free pixels: every free one, densest first (ties in row-major order).
    std::vector<LatticePoint> e = {{2, 0}};
    CHECK(adjust_to_exact(d2, occupied, 100, &e) == 4);
    CHECK(e == std::vector<LatticePoint>{{2, 0}, {0, 2}, {4, 2}, {0, 0}, {4, 0}});
    // A larger grid against a plain sort of every free pixel (the heap keeps only the wanted).
    Grid<double> d3(37, 23, 0.0);
    Grid<std::uint8_t> occ3(37, 23, 0);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x) {
            d3(x, y) = double((x * 7 + y * 13) % 11) / 10.0;  // many ties
            occ3(x, y) = (x + 2 * y) % 9 == 0;
        }
    std::vector<LatticePoint> f = {{4, 4}}, want = f;
    std::vector<int> order;
    for (int i = 0; i < 37 * 23; ++i)
        if (!occ3.data[std::size_t(i)] && i != 2 * 37 + 2) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](int p, int q) { return d3.data[std::size_t(p)] > d3.data[std::size_t(q)]; });
    for (int k = 0; k < 60; ++k) want.push_back({2 * (order[std::size_t(k)] % 37), 2 * (order[std::size_t(k)] / 37)});
    CHECK(adjust_to_exact(d3, occ3, 61, &f) == 60);
    CHECK(f == want);
}

TEST_CASE("exact-count policy and the thesis preset live in the library", "[methods]") {
    std::string warning = "stale";
    CHECK(check_exact_count(10, 10, ExactMode::fail, &warning).ok());
    CHECK(warning.empty());
    Status st = check_exact_count(10, 9, ExactMode::fail, &warning);
    CHECK(st.code == Code::density);
    CHECK(st.message == "target sampling density not achieved exactly (requested 10 but got 9)");
    CHECK(check_exact_count(10, 9, ExactMode::warn, &warning).ok());
    CHECK(warning == st.message);
    CHECK(check_exact_count(10, 9, ExactMode::ignore, &warning).ok());
    CHECK(warning.empty());

    const GenerateOptions t = thesis_options();
    CHECK(t.wedge_fit == 0);
    CHECK(t.alpha_min == 1.0);
    CHECK(t.alpha_max == 1.5);
    CHECK(t.edge_zero_radius == 0);
    const api::Options at = api::thesis_options();
    CHECK(at.exact == api::ExactMode::fail);
    CHECK(at.generate.wedge_fit == 0);
}

TEST_CASE("step 1 has one home: the ERD initial mesh uses the polylines edge_polylines gives", "[methods]") {
    const Image im = output_test::wave_disc_image();  // 40 x 30 with a disc: step 1 finds its edge
    EdgePolylineParams p;  // library defaults: beta 0.055, r 0.4, l 5, epsilon one pixel
    EdgePolylineResult chain;
    REQUIRE(edge_polylines(im, p, &chain).ok());
    REQUIRE_FALSE(chain.polylines.empty());
    CHECK(chain.edges.width == 79);
    CHECK(chain.traced >= chain.polylines.size());

    InitialMeshOptions mo;
    mo.method = ErdMethod::erdgpi;
    mo.target = 40 * 30;  // large: no polyline left out
    mo.request.beta = p.canny.beta;
    mo.request.r = p.canny.r;
    mo.request.l = p.min_length;
    mo.request.eps = p.epsilon;
    mo.request.simple = 1;
    Cdt cdt;
    InitialMesh mesh;
    REQUIRE(build_initial_mesh(im, mo, &cdt, &mesh).ok());
    CHECK(mesh.polylines == chain.polylines);
    CHECK(mesh.edges.data == chain.edges.data);

    p.epsilon = -1;
    CHECK(edge_polylines(im, p, &chain).code == Code::input);
}

TEST_CASE("typed statistics: each method fills its stages, the printed lines come from them", "[methods]") {
    const Image im = output_test::wave_disc_image();
    GenerateOptions o;
    o.points = 120;
    for (const char* name : {"ed", "gpi", "erded", "erdgpi"}) {
        INFO(name);
        const MethodInfo* m = find_method(name);
        REQUIRE(m);
        GenerateResult r;
        REQUIRE(m->run(im, o, &r).ok());
        CHECK(r.achieved == 120);
        const bool erd_model = m->model == ModelKind::erd;
        CHECK(r.model.kind == m->model);
        CHECK(r.stats.has_erd == erd_model);
        CHECK(r.stats.has_wedge_fit == erd_model);  // wedge_fit 6 by default
        CHECK(r.stats.has_greedy == (std::string(name).find("gpi") != std::string::npos));
        CHECK(r.stats.has_diffusion == (std::string(name).find("ed") != std::string::npos));
        CHECK(r.stages.back().name == "model");
        const std::vector<std::string> lines = result_lines(r.stats);
        REQUIRE_FALSE(lines.empty());
        if (erd_model) {
            CHECK(lines[0].rfind("wedge refit: ", 0) == 0);  // both ERD methods, one tail
            CHECK(lines[1].rfind("beta: ", 0) == 0);
            CHECK(r.stats.erd.initial_vertices >= 4);
            CHECK(r.polylines.size() == r.stats.erd.polylines);
        }
        if (r.stats.has_greedy) CHECK(lines.back().rfind("psnr (point evaluation): ", 0) == 0);
    }
    // The library API hands out the same typed fields.
    GenerateResult direct;
    REQUIRE(find_method("erdgpi")->run(im, o, &direct).ok());
    api::Options ao;
    ao.generate = o;
    Model model;
    api::GenerateInfo info;
    REQUIRE(api::generate(api::Method::erdgpi, api::view_of(im), ao, &model, &info).ok());
    REQUIRE(info.stats.has_erd);
    CHECK(info.stats.erd.params.beta == direct.stats.erd.params.beta);
    CHECK(info.stats.erd.params.l == direct.stats.erd.params.l);
    CHECK(info.stats.greedy.insertions == direct.stats.greedy.insertions);
    CHECK(result_lines(info.stats) == result_lines(direct.stats));
    CHECK(info.stages.size() == direct.stages.size());
}

TEST_CASE("erd generate: an unknown --method gets a did-you-mean, exit 2", "[cli]") {
    REQUIRE(erd_test::binary_available());
    erd_test::RunResult r = erd_test::run_erd("generate --method erdgdi -i x.pgm -o y.erd");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("unknown method 'erdgdi'; available: ed, gpi, erded, erdgpi, gpr, gprfs, id, erdgpr. Did you mean 'erdgpi'?"));
    r = erd_test::run_erd("generate --method zzzzzz -i x.pgm -o y.erd");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("unknown method 'zzzzzz'; available: ed, gpi, erded, erdgpi, gpr, gprfs, id, erdgpr.\n"));
}
