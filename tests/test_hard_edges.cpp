// Hard edges (issue 15): the edge-kind measure on hard and blurred versions of the same drawing,
// crack edges that keep pixels on their side, the .erd header block, and ERDGPI/ERDED with hard
// edges (exact N, meshes that verify, point reconstruction).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/imaging/drawings.h"
#include "algorithms/imaging/edge_kind.h"
#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "algorithms/model/metrics.h"
#include "tests/erd_check.h"
#include "tests/erd_run.h"
#include "tests/method_run_util.h"

using namespace erd;
using namespace erd_test;

namespace {

Image picture(const std::string& kind, int blur, int w = 160, int h = 120) {
    DrawingParams p;
    p.kind = kind;
    p.width = w;
    p.height = h;
    p.blur = blur;
    Image im;
    REQUIRE(draw_picture(p, &im).ok());
    return im;
}



// An .erd of a 3x3 image: centre vertex (2, 2), one wedge each (the thesis's body).
const char* kBody = "255\n5\n0 0 10\n4 0 20\n0 4 30\n4 4 40\n2 2 25\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n0\n";

std::string read_error(const std::string& text, ModelFileKind kind = ModelFileKind::unknown) {
    Model m;
    const Status st = read_model(text, kind, &m);
    return st.ok() ? "OK" : st.message;
}

}  // namespace

TEST_CASE("edge kind: every hard-edged picture is hard, its blurred versions soft", "[hardedges]") {
    REQUIRE(drawing_kinds().size() >= 8);
    for (const std::string& kind : drawing_kinds()) {
        INFO(kind);
        const EdgeKindStats hard = measure_edge_kind(picture(kind, 0));
        CHECK(hard.is_hard());
        CHECK(hard.hard_fraction() > 0.9);
        for (int blur : {1, 2}) {
            INFO("blur " << blur);
            const EdgeKindStats soft = measure_edge_kind(picture(kind, blur));
            CHECK(!soft.is_hard());
            CHECK(soft.hard_fraction() < 0.3);
        }
    }
    // A smooth ramp has no strong step: soft (nothing to gain from hard edges).
    Image ramp(64, 64, 255);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) ramp.at(x, y) = std::uint16_t(3 * x + y);
    CHECK(!measure_edge_kind(ramp).is_hard());
}

TEST_CASE("edge kind: --edges auto picks hard for a drawing and soft for its blurred version", "[hardedges]") {
    const Image hard = picture("drawing", 0), soft = picture("drawing", 2);
    CHECK(run_method("erdgpi", hard, 1, EdgeChoice::automatic).model.edges == EdgeKind::hard);
    CHECK(run_method("erdgpi", soft, 1, EdgeChoice::automatic).model.edges == EdgeKind::soft);
    CHECK(run_method("erdgpi", soft, 1, EdgeChoice::hard).model.edges == EdgeKind::hard);
    CHECK(run_method("erdgpi", hard, 1, EdgeChoice::soft).model.edges == EdgeKind::soft);
}

