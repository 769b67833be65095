// Edge kinds per edge (issue 44): the clean-step measure (anti-aliased drawings against blurred
// and aliased ones and photos), the pixels an edge governs, reconstruction of a model with edges
// of two kinds, kinds chosen by fit, the .erd and .erdz round trips, PSNR that never falls with
// density on an anti-aliased drawing, and mixed pictures (half photo, text over a photo).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/imaging/edge_kind.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/edge_kinds.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/model/reconstruct.h"
#include "kernel/predicates.h"
#include "tests/erd_check.h"
#include "tests/erd_run.h"
#include "tests/method_run_util.h"
#include "tests/thesis_cases.h"

using namespace erd;
using namespace erd_test;

namespace {

struct P2 {
    double x, y;
};

// A flat-colour drawing as an anti-aliasing renderer writes it: each pixel the coverage-weighted
// mean of the shapes over it (n x n sub-samples; n = 1 is an aliased drawing). Shapes in painting
// order over a gray ground: a disc, a rotated square, a triangle, a thin bar. offset_x places the
// drawing in a wider picture.
Image drawing(int w, int h, int n, int offset_x = 0, Image* into = nullptr) {
    Image im = into ? *into : Image(w, h, 255);
    const auto inside_convex = [](const std::vector<P2>& poly, double x, double y) {
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const P2 a = poly[i], b = poly[(i + 1) % poly.size()];
            if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) < 0) return false;
        }
        return true;
    };
    const double s = std::min(w, h);
    const double c = std::cos(0.5), si = std::sin(0.5);
    std::vector<P2> square;
    for (const P2 q : {P2{-1, -1}, P2{1, -1}, P2{1, 1}, P2{-1, 1}})
        square.push_back({0.62 * w + 0.17 * s * (c * q.x - si * q.y), 0.38 * h + 0.17 * s * (si * q.x + c * q.y)});
    const std::vector<P2> triangle = {{0.15 * w, 0.9 * h}, {0.55 * w, 0.93 * h}, {0.4 * w, 0.55 * h}};
    const std::vector<P2> bar = {{0.05 * w, 0.1 * h}, {0.95 * w, 0.13 * h}, {0.95 * w, 0.13 * h + 1.7}, {0.05 * w, 0.1 * h + 1.7}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double px = x + (i + 0.5) / n - 0.5, py = y + (j + 0.5) / n - 0.5;
                    double v = 90;
                    if (std::hypot(px - 0.3 * w, py - 0.4 * h) < 0.27 * s) v = 215;
                    if (inside_convex(square, px, py)) v = 140;
                    if (inside_convex(triangle, px, py)) v = 25;
                    if (inside_convex(bar, px, py)) v = 250;
                    sum += v;
                }
            im.at(x + offset_x, y) = std::uint16_t(std::lround(sum / (n * n)));
        }
    return im;
}

// passes of the binomial [1 2 1]/4 along x and y (edges a camera would blur), borders clamped.
Image blurred(const Image& im, int passes) {
    Image out = im;
    for (int p = 0; p < passes; ++p) {
        Image t = out;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) {
                const int l = std::max(x - 1, 0), r = std::min(x + 1, im.width - 1);
                t.at(x, y) = std::uint16_t((out.at(l, y) + 2 * out.at(x, y) + out.at(r, y) + 2) / 4);
            }
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) {
                const int u = std::max(y - 1, 0), d = std::min(y + 1, im.height - 1);
                out.at(x, y) = std::uint16_t((t.at(x, u) + 2 * t.at(x, y) + t.at(x, d) + 2) / 4);
            }
    }
    return out;
}



// ERDGPI's soft model of im at 2% with each edge's kind chosen by fit: edges of both kinds.
Model two_kind_model(const Image& im) {
    Model m = run_method("erdgpi", im, 2.0, EdgeChoice::soft).model;
    double db = 0;
    REQUIRE(choose_edge_kinds(im, &m, &db).ok());
    REQUIRE(!m.kind_exceptions.empty());
    return m;
}

