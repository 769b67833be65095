// Pictures, exports, statistics (library level): model edges and corner wedges, OBJ/PLY export
// with wedge copies, SVG and raster render, the error map, the --stats JSON emitter, the progress hook.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "algorithms/output/export.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/output/render.h"
#include "cli/progress.h"
#include "cli/stats_json.h"
#include "tests/output_util.h"

using namespace erd;
using namespace output_test;

TEST_CASE("mesh edges of the A.4.2 diagonal: five edges, the diagonal constrained", "[output]") {
    ModelTopology topo;
    REQUIRE(build_topology(diagonal_erd(), &topo).ok());
    std::vector<ModelEdge> edges = model_edges(diagonal_erd(), topo);
    REQUIRE(edges.size() == 5);
    int constrained = 0;
    for (const auto& e : edges)
        if (e.constrained) { ++constrained; CHECK(e.a == 1); CHECK(e.b == 2); }
    CHECK(constrained == 1);
    CHECK(std::count(topo.twin.begin(), topo.twin.end(), kNoHalfEdge) == 4);  // hull

    // The basic model is continuous: nothing constrained; an explicit list is honoured.
    Model b = diagonal_basic();
    REQUIRE(build_topology(b, &topo).ok());
    for (const auto& e : model_edges(b, topo)) CHECK_FALSE(e.constrained);
    b.constraints = {{2, 1}};
    edges = model_edges(b, topo);
    // Sorted: 0-1, 0-2, 1-2, 1-3, 2-3.
    CHECK(edges[2].a == 1);
    CHECK(edges[2].b == 2);
    CHECK(edges[2].constrained);

    Model bad = diagonal_basic();
    bad.faces[1][2] = 7;
    CHECK(build_topology(bad, &topo).code == Code::input);
    bad.faces[1][2] = 1;
    CHECK(build_topology(bad, &topo).code == Code::input);  // repeats a vertex
}

TEST_CASE("wedges of the A.4.2 diagonal: corners 1 and 2 have two each", "[output]") {
    Model m = diagonal_erd();
    ModelTopology topo;
    REQUIRE(build_topology(m, &topo).ok());
    CornerWedges cw = corner_wedges(m, topo);
    CHECK(cw.count == 6);
    CHECK(cw.first == std::vector<std::uint32_t>{0, 1, 3, 5, 6});
    // Face 0 = (0, 2, 1) holds the first wedge of each vertex, face 1 = (1, 2, 3) the second.
    CHECK(cw.label == std::vector<std::uint32_t>{0, 3, 1, 2, 4, 5});
    // Equal values across the diagonal: one wedge per vertex again.
    m.corner_values = {{127, 60, 60}, {60, 60, 90}};
    CHECK(corner_wedges(m, topo).count == 4);
    // ... unless the diagonal is listed as a constraint.
    m.constraints = {{1, 2}};
    CHECK(corner_wedges(m, topo).count == 6);
}

TEST_CASE("OBJ of the diagonal: 6 vertex copies for ERD, 4 for basic, faces point up", "[output]") {
    std::string obj;
    ExportCounts c;
    ExportOptions o;
    o.zscale = 0.5;
    REQUIRE(export_mesh(diagonal_erd(), o, &obj, &c).ok());
    CHECK(c.vertices == 6);
    CHECK(c.faces == 2);
    auto v = lines_starting(obj, "v ");
    auto f = lines_starting(obj, "f ");
    REQUIRE(v.size() == 6);
    REQUIRE(f.size() == 2);
    // Copies in vertex order, wedges by first face: v0, v1 (73), v1 (54), v2 (73), v2 (54), v3.
    // y is flipped: y = 49 - Y/2.
    CHECK(v[0] == "v 0 49 63.5");
    CHECK(v[1] == "v 0 0 36.5");
    CHECK(v[2] == "v 0 0 27");
    CHECK(v[3] == "v 49 49 36.5");
    CHECK(v[4] == "v 49 49 27");
    CHECK(v[5] == "v 49 0 45");
    // Face (0, 2, 1) -> copies (1, 4, 2) 1-based, written 0, 2, 1 for counter-clockwise with y up.
    CHECK(f[0] == "f 1 2 4");
    CHECK(f[1] == "f 3 6 5");

    REQUIRE(export_mesh(diagonal_basic(), o, &obj, &c).ok());
    CHECK(c.vertices == 4);
    CHECK(lines_starting(obj, "v ").size() == 4);
    CHECK(lines_starting(obj, "f ")[0] == "f 1 2 3");

    // Default zscale: max(W, H) / (10 maxval).
    CHECK(default_zscale(diagonal_basic()) == Approx(50.0 / 2550.0));
}