namespace {

// crack_edges as edge_kind.h defines it, written out plainly: every crack's step sorted to find
// the beta-quantile, then hysteresis as a fixed point (a crack >= low joins while it shares a
// pixel corner with a set crack), then the corners with two set cracks or more.
Grid<std::uint8_t> crack_definition(const Image& im, double beta, double r) {
    const int GW = 2 * im.width - 1, GH = 2 * im.height - 1;
    Grid<std::uint8_t> map(GW, GH, 0);
    Grid<int> step(GW, GH, -1);
    std::vector<int> all;
    for (int Y = 0; Y < GH; ++Y)
        for (int X = 0; X < GW; ++X) {
            if ((X + Y) % 2 == 0) continue;
            const int x = X / 2, y = Y / 2;
            step(X, Y) = std::abs(int(im.at(x + X % 2, y + Y % 2)) - int(im.at(x, y)));
            all.push_back(step(X, Y));
        }
    if (all.empty()) return map;
    std::sort(all.begin(), all.end(), std::greater<int>());
    const std::size_t k = std::min(all.size(), std::max<std::size_t>(1, std::size_t(beta * double(all.size()) + 0.5)));
    const double high = std::max(double(all[k - 1]), 0.5 * kStrongStep * double(im.maxval));
    const double low = std::max(1.0, r * high);
    for (int Y = 0; Y < GH; ++Y)
        for (int X = 0; X < GW; ++X) map(X, Y) = step(X, Y) >= 0 && double(step(X, Y)) >= high;
    const auto set_near = [&](int X, int Y) {  // a set crack shares an end (a pixel corner) with (X, Y)
        const int ends[2][2] = {{X % 2 ? X : X - 1, X % 2 ? Y - 1 : Y}, {X % 2 ? X : X + 1, X % 2 ? Y + 1 : Y}};
        for (const auto& e : ends) {
            const int around[4][2] = {{e[0], e[1] - 1}, {e[0], e[1] + 1}, {e[0] - 1, e[1]}, {e[0] + 1, e[1]}};
            for (const auto& q : around)
                if (map.inside(e[0], e[1]) && map.inside(q[0], q[1]) && map(q[0], q[1])) return true;
        }
        return false;
    };
    for (bool grew = true; grew;) {
        grew = false;
        for (int Y = 0; Y < GH; ++Y)
            for (int X = 0; X < GW; ++X)
                if (step(X, Y) >= 0 && !map(X, Y) && double(step(X, Y)) >= low && set_near(X, Y)) map(X, Y) = 1, grew = true;
    }
    for (int Y = 1; Y < GH; Y += 2)
        for (int X = 1; X < GW; X += 2) map(X, Y) = map(X, Y - 1) + map(X, Y + 1) + map(X - 1, Y) + map(X + 1, Y) >= 2;
    return map;
}

}  // namespace

TEST_CASE("crack edges: one detector, many (beta, r), each the definition's map", "[hardedges]") {
    std::uint32_t seed = 12345;
    const auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
    const int sizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {7, 5}, {40, 31}};
    for (const auto& wh : sizes)
        for (const std::uint32_t maxval : {255u, 65535u}) {
            Image im(wh[0], wh[1], maxval);
            // Blocks of flat values with noise: steps of every size, long crack curves.
            for (int y = 0; y < im.height; ++y)
                for (int x = 0; x < im.width; ++x)
                    im.at(x, y) = std::uint16_t((((x / 6 + y / 5) % 3) * (maxval / 3) + next() % (maxval / 16 + 1)) % (maxval + 1));
            const CrackDetector detector(im);
            Grid<std::uint8_t> reused(3, 2, 1);  // the wrong size first, then the last map's memory
            for (const double beta : {0.01, 0.05, 0.3, 1.0})
                for (const double r : {0.0, 0.4, 1.0}) {
                    INFO(wh[0] << " x " << wh[1] << " maxval " << maxval << " beta " << beta << " r " << r);
                    const Grid<std::uint8_t> want = crack_definition(im, beta, r);
                    CHECK(detector.detect(beta, r).data == want.data);
                    CHECK(crack_edges(im, beta, r).data == want.data);
                    detector.detect(beta, r, &reused);
                    CHECK(reused.width == 2 * wh[0] - 1);
                    CHECK(reused.data == want.data);
                }
        }
}

TEST_CASE("crack edges: the chain's edge map is its chosen detection's crack map (set aside, taken back)", "[hardedges]") {
    // The chain keeps one crack map, the last detection's: edge_map() is made from the traced
    // polylines, which may be another detection's.
    const Image im = picture("scene", 1);  // blurred: steps of many sizes, so beta matters
    const auto params = [](double beta) {
        CannyParams p;
        p.beta = beta;
        p.r = 0.4;
        return p;
    };
    const std::vector<std::uint8_t> wide = crack_edges(im, 0.3, 0.4).data, narrow = crack_edges(im, 0.05, 0.4).data;
    REQUIRE(wide != narrow);
    {
        EdgePolylines chain(im, true);
        REQUIRE(chain.detect(params(0.3)).ok());
        CHECK(chain.edge_map().data == wide);
    }
    {
        EdgePolylines chain(im, true);
        REQUIRE(chain.detect(params(0.3)).ok());
        chain.set_aside();
        REQUIRE(chain.detect(params(0.05)).ok());  // into the first map's memory
        REQUIRE(chain.detect(params(0.3)).ok());   // taken back: the memory holds 0.05's map
        CHECK(chain.edge_map().data == wide);
    }
    {
        EdgePolylines chain(im, true);
        REQUIRE(chain.detect(params(0.3)).ok());
        REQUIRE(chain.detect(params(0.05)).ok());
        chain.release_detector();
        CHECK(chain.edge_map().data == narrow);
    }
}