std::vector<std::array<std::uint32_t, 2>> discontinuities(const Model& m) {
    ModelTopology topo;
    REQUIRE(build_topology(m, &topo).ok());
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h)
        if (topo.twin[h] != kNoHalfEdge && h < topo.twin[h] && is_discontinuity(m, topo, h)) {
            const std::uint32_t a = m.faces[h / 3][h % 3], b = m.faces[h / 3][(h + 1) % 3];
            out.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(out.begin(), out.end());
    return out;
}

// The segment a-b meets the closed square [lo, hi]^2 (integer coordinates), by another road than
// for_each_governed_pixel: an end inside, or a crossing with one of the square's sides.
bool segment_meets_square(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t x0, std::int64_t y0,
                          std::int64_t x1, std::int64_t y1) {
    const auto in = [&](std::int64_t x, std::int64_t y) { return x >= x0 && x <= x1 && y >= y0 && y <= y1; };
    if (in(ax, ay) || in(bx, by)) return true;
    const auto orient = [](std::int64_t px, std::int64_t py, std::int64_t qx, std::int64_t qy, std::int64_t rx, std::int64_t ry) {
        const std::int64_t v = (qx - px) * (ry - py) - (qy - py) * (rx - px);
        return (v > 0) - (v < 0);
    };
    const auto on = [](std::int64_t p, std::int64_t q, std::int64_t r) { return std::min(p, q) <= r && r <= std::max(p, q); };
    const auto cross = [&](std::int64_t cx, std::int64_t cy, std::int64_t dx, std::int64_t dy) {
        const int o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
        const int o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
        if (o1 != o2 && o3 != o4) return true;
        return (o1 == 0 && on(ax, bx, cx) && on(ay, by, cy)) || (o2 == 0 && on(ax, bx, dx) && on(ay, by, dy)) ||
               (o3 == 0 && on(cx, dx, ax) && on(cy, dy, ay)) || (o4 == 0 && on(cx, dx, bx) && on(cy, dy, by));
    };
    return cross(x0, y0, x1, y0) || cross(x1, y0, x1, y1) || cross(x1, y1, x0, y1) || cross(x0, y1, x0, y0);
}

}  // namespace

TEST_CASE("edge kinds: clean steps tell anti-aliased drawings from blurred, aliased ones and photos", "[edgekinds]") {
    const Image aa = drawing(160, 120, 16);
    const EdgeKindStats a = measure_edge_kind(aa);
    CHECK(a.is_stepped());
    CHECK(!a.is_hard());
    CHECK(a.clean_fraction() > 0.3);
    for (int passes : {1, 2}) {
        INFO("blur passes " << passes);
        const EdgeKindStats b = measure_edge_kind(blurred(aa, passes));
        CHECK(!b.is_stepped());
        CHECK(!b.is_hard());
    }
    const EdgeKindStats h = measure_edge_kind(drawing(160, 120, 1));
    CHECK(h.is_hard());
    CHECK(!h.is_stepped());  // hard first: the kind of issue 15 decides
    for (const char* name : {"lena", "peppers", "bull"}) {
        Image photo;
        if (!test::read_thesis_image(name, &photo)) return;
        INFO(name);
        const EdgeKindStats p = measure_edge_kind(photo);
        CHECK(!p.is_stepped());
        CHECK(p.clean_fraction() < 0.06);  // measured 0.024, 0.036, 0.056
    }
}

TEST_CASE("edge kinds: an edge governs exactly the pixels whose sub-sample square it meets", "[edgekinds]") {
    std::mt19937 rng(44);
    const int W = 13, H = 11;
    std::uniform_int_distribution<int> X(0, 2 * W - 2), Y(0, 2 * H - 2);
    for (int k = 0; k < 400; ++k) {
        const LatticePoint u{X(rng), Y(rng)}, w = k % 7 ? LatticePoint{X(rng), Y(rng)} : LatticePoint{u.x, Y(rng)};
        std::set<std::pair<int, int>> got, want;
        for_each_governed_pixel(u, w, W, H, [&](int x, int y) { CHECK(got.insert({x, y}).second); });
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                if (segment_meets_square(4 * u.x, 4 * u.y, 4 * w.x, 4 * w.y, 8 * x - 3, 8 * y - 3, 8 * x + 3, 8 * y + 3)) want.insert({x, y});
        INFO("segment (" << u.x << ", " << u.y << ") - (" << w.x << ", " << w.y << ")");
        CHECK(got == want);
    }
}