TEST_CASE("PLY of the diagonal: header counts and index lists", "[output]") {
    std::string ply;
    ExportOptions o;
    o.format = MeshFormat::ply;
    o.zscale = 1;
    REQUIRE(export_mesh(diagonal_erd(), o, &ply).ok());
    CHECK(ply.compare(0, 4, "ply\n") == 0);
    CHECK(count(ply, "element vertex 6\n") == 1);
    CHECK(count(ply, "element face 2\n") == 1);
    auto tail = ply.substr(ply.find("end_header\n") + 11);
    auto faces = lines_starting(tail, "3 ");
    REQUIRE(faces.size() == 2);
    CHECK(faces[0] == "3 0 1 3");
    CHECK(lines_starting(tail, "0 49 127").size() == 1);
}

TEST_CASE("SVG of the diagonal: 4 thin edges, 1 constrained, 4 vertex dots", "[output]") {
    RenderOptions o;
    o.scale = 2;
    o.vertices = true;
    std::string svg;
    REQUIRE(render_svg(diagonal_erd(), "", o, &svg).ok());
    CHECK(count(svg, "<svg ") == 1);
    CHECK(count(svg, "width=\"100\" height=\"100\"") == 2);  // svg element and background rect
    CHECK(count(group(svg, "edges"), "<line ") == 4);
    std::string cons = group(svg, "constrained");
    CHECK(count(cons, "<line ") == 1);
    CHECK(count(cons, "stroke=\"#eb1919\" stroke-width=\"2.5\"") == 1);
    // Vertex 1 = (0, 49) px -> (1, 99); vertex 2 = (49, 0) px -> (99, 1).
    CHECK(count(cons, "x1=\"1\" y1=\"99\" x2=\"99\" y2=\"1\"") == 1);
    CHECK(count(group(svg, "vertices"), "<circle ") == 4);
    CHECK(count(svg, "<line ") == 5);

    // A crop keeps only the edges that reach it.
    o.crop_x = 0; o.crop_y = 0; o.crop_w = 10; o.crop_h = 10;
    REQUIRE(render_svg(diagonal_erd(), "data:image/png;base64,AAAA", o, &svg).ok());
    // The top and left hull edges, and the diagonal (culling is by bounding box only); not the
    // right and bottom hull edges.
    CHECK(count(svg, "<line ") == 3);
    CHECK(count(svg, "<image id=\"background\"") == 1);
    o.crop_x = 45;
    CHECK(render_svg(diagonal_erd(), "", o, &svg).code == Code::input);
}

TEST_CASE("raster render: constrained edge red and thick, hull blue, interior white", "[output]") {
    RenderOptions o;
    o.scale = 4;
    RgbImage im;
    REQUIRE(render_raster(diagonal_erd(), nullptr, o, &im).ok());
    REQUIRE(im.width == 200);
    REQUIRE(im.height == 200);
    auto at = [&](int x, int y, int k) { return int(im.pixels[(std::size_t(y) * 200 + std::size_t(x)) * 3 + std::size_t(k)]); };
    // The diagonal runs from (2, 198) to (198, 2): pixel (99, 100) has its centre on it.
    CHECK(at(99, 100, 0) == 235);
    CHECK(at(99, 100, 1) == 25);
    // 1.5 px off the diagonal (perpendicular distance ~1.06) still partly red: the line is 2.5 wide.
    CHECK(at(100, 100, 1) < 255);
    CHECK(at(100, 100, 0) > at(100, 100, 1));
    // The left hull edge x = 2 is one pixel wide and blue: pixel column 1 is centred 0.5 px away.
    CHECK(at(1, 50, 2) == 255);
    CHECK(at(1, 50, 0) < 255);
    CHECK(at(5, 50, 0) == 255);
    // Far from every edge: white.
    CHECK(at(60, 60, 0) == 255);
    CHECK(at(60, 60, 1) == 255);
    CHECK(at(60, 60, 2) == 255);

    // Background scaled pixel for pixel; the model size must match.
    RgbImage bg(50, 50, 100);
    REQUIRE(render_raster(diagonal_erd(), &bg, o, &im).ok());
    CHECK(at(60, 60, 0) == 100);
    RgbImage wrong(10, 10, 0);
    CHECK(render_raster(diagonal_erd(), &wrong, o, &im).code == Code::input);
    o.scale = 1000;
    CHECK(render_raster(diagonal_erd(), nullptr, o, &im).code == Code::input);
}