TEST_CASE("crack edges: the simplified curves keep every pixel next to a crack on its side", "[hardedges]") {
    const Image im = picture("cel", 0);
    const Grid<std::uint8_t> map = crack_edges(im, 0.05, 0.4);
    REQUIRE(map.width == 2 * im.width - 1);
    std::size_t cracks = 0;
    for (int Y = 0; Y < map.height; ++Y)
        for (int X = 0; X < map.width; ++X) {
            if (!map(X, Y)) continue;
            CHECK((X % 2 == 1 || Y % 2 == 1));  // never on a pixel centre
            cracks += (X + Y) % 2;
        }
    REQUIRE(cracks > 100);
    const PolylineList traced = trace_polylines(map);
    std::size_t before = 0, after = 0;
    for (std::size_t k = 0; k < traced.size(); ++k) {
        const Polyline line = traced[k];
        const Polyline s = simplify_cracks(line, 8.0);
        before += line.size();
        after += s.size();
        REQUIRE(s.front() == line.front());
        REQUIRE(s.back() == line.back());
        // Each crack midpoint of the traced line: its two pixels on either side of the kept
        // segment that replaced it (located by walking both lines).
        std::size_t j = 0;
        for (std::size_t i = 0; i < line.size(); ++i) {
            while (j + 1 < s.size() && i > 0 && line[i - 1] == s[j + 1]) ++j;
            const LatticePoint p = line[i];
            if ((p.x + p.y) % 2 == 0 || j + 1 >= s.size()) continue;
            const LatticePoint a = s[j], b = s[j + 1];
            const LatticePoint pa = p.x % 2 ? LatticePoint{p.x - 1, p.y} : LatticePoint{p.x, p.y - 1};
            const LatticePoint pb = p.x % 2 ? LatticePoint{p.x + 1, p.y} : LatticePoint{p.x, p.y + 1};
            const auto o = [&](LatticePoint c) {
                return (std::int64_t(b.x) - a.x) * (std::int64_t(c.y) - a.y) - (std::int64_t(c.x) - a.x) * (std::int64_t(b.y) - a.y);
            };
            CHECK(o(pa) * o(pb) < 0);
        }
    }
    CHECK(after * 3 < before);  // it does simplify
}

TEST_CASE("edges header: written for hard edges only, read back, thesis files unchanged", "[hardedges][model_io]") {
    Model m;
    REQUIRE(read_model(kBody, ModelFileKind::erd, &m).ok());
    CHECK(m.edges == EdgeKind::soft);
    std::string text;
    REQUIRE(write_model(m, &text).ok());
    CHECK(text == kBody);  // no header: the thesis's format byte for byte

    m.edges = EdgeKind::hard;
    REQUIRE(write_model(m, &text).ok());
    CHECK(text == std::string("erd-header 1\nedges hard\nend\n") + kBody);
    Model back;
    REQUIRE(read_model(text, ModelFileKind::unknown, &back).ok());
    CHECK(back.kind == ModelKind::erd);
    CHECK(back.edges == EdgeKind::hard);
    std::string again;
    REQUIRE(write_model(back, &again).ok());
    CHECK(again == text);

    // "edges soft" reads like no header at all.
    Model soft;
    REQUIRE(read_model(std::string("erd-header 1\nedges soft\nend\n") + kBody, ModelFileKind::erd, &soft).ok());
    CHECK(soft.edges == EdgeKind::soft);
    REQUIRE(write_model(soft, &again).ok());
    CHECK(again == kBody);
}

