// erd render --vector: every face's gradient is its plane (read back from the SVG text and
// evaluated at the face's corners), ids are unique and defined, flat faces are one colour, no
// raster is embedded; the CLI refuses the options that do not go with it. The browser measurement
// is tools/svg_browser_psnr.sh (a stage of tests/run_all.sh).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/output/vector_svg.h"
#include "tests/erd_run.h"

using namespace erd_test;

namespace {

struct Gradient {
    std::string tmpl;  // "_" gray, "_r", "_g", "_b"
    double x1, y1, x2, y2;
};

// What a renderer paints at (u, v) for the black-to-white (or black-to-channel) template gradient g.
double paint(const Gradient& g, double u, double v) {
    double dx = g.x2 - g.x1, dy = g.y2 - g.y1;
    return 255 * std::clamp(((u - g.x1) * dx + (v - g.y1) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
}

// Value of channel c of face f at its corner k, as the model holds it.
double model_value(const erd::Model& m, std::size_t f, int k, int c) {
    const std::size_t C = std::size_t(m.channels);
    if (m.kind == erd::ModelKind::erd) return m.corner_values[f * C + std::size_t(c)][std::size_t(k)];
    return m.values[std::size_t(m.faces[f][std::size_t(k)]) * C + std::size_t(c)];
}

// Checks every face of m against the SVG text, channel by channel: in the layer of channel c
// (the group "_m", or "_m0", "_m1", "_m2" in colour) path f is face f and its fill is the face's
// plane in that channel, painted only in that channel (colour: black to pure red, green or blue).
void check_planes(const erd::Model& m, const std::string& svg, double unit) {
    std::map<std::string, Gradient> grads;
    std::regex grad_re("<linearGradient id=\"(\\w+)\" xlink:href=\"#(_[rgb]?)\" x1=\"([-.0-9]+)\" y1=\"([-.0-9]+)\" x2=\"([-.0-9]+)\" y2=\"([-.0-9]+)\"/>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), grad_re); it != std::sregex_iterator(); ++it) {
        const auto& g = *it;
        INFO(g[0].str());
        REQUIRE(grads.count(g[1]) == 0);  // ids unique
        grads[g[1]] = {g[2], std::stod(g[3]), std::stod(g[4]), std::stod(g[5]), std::stod(g[6])};
    }
    const std::string kTemplates[3] = {"_r", "_g", "_b"};
    std::set<std::string> used;
    std::size_t flat = 0;
    for (int c = 0; c < m.channels; ++c) {
        const std::string group = m.channels == 1 ? "<g id=\"_m\">" : "<g id=\"_m" + std::to_string(c) + "\">";
        const std::size_t begin = svg.find(group), end = svg.find("</g></defs>", begin);
        REQUIRE(begin != std::string::npos);
        REQUIRE(end != std::string::npos);
        const std::string layer = svg.substr(begin, end - begin);
        // Faces off the model's hard jumps say visibility="visible" when it has any (they alone
        // show in the hidden anti-aliased layer).
        std::regex path_re("<path fill=\"([^\"]+)\"(?: visibility=\"visible\")? d=\"M[-.0-9 ]+z\"/>");
        std::size_t f = 0;
        for (auto it = std::sregex_iterator(layer.begin(), layer.end(), path_re); it != std::sregex_iterator(); ++it, ++f) {
            REQUIRE(f < m.faces.size());
            const std::string fill = (*it)[1];
            for (int k = 0; k < 3; ++k) {
                const erd::LatticePoint p = m.vertices[m.faces[f][std::size_t(k)]];
                const double want = std::clamp(model_value(m, f, k, c) * 255.0 / m.maxval, 0.0, 255.0);
                INFO("channel " << c << " face " << f << " corner " << k << " fill " << fill);
                if (fill[0] == '#') {
                    REQUIRE((fill.size() == 7 || fill.size() == 4));  // #rrggbb or #rgb
                    const int digits = fill.size() == 4 ? 1 : 2;
                    long level = 0;
                    for (int ch = 0; ch < 3; ++ch) {
                        const long l = std::strtol(fill.substr(std::size_t(1 + ch * digits), std::size_t(digits)).c_str(), nullptr, 16) *
                                       (digits == 1 ? 17 : 1);
                        if (m.channels == 1 || ch == c) level = l;
                        else CHECK(l == 0);  // the other channels black
                        if (m.channels == 1 && ch > 0) CHECK(l == level);
                    }
                    CHECK(std::fabs(double(level) - want) <= 0.5 + erd::kFlatRange);
                } else {
                    const std::string id = fill.substr(5, fill.size() - 6);
                    REQUIRE(grads.count(id) == 1);
                    CHECK(grads[id].tmpl == (m.channels == 1 ? "_" : kTemplates[c]));
                    used.insert(id);
                    CHECK(std::fabs(paint(grads[id], p.x * unit / 2, p.y * unit / 2) - want) <= erd::kGradientTolerance);
                }
            }
            flat += fill[0] == '#';
        }
        CHECK(f == m.faces.size());
    }
    CHECK(used.size() == grads.size());  // every gradient written is used (deduplicated, none stray)
    CHECK(flat < m.faces.size() * std::size_t(m.channels));
}

// A colour model made by hand from a gray one: red the gray values, green their negative, blue
// a ramp across the image plus a constant per face, so the three planes of a face point in
// different directions and ERD faces jump in blue too.
erd::Model colour_of(const erd::Model& g) {
    erd::Model m = g;
    m.channels = 3;
    m.values.clear();
    for (std::size_t v = 0; v < g.vertices.size(); ++v)
        for (double z : {g.values[v], double(g.maxval) - g.values[v], double(g.vertices[v].x % 97)}) m.values.push_back(z);
    m.corner_values.clear();
    for (std::size_t f = 0; f < g.corner_values.size(); ++f) {
        const auto& z = g.corner_values[f];
        m.corner_values.push_back(z);
        m.corner_values.push_back({g.maxval - z[0], g.maxval - z[1], g.maxval - z[2]});
        std::array<double, 3> b;
        for (int k = 0; k < 3; ++k) b[std::size_t(k)] = g.vertices[g.faces[f][std::size_t(k)]].x % 97 + double(f % 5) * 10;
        m.corner_values.push_back(b);
    }
    return m;
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

        // Colour: one layer per channel, the green and blue ones screened over red.
        const erd::Model colour = colour_of(m);
        std::string rgb;
        const erd::Status st = erd::render_vector_svg(colour, erd::VectorSvgOptions{}, &rgb);
        INFO(method << ": " << st.message);
        REQUIRE(st.ok());
        CHECK(rgb.find("<stop offset=\"1\" stop-color=\"#f00\"/>") != std::string::npos);
        std::size_t screens = 0;
        for (std::size_t at = rgb.find("<g style=\"mix-blend-mode:screen\">"); at != std::string::npos;
             at = rgb.find("<g style=\"mix-blend-mode:screen\">", at + 1))
            ++screens;
        CHECK(screens == 2);
        check_planes(colour, rgb, erd_kind ? 2 : 1);
        erd::Model two = colour;
        two.channels = 2;
        CHECK(!erd::render_vector_svg(two, erd::VectorSvgOptions{}, &rgb).ok());
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
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.svg")) + " --vector --ramp steps").status == 2);
    CHECK(run_erd(base + "-o " + sh_quote(dir.file("a.svg")) + " --ramp smooth").status == 2);
    CHECK(!exists(dir.file("a.svg")));
    RunResult r = run_erd(base + "-o " + sh_quote(dir.file("c.svg")) + " --vector --seams crisp --crop 8,4,16,12 --scale 2");
    REQUIRE(r.status == 0);
    const std::string c = slurp(dir.file("c.svg"));
    CHECK(c.find("width=\"32\" height=\"24\" viewBox=\"7.5 3.5 16 12\" shape-rendering=\"crispEdges\"") != std::string::npos);
    CHECK(c.find("<use") == std::string::npos);
}

namespace {

// The stops of template `id` in svg: (offset, level in `channel`'s component; -1 gray).
std::vector<std::pair<double, int>> template_stops(const std::string& svg, const std::string& id, int channel) {
    const std::size_t begin = svg.find("<linearGradient id=\"" + id + "\" gradientUnits=\"userSpaceOnUse\">");
    const std::size_t end = svg.find("</linearGradient>", begin);
    std::vector<std::pair<double, int>> stops;
    if (begin == std::string::npos || end == std::string::npos) return stops;
    const std::string t = svg.substr(begin, end - begin);
    std::regex stop_re("<stop(?: offset=\"([.0-9]+)\")?(?: stop-color=\"#([0-9a-f]+)\")?/>");
    for (auto it = std::sregex_iterator(t.begin(), t.end(), stop_re); it != std::sregex_iterator(); ++it) {
        const std::string off = (*it)[1], hex = (*it)[2];
        int level = 0;  // no stop-color: black
        if (!hex.empty()) {
            const int digits = hex.size() == 3 ? 1 : 2, k = channel < 0 ? 0 : channel;
            level = int(std::strtol(hex.substr(std::size_t(k * digits), std::size_t(digits)).c_str(), nullptr, 16)) * (digits == 1 ? 17 : 1);
        }
        stops.push_back({off.empty() ? 0.0 : std::stod(off), level});
    }
    return stops;
}

// What a renderer paints at gradient parameter t in [0, 1] (levels, unrounded): the colour
// interpolated between the stops around t; at a repeated offset the later stop holds from there on.
double paint_stops(const std::vector<std::pair<double, int>>& s, double t) {
    std::size_t k = 0;
    while (k + 1 < s.size() && s[k + 1].first <= t) ++k;
    if (k + 1 == s.size()) return s[k].second;
    const double w = (t - s[k].first) / (s[k + 1].first - s[k].first);
    return s[k].second + w * (s[k + 1].second - s[k].second);
}

}  // namespace

TEST_CASE("render --vector: the levels ramp paints each plane rounded to levels, smooth the plane", "[vector]") {
    // Every face's gradient runs its template from its plane's 0 point to its 255 point (the
    // test above), so a template that paints floor(255 t + 1/2) at t paints the rounded plane.
    REQUIRE(binary_available());
    TempDir dir;
    REQUIRE(run_erd("synth -W 32 -H 24 -o " + sh_quote(dir.file("s.pgm"))).status == 0);
    REQUIRE(run_erd("generate -q -m gpi -i " + sh_quote(dir.file("s.pgm")) + " -d 5 -o " + sh_quote(dir.file("s.model"))).status == 0);
    erd::Model m;
    REQUIRE(erd::read_model(slurp(dir.file("s.model")), erd::ModelFileKind::basic, &m).ok());
    const erd::Model colour = colour_of(m);
    for (const erd::Ramp ramp : {erd::Ramp::levels, erd::Ramp::smooth}) {
        erd::VectorSvgOptions o;
        o.ramp = ramp;
        std::string gray, rgb;
        REQUIRE(erd::render_vector_svg(m, o, &gray).ok());
        REQUIRE(erd::render_vector_svg(colour, o, &rgb).ok());
        const std::pair<const std::string*, int> cases[4] = {{&gray, -1}, {&rgb, 0}, {&rgb, 1}, {&rgb, 2}};
        const char* ids[4] = {"_", "_r", "_g", "_b"};
        for (int i = 0; i < 4; ++i) {
            const auto stops = template_stops(*cases[i].first, ids[i], cases[i].second);
            INFO("template " << ids[i] << (ramp == erd::Ramp::levels ? " levels" : " smooth"));
            REQUIRE(stops.size() == (ramp == erd::Ramp::levels ? 512u : 2u));
            for (int k = 0; k < 255 * 64; ++k) {
                const double z = k / 64.0 + 1.0 / 128;  // never a half level
                const double painted = paint_stops(stops, z / 255);
                if (ramp == erd::Ramp::levels) CHECK(painted == std::floor(z + 0.5));
                else CHECK(std::fabs(painted - z) < 1e-9);
            }
        }
    }
    // The CLI's default is levels; --ramp smooth gives the two-stop template.
    REQUIRE(run_erd("render " + sh_quote(dir.file("s.model")) + " -o " + sh_quote(dir.file("l.svg")) + " --vector").status == 0);
    REQUIRE(run_erd("render " + sh_quote(dir.file("s.model")) + " -o " + sh_quote(dir.file("s.svg")) + " --vector --ramp smooth").status == 0);
    CHECK(template_stops(slurp(dir.file("l.svg")), "_", -1).size() == 512);
    CHECK(template_stops(slurp(dir.file("s.svg")), "_", -1).size() == 2);
}

TEST_CASE("render --vector: colour model files become three screened layers", "[vector][colour]") {
    REQUIRE(binary_available());
    TempDir dir;
    // 3x3 pixels, a basic model and an ERD model (a jump in blue across the diagonal), by hand.
    const std::string basic = "erd-header 1\nchannels 3\nend\n255\n5\n0 0 255 0 0\n4 0 0 255 0\n0 4 0 0 255\n4 4 255 255 255\n"
                              "2 2 10 20 30\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n";
    const std::string erd = "erd-header 1\nchannels 3\nend\n255\n5\n0 0 10 11 12\n4 0 20 21 22\n0 4 30 31 32\n4 4 40 41 42\n"
                            "2 2 25 26 25\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n4\n4 0 25 26 10\n4 1 25 26 10\n4 2 25 26 40\n4 3 25 26 40\n";
    for (const auto& [name, text] : {std::pair<std::string, std::string>{"c.model", basic}, {"c.erd", erd}}) {
        INFO(name);
        spit(dir.file(name), text);
        RunResult r = run_erd("render " + sh_quote(dir.file(name)) + " -o " + sh_quote(dir.file("c.svg")) + " --vector");
        INFO(r.err);
        REQUIRE(r.status == 0);
        erd::Model m;
        REQUIRE(erd::read_model(text, name == "c.erd" ? erd::ModelFileKind::erd : erd::ModelFileKind::basic, &m).ok());
        REQUIRE(m.channels == 3);
        std::string lib;
        REQUIRE(erd::render_vector_svg(m, erd::VectorSvgOptions{}, &lib).ok());
        const std::string svg = slurp(dir.file("c.svg"));
        CHECK(svg == lib);
        check_planes(m, svg, 1);
    }
}