TEST_CASE("edge kinds: the pixels along an edge of the other kind are evaluated as that kind says", "[edgekinds]") {
    const Image im = drawing(96, 72, 16);
    Model m = run_method("erdgpi", im, 3.0, EdgeChoice::soft).model;
    REQUIRE(m.edges == EdgeKind::soft);
    const auto disc = discontinuities(m);
    REQUIRE(disc.size() > 10);
    Image point, super;
    REQUIRE(reconstruct(m, false, &point).ok());
    REQUIRE(reconstruct(m, true, &super).ok());
    for (EdgeKind base : {EdgeKind::soft, EdgeKind::hard}) {
        INFO("model kind " << (base == EdgeKind::hard ? "hard" : "soft"));
        m.edges = base;
        m.kind_exceptions.clear();
        for (std::size_t i = 0; i < disc.size(); i += 3) m.kind_exceptions.push_back(disc[i]);
        ModelTopology topo;
        REQUIRE(build_topology(m, &topo).ok());
        REQUIRE(check_kind_exceptions(m, topo).ok());
        const std::vector<std::uint8_t> governed = exception_pixels(m);
        std::size_t n = 0;
        for (std::uint8_t g : governed) n += g;
        CHECK(n > 0);
        CHECK(n < governed.size() / 2);
        Image mixed;
        REQUIRE(reconstruct(m, supersampled(m), &mixed).ok());
        const Image& own = base == EdgeKind::soft ? super : point;
        const Image& other = base == EdgeKind::soft ? point : super;
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < governed.size(); ++i) wrong += mixed.samples[i] != (governed[i] ? other : own).samples[i];
        CHECK(wrong == 0);
        // The evaluation asked for at every pixel where the edges' kinds are that one anyway.
        Image all;
        REQUIRE(reconstruct(m, base == EdgeKind::hard, &all).ok());
        CHECK(all.samples == (base == EdgeKind::hard ? super : point).samples);
    }
    // A listed edge that is no discontinuity, or out of order, is refused.
    m.kind_exceptions = {{0, 1}};
    ModelTopology topo;
    REQUIRE(build_topology(m, &topo).ok());
    if (!std::binary_search(disc.begin(), disc.end(), m.kind_exceptions[0]))
        CHECK(check_kind_exceptions(m, topo).message.find("is not a discontinuity") != std::string::npos);
    m.kind_exceptions = {disc[1], disc[0]};
    CHECK(check_kind_exceptions(m, topo).message.find("increasing order") != std::string::npos);
}

TEST_CASE("edge kinds: chosen by fit, each edge the kind that fits the pixels along it", "[edgekinds]") {
    const Image im = drawing(96, 72, 16);
    Model m = run_method("erdgpi", im, 2.0, EdgeChoice::soft).model;
    Image point, super;
    REQUIRE(reconstruct(m, false, &point).ok());
    REQUIRE(reconstruct(m, true, &super).ok());
    const double p = psnr(im, point), s = psnr(im, super);
    double chosen = 0;
    REQUIRE(choose_edge_kinds(im, &m, &chosen).ok());
    CHECK(!m.kind_exceptions.empty());
    CHECK(m.edges == (p > s ? EdgeKind::hard : EdgeKind::soft));
    ModelTopology topo;
    REQUIRE(build_topology(m, &topo).ok());
    CHECK(check_kind_exceptions(m, topo).ok());
    CHECK(chosen == own_psnr(im, m));  // what it reports is the model's own reconstruction
    CHECK(chosen > std::max(p, s));   // measured: both kinds somewhere
}