TEST_CASE("error map ramp: zero black, full scale white, sizes checked", "[output]") {
    Image a(3, 1, 255), b(3, 1, 255);
    a.samples = {10, 10, 10};
    b.samples = {10, 42, 200};
    RgbImage out;
    REQUIRE(error_map(a, b, 0, &out).ok());  // full = 255/8 = 31.875
    CHECK(out.pixels[0] == 0);
    CHECK(out.pixels[1] == 0);
    CHECK(out.pixels[2] == 0);
    for (int k = 3; k < 9; ++k) CHECK(out.pixels[std::size_t(k)] == 255);
    Image c(2, 1, 255);
    CHECK(error_map(a, c, 0, &out).code == Code::input);
    CHECK(auto_scale(50, 50) == 11);
    CHECK(auto_scale(1024, 768) == 1);
}

TEST_CASE("stats JSON: counts from the model, parameters, stages, psnr", "[output]") {
    GenerateResult r;
    r.model = diagonal_erd();
    r.requested = 5;
    r.achieved = 4;
    r.stages = {{"edges", 0.25}, {"greedy \"insertion\"", 1.5}};
    Image im(50, 50, 255);
    r.stats.has_erd = true;
    r.stats.erd.params.beta = 0.055;
    r.stats.erd.params.r = 0.4;
    r.stats.erd.params.l = 5;
    r.stats.erd.params.eps = 1;
    r.stats.erd.params.simple = false;
    r.stats.erd.dropped_crossing = 3;
    r.stats.has_greedy = true;
    r.stats.greedy.insertions = 1;
    cli::GenerateStats s = cli::collect_stats("erdgpi", im, r);
    CHECK(s.constrained_edges == 1);
    CHECK(s.constrained_vertices == 2);
    CHECK(s.has_params);
    CHECK(s.l == 5);
    CHECK_FALSE(s.simple);
    s.total_seconds = 2;
    s.peak_memory_bytes = cli::peak_memory_bytes();
    CHECK(s.peak_memory_bytes > 0);
    s.has_psnr = true;
    s.psnr = 31.25;
    std::string text = cli::stats_json(s);
    CHECK(text.back() == '\n');
    CHECK(std::count(text.begin(), text.end(), '\n') == 1);
    Json j = parse_json(text.substr(0, text.size() - 1));
    REQUIRE(j.kind == Json::object);
    CHECK(j["method"].s == "erdgpi");
    CHECK(j["model"].s == "erd");
    CHECK(j["image"]["width"].n == 50);
    CHECK(j["image"]["maxval"].n == 255);
    CHECK(j["points"]["requested"].n == 5);
    CHECK(j["points"]["achieved"].n == 4);
    CHECK(j["vertices"].n == 4);
    CHECK(j["faces"].n == 2);
    CHECK(j["constrained_edges"].n == 1);
    CHECK(j["constrained_vertices"].n == 2);
    CHECK(j["dropped_constraints"].n == 3);
    CHECK(j["parameters"]["beta"].n == 0.055);
    CHECK(j["parameters"]["l"].n == 5);
    CHECK(j["parameters"]["simple"].kind == Json::boolean);
    CHECK(j["stop"].s == "target");
    REQUIRE(j["stages"].items.size() == 2);
    CHECK(j["stages"].items[1]["name"].s == "greedy \"insertion\"");
    CHECK(j["stages"].items[1]["seconds"].n == 1.5);
    CHECK(j["peak_memory_bytes"].n > 0);
    CHECK(j["psnr"].n == 31.25);

    // A basic model without --psnr-report: null parameters, no psnr key.
    r.model = diagonal_basic();
    r.stats = erd::RunStats();
    s = cli::collect_stats("gpi", im, r);
    j = parse_json(cli::stats_json(s));
    CHECK(j["model"].s == "basic");
    CHECK(j["parameters"].kind == Json::null);
    CHECK(j["stop"].kind == Json::null);
    CHECK(j["constrained_edges"].n == 0);
    CHECK_FALSE(j.has("psnr"));
}