TEST_CASE("edges header: malformed blocks get one message naming the problem", "[hardedges][model_io]") {
    const std::string b = kBody;
    CHECK(read_error("erd-header 1\ncolour rgb\nend\n" + b) == "line 2: unknown header key 'colour' (this reader knows: edges, hard-edges, soft-edges, channels, type, range, nodata, holes, doubled, geo-pixel-scale, geo-tiepoints, geo-transform, geo-keys, geo-doubles, geo-ascii)");
    CHECK(read_error("erd-header 2\nend\n" + b) == "line 1: header version 2 is not supported (this reader knows 1)");
    CHECK(read_error("erd-header 1\nedges blurry\nend\n" + b) == "line 2: edges must be hard or soft, found 'blurry'");
    CHECK(read_error("erd-header 1\nedges hard\nedges hard\nend\n" + b) == "line 3: header key 'edges' given twice");
    CHECK(read_error("erd-header 1\nedges hard\n") == "file ends early: expected a header key or 'end'");
    CHECK(read_error("erd-header 1\nedges hard\nend\n255\n4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n2\n0 1 2\n1 3 2\n", ModelFileKind::basic) ==
          "line 2: header key 'edges' is for .erd files only");
    CHECK(read_error("erd-header 1\nend\n" + b) == "OK");
}

TEST_CASE("hard edges: ERDGPI and ERDED make exactly N points, verified meshes, point reconstruction", "[hardedges]") {
    for (const char* kind : {"drawing", "cartoon", "map"}) {
        const Image im = picture(kind, 0);
        for (const char* method : {"erdgpi", "erded"}) {
            INFO(kind << " " << method);
            const GenerateResult r = run_method(method, im, 1.0, EdgeChoice::automatic);
            CHECK(r.achieved == r.requested);
            CHECK(r.model.size() == r.requested);
            CHECK(r.model.edges == EdgeKind::hard);
            CHECK(!supersampled(r.model));
            test::check_model(r.model);
            REQUIRE(check_triangulation(r.model).ok());
        }
    }
    // The drawing's hard edges: ERDGPI far above GPI and above its own soft version.
    const Image im = picture("drawing", 0);
    const double gpi = own_psnr(im, run_method("gpi", im, 1.0, EdgeChoice::automatic).model);
    const double hard = own_psnr(im, run_method("erdgpi", im, 1.0, EdgeChoice::automatic).model);
    const double soft = own_psnr(im, run_method("erdgpi", im, 1.0, EdgeChoice::soft).model);
    CHECK(hard > gpi + 10);
    CHECK(hard > soft + 10);
    // Both treatments of over-budget curves ran; the better one is the model (its PSNR).
    const GenerateResult r = run_method("erdgpi", im, 1.0, EdgeChoice::automatic);
    CHECK(r.stats.erd.hard_edges);
    CHECK(r.stats.erd.edges_measured);
    REQUIRE(r.stats.erd.plain_psnr > 0);
    REQUIRE(r.stats.erd.exact_psnr > 0);
    CHECK(own_psnr(im, r.model) == std::max(r.stats.erd.plain_psnr, r.stats.erd.exact_psnr));
    bool said = false;
    for (const std::string& line : result_lines(r.stats)) said = said || line.rfind("edges: hard (measured: ", 0) == 0;
    CHECK(said);
}

TEST_CASE("hard edges: the run without the fallback is skipped only where it would repeat the first", "[hardedges]") {
    // hard_fallback reaches only step 1's counts: where no count took the plain curves, step 1
    // (parameters, curves, mesh) is the same without the fallback, so run_erd_method's second run
    // would repeat the first. Across sizes the fallback both fires (tiny N) and does not.
    int fired = 0, quiet = 0;
    for (const char* kind : {"drawing", "cartoon", "map"}) {
        const Image im = picture(kind, 0);
        for (std::size_t n : {30, 200, 1000, 4000}) {
            INFO(kind << " N " << n);
            InitialMeshOptions mo;
            mo.target = n;
            mo.hard_edges = true;
            InitialMesh with, without;
            Cdt a, b;
            REQUIRE(build_initial_mesh(im, mo, &a, &with).ok());
            mo.hard_fallback = false;
            REQUIRE(build_initial_mesh(im, mo, &b, &without).ok());
            CHECK_FALSE(without.plain_fallback);
            if (with.plain_fallback) {
                ++fired;
                continue;
            }
            ++quiet;
            erd::test::check_same_step1(with, without);
            CHECK(with.n0 == without.n0);
            CHECK(a.vertex_count() == b.vertex_count());
        }
    }
    CHECK(fired > 0);
    CHECK(quiet > 0);
    // Through the method: no fallback, one run, both PSNRs the model's; with it, two runs.
    for (double d : {0.15, 5.0}) {
        const Image im = picture("drawing", 0);
        const GenerateResult r = run_method("erdgpi", im, d, EdgeChoice::hard);
        INFO("density " << d << " fallback " << r.stats.erd.plain_fallback);
        REQUIRE(r.stats.erd.plain_psnr > 0);
        CHECK(own_psnr(im, r.model) == std::max(r.stats.erd.plain_psnr, r.stats.erd.exact_psnr));
        CHECK(r.stats.erd.plain_fallback == (d < 1));  // the tiny mesh needs the plain curves, the large one not
        if (!r.stats.erd.plain_fallback) CHECK(r.stats.erd.plain_psnr == r.stats.erd.exact_psnr);
    }
}