TEST_CASE("edge kinds: .erd round trip and the header keys hard-edges / soft-edges", "[edgekinds][model_io]") {
    const Image im = drawing(96, 72, 16);
    const Model m = two_kind_model(im);
    for (EdgeKind base : {m.edges, m.edges == EdgeKind::hard ? EdgeKind::soft : EdgeKind::hard}) {
        Model k = m;
        k.edges = base;
        const std::string key = base == EdgeKind::hard ? "soft-edges" : "hard-edges";
        std::string text;
        REQUIRE(write_model(k, &text).ok());
        CHECK(text.find("erd-header 1\nedges " + std::string(base == EdgeKind::hard ? "hard" : "soft") + "\n" + key + " " +
                        std::to_string(k.kind_exceptions.size()) + "\nend\n") == 0);
        Model back;
        REQUIRE(read_model(text, ModelFileKind::erd, &back).ok());
        CHECK(back.edges == base);
        CHECK(back.kind_exceptions == k.kind_exceptions);
        Image a, b;
        REQUIRE(reconstruct(k, supersampled(k), &a).ok());
        REQUIRE(reconstruct(back, supersampled(back), &b).ok());
        CHECK(a.samples == b.samples);
        std::string again;
        REQUIRE(write_model(back, &again).ok());
        CHECK(again == text);
    }
    // The grammar's refusals, each one line naming the problem.
    std::string text;
    REQUIRE(write_model(m, &text).ok());
    const auto read_error = [](const std::string& t, ModelFileKind kind = ModelFileKind::erd) {
        Model x;
        const Status st = read_model(t, kind, &x);
        return st.ok() ? std::string("OK") : st.message;
    };
    const std::string key = m.edges == EdgeKind::hard ? "soft-edges" : "hard-edges", other = m.edges == EdgeKind::hard ? "hard-edges" : "soft-edges";
    const std::size_t body = text.find("end\n") + 4;
    const std::string n = std::to_string(m.kind_exceptions.size());
    const auto with_header = [&](const std::string& header) { return header + text.substr(body); };
    CHECK(read_error(with_header("erd-header 1\nedges " + std::string(m.edges == EdgeKind::hard ? "hard" : "soft") + "\n" + other + " " + n + "\nend\n")).find(
              "lists edges of the kind 'edges' gives them already") != std::string::npos);
    CHECK(read_error(with_header("erd-header 1\n" + key + " " + n + "\nsoft-edges 1\nend\n")).find("only one of them, once") != std::string::npos);
    // One edge line more than the count: it is what follows the last one.
    CHECK(read_error(with_header("erd-header 1\nedges " + std::string(m.edges == EdgeKind::hard ? "hard" : "soft") + "\n" + key + " " +
                                 std::to_string(m.kind_exceptions.size() - 1) + "\nend\n"))
              .find("after the last edge line") != std::string::npos);
    // An edge listed twice, one that is no discontinuity, an index out of range.
    const std::string first = std::to_string(m.kind_exceptions[0][0]) + " " + std::to_string(m.kind_exceptions[0][1]) + "\n";
    const std::string header = text.substr(0, body);
    std::string grown = header;
    grown.replace(grown.find(key + " " + n), key.size() + 1 + n.size(), key + " " + std::to_string(m.kind_exceptions.size() + 1));
    CHECK(read_error(grown + text.substr(body) + first).find("is listed twice") != std::string::npos);
    const auto disc = discontinuities(m);
    std::array<std::uint32_t, 2> plain{0, 0};
    for (const auto& f : m.faces) {
        const std::array<std::uint32_t, 2> e{std::min(f[0], f[1]), std::max(f[0], f[1])};
        if (!std::binary_search(disc.begin(), disc.end(), e)) { plain = e; break; }
    }
    CHECK(read_error(grown + text.substr(body) + std::to_string(plain[0]) + " " + std::to_string(plain[1]) + "\n")
              .find("is not a discontinuity of the model") != std::string::npos);
    CHECK(read_error(grown + text.substr(body) + "0 999999\n").find("out of range") != std::string::npos);
    // .model files have no edges to give a kind.
    CHECK(read_error("erd-header 1\nhard-edges 0\nend\n255\n4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n2\n0 1 2\n1 3 2\n", ModelFileKind::basic) ==
          "line 2: header key 'hard-edges' is for .erd files only");
    // A model with edges of one kind is written as before (no key, no edge lines).
    Model one = m;
    one.kind_exceptions.clear();
    std::string plain_text;
    REQUIRE(write_model(one, &plain_text).ok());
    CHECK(plain_text.find("-edges") == std::string::npos);
}