TEST_CASE("wedge copies of a generated ERD model: one value each, as many as vertex_wedges, same after a round trip",
          "[output]") {
    const erd::MethodInfo* method = erd::find_method("erdgpi");
    if (!method) {
        WARN("erdgpi not registered in this build");
        return;
    }
    erd::Image im = wave_disc_image();
    erd::GenerateOptions opt;
    opt.points = 80;
    erd::GenerateResult res;
    REQUIRE(method->run(im, opt, &res).ok());
    const Model& m = res.model;
    REQUIRE(m.kind == ModelKind::erd);

    ModelTopology topo;
    REQUIRE(build_topology(m, &topo).ok());
    const CornerWedges cw = corner_wedges(m, topo);
    const std::uint32_t n = cw.count;
    std::size_t multi = 0;
    for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
        INFO("vertex " << v);
        CHECK(int(cw.first[v + 1] - cw.first[v]) == vertex_wedges(m, topo, v).count);
        multi += cw.first[v + 1] - cw.first[v] > 1 ? 1 : 0;
    }
    CHECK(multi > 0);
    // Every corner of one wedge carries one value.
    std::vector<double> value(n, -1);
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            double& w = value[cw.label[3 * f + std::size_t(i)]];
            if (w < 0) w = m.corner_values[f][std::size_t(i)];
            CHECK(w == m.corner_values[f][std::size_t(i)]);
        }

    // The model written to .erd and read back draws and exports the same.
    std::string text, svg1, svg2, obj1, obj2;
    REQUIRE(write_model(m, &text).ok());
    Model back;
    REQUIRE(read_model(text, ModelFileKind::erd, &back).ok());
    RenderOptions ro;
    ro.scale = 1;
    REQUIRE(render_svg(m, "", ro, &svg1).ok());
    REQUIRE(render_svg(back, "", ro, &svg2).ok());
    CHECK(count(group(svg1, "constrained"), "<line ") == count(group(svg2, "constrained"), "<line "));
    ExportCounts c1, c2;
    REQUIRE(export_mesh(m, ExportOptions(), &obj1, &c1).ok());
    REQUIRE(export_mesh(back, ExportOptions(), &obj2, &c2).ok());
    CHECK(c1.vertices == n);
    CHECK(c2.vertices == c1.vertices);
    CHECK(c2.faces == m.faces.size());
}

TEST_CASE("progress is shown only when forced or on a terminal, never when quiet", "[output]") {
    CHECK_FALSE(cli::Progress::should_show(true, true));
    CHECK_FALSE(cli::Progress::should_show(false, true));
    CHECK(cli::Progress::should_show(true, false));
    // A hook with no function is a no-op; one with a function reaches it with stage and fraction.
    ProgressHook none;
    CHECK_FALSE(bool(none));
    none("x", 0.5);
    struct Seen { std::string stage; double fraction = -1; } seen;
    ProgressHook hook{[](void* ctx, const char* stage, double f) {
                          static_cast<Seen*>(ctx)->stage = stage;
                          static_cast<Seen*>(ctx)->fraction = f;
                      },
                      &seen};
    hook("greedy insertion", 0.25);
    CHECK(seen.stage == "greedy insertion");
    CHECK(seen.fraction == 0.25);
}