TEST_CASE("hard edges in colour: both runs, the better kept by RGB-PSNR, verified", "[hardedges][colour]") {
    // A drawing's three channels made different (not gray), so the colour methods mesh it.
    const Image g = picture("drawing", 0);
    Image im(g.width, g.height, g.maxval, 3);
    for (std::size_t i = 0; i < g.samples.size(); ++i) {
        im.samples[3 * i] = g.samples[i];
        im.samples[3 * i + 1] = std::uint16_t(g.maxval - g.samples[i]);
        im.samples[3 * i + 2] = std::uint16_t(g.samples[i] / 2 + (i % 7 == 0 ? 1 : 0));
    }
    for (const char* method : {"erdgpi", "erded"}) {
        INFO(method);
        const GenerateResult r = run_method(method, im, 1.0, EdgeChoice::automatic);
        CHECK(r.model.channels == 3);
        CHECK(r.model.edges == EdgeKind::hard);
        CHECK(r.model.size() == r.requested);
        test::check_model(r.model);
        REQUIRE(check_triangulation(r.model).ok());
        REQUIRE(r.stats.erd.plain_psnr > 0);
        REQUIRE(r.stats.erd.exact_psnr > 0);
        CHECK(own_psnr(im, r.model) == std::max(r.stats.erd.plain_psnr, r.stats.erd.exact_psnr));
    }
}

TEST_CASE("hard edges: erd generate --edges, the header in the file, reconstruct by point evaluation", "[hardedges][cli]") {
    REQUIRE(binary_available());
    TempDir t;
    REQUIRE(!t.path.empty());
    REQUIRE(run_erd("synth -q --kind drawing -W 160 -H 120 -o " + t.file("d.pgm")).status == 0);
    REQUIRE(run_erd("generate -q --method erdgpi -i " + t.file("d.pgm") + " -d 1 -o " + t.file("auto.erd") + " --stats " +
                    t.file("s.json")).status == 0);
    CHECK(slurp(t.file("s.json")).find(",\"edges\":\"hard\"}") != std::string::npos);
    CHECK(slurp(t.file("auto.erd")).rfind("erd-header 1\nedges hard\nend\n", 0) == 0);
    REQUIRE(run_erd("generate -q --method erdgpi --thesis -i " + t.file("d.pgm") + " -d 1 -o " + t.file("thesis.erd")).status == 0);
    CHECK(slurp(t.file("thesis.erd")).rfind("255\n", 0) == 0);
    REQUIRE(run_erd("generate -q --method erdgpi --edges soft -i " + t.file("d.pgm") + " -d 1 -o " + t.file("soft.erd")).status == 0);
    CHECK(slurp(t.file("soft.erd")).rfind("255\n", 0) == 0);
    // A hard-edged file reconstructs by point evaluation: the same image as --no-aa.
    REQUIRE(run_erd("reconstruct " + t.file("auto.erd") + " -o " + t.file("a.pgm")).status == 0);
    REQUIRE(run_erd("reconstruct --no-aa " + t.file("auto.erd") + " -o " + t.file("b.pgm")).status == 0);
    CHECK(slurp(t.file("a.pgm")) == slurp(t.file("b.pgm")));
    const RunResult bad = run_erd("generate -q --method erdgpi --edges blurry -i " + t.file("d.pgm") + " -d 1 -o " + t.file("x.erd"));
    CHECK(bad.status == 2);
    CHECK(bad.err.find("--edges: 'blurry' is not hard, soft or auto") != std::string::npos);
}