TEST_CASE("edge kinds: .erdz keeps them (version 4), models of one kind stay version 3", "[edgekinds][erdz]") {
    const Image im = drawing(96, 72, 16);
    const Model m = two_kind_model(im);
    const auto coordinates = [](const Model& x) {
        std::set<std::pair<std::uint64_t, std::uint64_t>> s;
        for (const auto& e : x.kind_exceptions) s.insert(std::minmax(test::key(x.vertices[e[0]]), test::key(x.vertices[e[1]])));
        return s;
    };
    for (double step : {1.0 / 256, 1.0, 4.0}) {
        INFO("step " << step);
        ErdzOptions o;
        o.step = step;
        std::string bytes;
        ErdzInfo info;
        REQUIRE(encode_erdz(m, o, &bytes, &info).ok());
        CHECK(int(std::uint8_t(bytes[4])) == 4);
        CHECK(info.kind_bits > 0);
        Model d;
        ErdzInfo dinfo;
        REQUIRE(decode_erdz(bytes, &d, &dinfo).ok());
        CHECK(d.edges == m.edges);
        CHECK(dinfo.other_kind_edges == d.kind_exceptions.size());
        ModelTopology topo;
        REQUIRE(build_topology(d, &topo).ok());
        CHECK(check_kind_exceptions(d, topo).ok());
        // Every decoded one was listed; at the finest step every listed one survives.
        const auto want = coordinates(m), got = coordinates(d);
        CHECK(std::includes(want.begin(), want.end(), got.begin(), got.end()));
        if (step < 1) CHECK(got == want);
        else CHECK(got.size() * 2 > want.size());
        for (std::size_t cut = bytes.size() - 3; cut < bytes.size(); ++cut) CHECK(!decode_erdz(bytes.substr(0, cut), &d).ok());
    }
    Model one = m;
    one.kind_exceptions.clear();
    std::string bytes;
    REQUIRE(encode_erdz(one, ErdzOptions(), &bytes).ok());
    CHECK(int(std::uint8_t(bytes[4])) == 3);
}

TEST_CASE("edge kinds: more points never cost quality on an anti-aliased drawing", "[edgekinds]") {
    const Image im = drawing(128, 96, 16);
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    const std::vector<double> densities = sanitized ? std::vector<double>{1, 2} : std::vector<double>{0.5, 1, 2, 4};
    double last[2] = {0, 0};
    for (double d : densities) {
        INFO("density " << d);
        const double gpi = own_psnr(im, run_method("gpi", im, d).model), ed = own_psnr(im, run_method("ed", im, d).model);
        const GenerateResult g = run_method("erdgpi", im, d), e = run_method("erded", im, d);
        CHECK(g.stats.erd.stepped);
        test::check_model(g.model);
        const double erdgpi = own_psnr(im, g.model), erded = own_psnr(im, e.model);
        CHECK(erdgpi >= gpi - 0.2);
        CHECK(erded >= ed);
        CHECK(erdgpi >= last[0] - 0.05);
        CHECK(erded >= last[1] - 0.05);
        last[0] = erdgpi;
        last[1] = erded;
    }
}

