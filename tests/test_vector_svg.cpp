// erd render --vector: every face's gradient is its plane (read back from the SVG text and
// evaluated at the face's corners), ids are unique and defined, flat faces are one colour, no
// raster is embedded; the CLI refuses the options that do not go with it. The browser measurement
// is tools/svg_browser_psnr.sh (a stage of tests/run_all.sh).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/output/vector_svg.h"
#include "tests/erd_run.h"

using namespace erd_test;

namespace {

struct Gradient {
    double x1, y1, x2, y2;
};

// What a renderer paints at (u, v) for the black-to-white template gradient g.
double paint(const Gradient& g, double u, double v) {
    double dx = g.x2 - g.x1, dy = g.y2 - g.y1;
    return 255 * std::clamp(((u - g.x1) * dx + (v - g.y1) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
}

// Checks every face of m against the SVG text: path f is face f, its fill the face's plane.
void check_planes(const erd::Model& m, const std::string& svg, double unit) {
    std::map<std::string, Gradient> grads;
    std::regex grad_re("<linearGradient id=\"(\\w+)\" xlink:href=\"#_\" x1=\"([-.0-9]+)\" y1=\"([-.0-9]+)\" x2=\"([-.0-9]+)\" y2=\"([-.0-9]+)\"/>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), grad_re); it != std::sregex_iterator(); ++it) {
        const auto& g = *it;
        INFO(g[0].str());
        REQUIRE(grads.count(g[1]) == 0);  // ids unique
        grads[g[1]] = {std::stod(g[2]), std::stod(g[3]), std::stod(g[4]), std::stod(g[5])};
    }
    std::regex path_re("<path fill=\"([^\"]+)\" d=\"M[-.0-9 ]+z\"/>");
    std::size_t f = 0, flat = 0;
    std::set<std::string> used;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path_re); it != std::sregex_iterator(); ++it, ++f) {
        REQUIRE(f < m.faces.size());
        const std::string fill = (*it)[1];
        for (int k = 0; k < 3; ++k) {
            const erd::LatticePoint p = m.vertices[m.faces[f][std::size_t(k)]];
            const double want = std::clamp(erd::corner_value(m, std::uint32_t(3 * f + std::size_t(k))) * 255.0 / m.maxval, 0.0, 255.0);
            INFO("face " << f << " corner " << k << " fill " << fill);
            if (fill[0] == '#') {
                REQUIRE((fill.size() == 7 || fill.size() == 4));  // #rrggbb or #rgb
                const long level = std::strtol(fill.substr(fill.size() == 4 ? 3 : 5).c_str(), nullptr, 16) * (fill.size() == 4 ? 17 : 1);
                CHECK(std::fabs(double(level) - want) <= 0.5 + erd::kFlatRange);
            } else {
                const std::string id = fill.substr(5, fill.size() - 6);
                REQUIRE(grads.count(id) == 1);
                used.insert(id);
                CHECK(std::fabs(paint(grads[id], p.x * unit / 2, p.y * unit / 2) - want) <= erd::kGradientTolerance);
            }
        }
        flat += fill[0] == '#';
    }
    CHECK(f == m.faces.size());
    CHECK(used.size() == grads.size());  // every gradient written is used (deduplicated, none stray)
    CHECK(flat < m.faces.size());
}

}  // namespace

TEST_CASE("render --vector: each face's gradient is its plane, for both models", "[vector]") {
    REQUIRE(binary_available());
    TempDir dir;
    REQUIRE(run_erd("synth -W 96 -H 64 -o " + sh_quote(dir.file("s.pgm"))).status == 0);
    for (const char* method : {"gpi", "erdgpi"}) {
        const bool erd_kind = std::string(method) == "erdgpi";
        const std::string model = dir.file(erd_kind ? "s.erd" : "s.model"), svg = dir.file(std::string(method) + ".svg");
        RunResult r = run_erd(std::string("generate -q -m ") + method + " -i " + sh_quote(dir.file("s.pgm")) + " -d 3 -o " + sh_quote(model));
        REQUIRE(r.status == 0);
        r = run_erd("render " + sh_quote(model) + " -o " + sh_quote(svg) + " --vector");
        INFO(r.err);
        REQUIRE(r.status == 0);
        erd::Model m;
        REQUIRE(erd::read_model(slurp(model), erd_kind ? erd::ModelFileKind::erd : erd::ModelFileKind::basic, &m).ok());
        const std::string text = slurp(svg);
        std::string lib;
        REQUIRE(erd::render_vector_svg(m, erd::VectorSvgOptions{}, &lib).ok());
        CHECK(lib == text);  // the CLI adds nothing
        CHECK(text.find("<image") == std::string::npos);
        CHECK(text.find("base64") == std::string::npos);
        // Basic models in pixel units, ERD models in half pixels; the viewBox is moved half a pixel.
        CHECK(text.find(erd_kind ? "viewBox=\"-1 -1 192 128\"" : "viewBox=\"-.5 -.5 96 64\"") != std::string::npos);
        CHECK(text.find("<use xlink:href=\"#_m\" shape-rendering=\"crispEdges\"/>") != std::string::npos);
        check_planes(m, text, erd_kind ? 2 : 1);
    }
}

TEST_CASE("render --vector: options that do not go with it are refused", "[vector]") {
    REQUIRE(binary_available());
    TempDir dir;
    REQUIRE(run_erd("synth -W 32 -H 24 -o " + sh_quote(dir.file("s.pgm"))).status == 0);
    REQUIRE(run_erd("generate -q -m gpi -i " + sh_quote(dir.file("s.pgm")) + " -d 5 -o " + sh_quote(dir.file("s.model"))).status == 0);
    const std::string base = "render " + sh_quote(dir.file("s.model")) + " ";
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.png")) + " --vector").status == 2);
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.svg")) + " --vector --over " + sh_quote(dir.file("s.pgm"))).status == 2);
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.svg")) + " --vector --seams blur").status == 2);
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.svg")) + " --seams crisp").status == 2);
    CHECK(!exists(dir.file("a.svg")));
    RunResult r = run_erd(base + "-o " + sh_quote(dir.file("c.svg")) + " --vector --seams crisp --crop 8,4,16,12 --scale 2");
    REQUIRE(r.status == 0);
    const std::string c = slurp(dir.file("c.svg"));
    CHECK(c.find("width=\"32\" height=\"24\" viewBox=\"7.5 3.5 16 12\" shape-rendering=\"crispEdges\"") != std::string::npos);
    CHECK(c.find("<use") == std::string::npos);
}