TEST_CASE("edge kinds: a picture half photo, half drawing gets the better of both", "[edgekinds]") {
    // Left: a smooth, textured "photo" (blurred noise over blurred shapes); right: the anti-aliased
    // drawing.
    const int W = 192, H = 96;
    Image photo = blurred(drawing(W / 2, H, 4), 3);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0, 6);
    for (auto& v : photo.samples) v = std::uint16_t(std::clamp(double(v) + noise(rng), 0.0, 255.0));
    photo = blurred(photo, 1);
    Image mixed(W, H, 255);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W / 2; ++x) mixed.at(x, y) = photo.at(x, y);
    mixed = drawing(W / 2, H, 16, W / 2, &mixed);
    CHECK(measure_edge_kind(mixed).is_stepped());
    for (double d : {1.0, 2.0}) {
        INFO("density " << d);
        const GenerateResult r = run_method("erdgpi", mixed, d);
        REQUIRE(r.stats.erd.tried);
        const double best = own_psnr(mixed, r.model);
        CHECK(best == r.stats.erd.tried_psnr[r.stats.erd.tried_choice]);
        CHECK(best >= own_psnr(mixed, run_method("erdgpi", mixed, d, EdgeChoice::soft).model));
        CHECK(best >= own_psnr(mixed, run_method("erdgpi", mixed, d, EdgeChoice::hard).model));
        CHECK(best >= own_psnr(mixed, run_method("gpi", mixed, d).model) + 3);
    }
}

TEST_CASE("edge kinds: the graphics of make eval, text over a photo and half photo, rendered by rsvg-convert", "[edgekinds][graphics]") {
    if (!need_binary()) return;
    const char* src = std::getenv("ERD_SRC");
    const std::string root = absolute(src && *src ? src : ".");
    if (!have_input(exists(root + "/tools/graphics_svg.py"), "tools/graphics_svg.py not found (run from the repository or set ERD_SRC)")) return;
    if (!have_input(run_shell("command -v rsvg-convert").status == 0, "rsvg-convert missing (make graphics-deps)")) return;
    const char* images = std::getenv("ERD_IMAGES");
    TempDir dir;
    RunResult r = run_shell("python3 " + sh_quote(root + "/tools/graphics_svg.py") + " " + sh_quote(dir.file("svg")) + " " +
                            sh_quote(absolute(images && *images ? images : "../shared/images")));
    if (!have_input(r.status == 0, "tools/graphics_svg.py failed: " + r.err)) return;
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    for (const char* name : {"mixed-text", "mixed-half", "flag-disc"}) {
        if (sanitized && std::string(name) != "mixed-text") continue;
        INFO(name);
        const std::string png = dir.file(std::string(name) + ".png");
        REQUIRE(run_shell("rsvg-convert " + sh_quote(dir.file("svg/" + std::string(name) + ".svg")) + " -o " + sh_quote(png)).status == 0);
        const auto psnr_at = [&](const char* method, double d, std::string* info = nullptr) {
            const std::string model = dir.file(std::string(name) + "." + method + (method[0] == 'e' && method[1] == 'r' ? ".erd" : ".model"));
            RunResult g = run_erd(std::string("generate -q -x 2 -m ") + method + " -i " + sh_quote(png) + " -d " + std::to_string(d) +
                                  " -o " + sh_quote(model) + " --stats " + sh_quote(model + ".json"));
            REQUIRE(g.status == 0);
            if (info) *info = slurp(model + ".json");
            RunResult p = run_erd("reconstruct -q " + sh_quote(model) + " -o - | " + sh_quote(erd_bin()) + " psnr " + sh_quote(png) + " -");
            REQUIRE(p.status == 0);
            return p.out.find("inf") == 0 ? 1e9 : std::stod(p.out);
        };
        double last = 0;
        for (double d : sanitized ? std::vector<double>{1} : std::vector<double>{1, 2}) {
            INFO("density " << d);
            std::string stats;
            const double erdgpi = psnr_at("erdgpi", d, &stats);
            CHECK(erdgpi >= psnr_at("gpi", d) - 0.2);
            CHECK(psnr_at("erded", d) >= psnr_at("ed", d));
            CHECK(erdgpi >= last - 0.05);
            last = erdgpi;
            // Text over a photo: edges of both kinds in one model.
            if (std::string(name) == "mixed-text") CHECK(stats.find("\"other_kind_edges\":0,") == std::string::npos);
        }
    }
}
