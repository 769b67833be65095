// Colour models (Model::channels 3) downstream of the methods: .model/.erd files with the
// "channels 3" header, hostile colour files, reconstruction per channel, export and render
// colours, and the API's colour views. The colour models are made by hand from gray ones (each
// channel the gray values plus an offset), so these tests need no colour method.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/synth.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/model/reconstruct.h"
#include "algorithms/output/export.h"
#include "algorithms/output/render.h"
#include "api/erd.h"
#include "tests/erd_check.h"
#include "tests/erd_run.h"
#include "tests/synth_util.h"

using namespace erd;
using erd::test::check_model;

namespace {

// Channel c of the colour model is the gray model's values plus offset[c], clamped to
// [0, maxval] (so a basic model's integer values stay integers in range); an ERD model's vertex
// values are then the means of their wedges, as the methods and the reader make them.
Model colourise(const Model& g, const double offset[3]) {
    Model m = g;
    m.channels = 3;
    const auto shift = [&](double v, int c) { return std::min(double(g.maxval), std::max(0.0, v + offset[c])); };
    m.values.clear();
    for (double v : g.values)
        for (int c = 0; c < 3; ++c) m.values.push_back(shift(v, c));
    m.corner_values.clear();
    for (const auto& cv : g.corner_values)
        for (int c = 0; c < 3; ++c) m.corner_values.push_back({shift(cv[0], c), shift(cv[1], c), shift(cv[2], c)});
    if (m.kind == ModelKind::erd) {
        ModelTopology topo;
        REQUIRE(build_topology(m, &topo).ok());
        for (std::uint32_t v = 0; v < m.vertices.size(); ++v)
            for (int c = 0; c < 3; ++c) m.values[v * 3 + std::size_t(c)] = vertex_wedges(m, topo, v, c).mean;
    }
    return m;
}

// Channel c of a colour model as a gray model.
Model channel_model(const Model& m, int c) {
    Model g = m;
    g.channels = 1;
    g.values.clear();
    for (std::size_t v = 0; v < m.vertices.size(); ++v) g.values.push_back(m.values[v * 3 + std::size_t(c)]);
    g.corner_values.clear();
    if (m.kind == ModelKind::erd)
        for (std::size_t f = 0; f < m.faces.size(); ++f) g.corner_values.push_back(m.corner_values[f * 3 + std::size_t(c)]);
    return g;
}

// Gray models of a small synthetic scene: basic (GPI) and ERD (ERDGPI).
Model gray_model(const char* method, int points) {
    const Image im = erd_test::synth_image(48, 40);
    GenerateOptions o;
    o.points = points;
    o.density_given = false;
    GenerateResult r;
    const MethodInfo* mi = find_method(method);
    REQUIRE(mi);
    REQUIRE(mi->run(im, o, &r).ok());
    return r.model;
}

const double kOffsets[3] = {-17.0, 0.0, 23.0};

std::string read_error(const std::string& text, ModelFileKind kind) {
    Model m;
    const Status st = read_model(text, kind, &m);
    if (st.ok()) return "OK";
    CHECK(st.code == Code::input);
    return st.message;
}

// A 3x3 colour .erd: centre vertex (2, 2), four faces, wedge lines as given.
std::string colour_erd(const std::string& vertex4, const std::string& wedges) {
    return "erd-header 1\nchannels 3\nend\n255\n5\n0 0 10 11 12\n4 0 20 21 22\n0 4 30 31 32\n4 4 40 41 42\n" + vertex4 +
           "\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n" + wedges;
}

}  // namespace

TEST_CASE("colour model files: the header, write -> read -> write identical", "[colour]") {
    for (const char* method : {"gpi", "erdgpi"}) {
        INFO(method);
        const Model m = colourise(gray_model(method, 60), kOffsets);
        std::string a, b;
        REQUIRE(write_model(m, &a).ok());
        CHECK(a.rfind("erd-header 1\nchannels 3\n", 0) == 0);
        Model r;
        const ModelFileKind kind = m.kind == ModelKind::erd ? ModelFileKind::erd : ModelFileKind::basic;
        REQUIRE(read_model(a, kind, &r).ok());
        CHECK(r.channels == 3);
        CHECK(r.vertices == m.vertices);
        CHECK(r.faces == m.faces);
        CHECK(r.values == m.values);
        CHECK(r.corner_values == m.corner_values);
        REQUIRE(write_model(r, &b).ok());
        CHECK(a == b);
        // Kind told from the content as for gray files.
        Model u;
        REQUIRE(read_model(a, ModelFileKind::unknown, &u).ok());
        CHECK(u.kind == m.kind);
        if (m.kind == ModelKind::erd) {
            check_model(r);
            CHECK_FALSE(r.constraints.empty());
        }
        // The gray model's file is untouched by the colour code: no header.
        std::string g;
        REQUIRE(write_model(gray_model(method, 60), &g).ok());
        CHECK(g.find("channels") == std::string::npos);
    }
    // channels and edges together, and channels alone.
    Model h = colourise(gray_model("erdgpi", 40), kOffsets);
    h.edges = EdgeKind::soft;
    std::string soft;
    REQUIRE(write_model(h, &soft).ok());
    CHECK(soft.rfind("erd-header 1\nchannels 3\nend\n", 0) == 0);
    h.edges = EdgeKind::hard;
    std::string t;
    REQUIRE(write_model(h, &t).ok());
    CHECK(t.rfind("erd-header 1\nchannels 3\nedges hard\nend\n", 0) == 0);
    Model r;
    REQUIRE(read_model(t, ModelFileKind::erd, &r).ok());
    CHECK(r.edges == EdgeKind::hard);
    CHECK(r.channels == 3);
}

TEST_CASE("colour .erd: wedge lines carry three values; a jump in one channel is a discontinuity", "[colour]") {
    // Vertex 4's wedges differ in the blue channel only, across the diagonal 0-4-3.
    const std::string text = colour_erd("2 2 25 26 27", "4\n4 0 25 26 10\n4 1 25 26 10\n4 2 25 26 40\n4 3 25 26 40\n");
    Model m;
    REQUIRE(read_model(text, ModelFileKind::erd, &m).ok());
    CHECK(m.channels == 3);
    REQUIRE(m.corner_values.size() == 4 * 3);
    CHECK(m.values[4 * 3 + 0] == 25);
    CHECK(m.values[4 * 3 + 2] == 25);  // the mean of the blue wedges 10 and 40
    CHECK(m.constraints.size() == 2);
    check_model(m);
    std::string a, b;
    REQUIRE(write_model(m, &a).ok());
    Model r;
    REQUIRE(read_model(a, ModelFileKind::erd, &r).ok());
    REQUIRE(write_model(r, &b).ok());
    CHECK(a == b);
    // Fewer wedge lines than faces: a face between two listed faces that agree in every channel
    // takes their values (faces 0 and 2 give face 1 its values).
    Model full, p;
    REQUIRE(read_model(colour_erd("2 2 0 0 0", "4\n4 0 25 26 10\n4 1 25 26 10\n4 2 25 26 10\n4 3 25 26 40\n"), ModelFileKind::erd, &full).ok());
    REQUIRE(read_model(colour_erd("2 2 0 0 0", "3\n4 0 25 26 10\n4 2 25 26 10\n4 3 25 26 40\n"), ModelFileKind::erd, &p).ok());
    CHECK(p.corner_values == full.corner_values);
    // ... but not when they differ in one channel only.
    CHECK(read_error(colour_erd("2 2 0 0 0", "3\n4 0 25 26 10\n4 2 25 27 10\n4 3 25 26 40\n"), ModelFileKind::erd) ==
          "the wedge of face 1 at vertex 4 is undetermined (give a wedge line for every face of a vertex with several wedges)");
}

TEST_CASE("hostile colour model files: one clear message each", "[colour]") {
    const std::string good = colour_erd("2 2 25 26 27", "0\n");
    CHECK(read_error(good, ModelFileKind::erd) == "OK");
    const auto with_header = [](const std::string& header) {
        return header + "255\n4\n0 0 1 2 3\n1 0 1 2 3\n0 1 1 2 3\n1 1 1 2 3\n2\n0 1 3\n0 3 2\n";
    };
    CHECK(read_error(with_header("erd-header 1\nchannels 3\nend\n"), ModelFileKind::basic) == "OK");
    CHECK(read_error(with_header("erd-header 1\nchannels 2\nend\n"), ModelFileKind::basic) ==
          "line 2: channels must be 1 (gray) or 3 (RGB), found '2'");
    CHECK(read_error(with_header("erd-header 1\nchannels 4\nend\n"), ModelFileKind::basic) ==
          "line 2: channels must be 1 (gray) or 3 (RGB), found '4'");
    CHECK(read_error(with_header("erd-header 1\nchannels rgb\nend\n"), ModelFileKind::basic) ==
          "line 2: channels must be 1 (gray) or 3 (RGB), found 'rgb'");
    CHECK(read_error(with_header("erd-header 1\nchannels 3\nchannels 3\nend\n"), ModelFileKind::basic) ==
          "line 3: header key 'channels' given twice");
    CHECK(read_error("erd-header 1\nchannels", ModelFileKind::basic) == "file ends early: expected the value of 'channels' (1 or 3)");
    // A vertex line with two values, or four.
    CHECK(read_error(colour_erd("2 2 25 26", "0\n"), ModelFileKind::erd) ==
          "line 10: vertex 4 has 2 values on its line, expected 3 (the header says channels 3)");
    CHECK(read_error(colour_erd("2 2 25 26 27 28", "0\n"), ModelFileKind::erd) ==
          "line 10: vertex 4 has more than 3 values on its line, expected 3 (the header says channels 3)");
    // A gray body under a colour header: too short for its counts, or its first vertex line says so.
    CHECK(read_error("erd-header 1\nchannels 3\nend\n255\n4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n2\n0 1 3\n0 3 2\n", ModelFileKind::basic) ==
          "line 5: vertex count 4 is more than the rest of the file holds (the file ends early or the count is wrong)");
    CHECK(read_error("erd-header 1\nchannels 3\nend\n255\n4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n2\n0 1 3\n0 3 2\n# a comment\n",
                     ModelFileKind::basic) == "line 6: vertex 0 has 1 values on its line, expected 3 (the header says channels 3)");
    // Wedge lines.
    CHECK(read_error(colour_erd("2 2 25 26 27", "2\n4 0 25 26\n4 1 25 26 27\n"), ModelFileKind::erd) ==
          "line 17: wedge line 0 has 2 values on its line, expected 3 (the header says channels 3)");
    CHECK(read_error(colour_erd("2 2 25 26 27", "1\n4 0 25 26\n"), ModelFileKind::erd) ==
          "file ends early: expected blue wedge value of wedge line 0");
    CHECK(read_error(colour_erd("2 2 25 26 27", "1\n4 0 25 26 27 1\n"), ModelFileKind::erd) ==
          "line 17: wedge line 0 has more than 3 values on its line, expected 3 (the header says channels 3)");
    CHECK(read_error(colour_erd("2 2 25 26 27", "1\n4 0 25 x 27\n"), ModelFileKind::erd) ==
          "line 17: expected green wedge value of wedge line 0, found 'x'");
    CHECK(read_error(colour_erd("2 2 25 26 nan", "0\n"), ModelFileKind::erd) ==
          "line 10: blue value of vertex 4 'nan' is not a finite number");
    CHECK(read_error(colour_erd("2 2 25 26 27", "2\n4 0 1 2 3\n4 0 1 2 4\n"), ModelFileKind::erd) ==
          "line 18: wedge line 1: conflicting values for vertex 4 in face 0");
    // A colour file given to a consumer of gray models.
    Model m;
    REQUIRE(read_model(good, ModelFileKind::erd, &m).ok());
    const Status st = require_gray(m, "the vector picture");
    CHECK(st.code == Code::input);
    CHECK(st.message == "a colour model (channels 3): the vector picture handles gray models only");
    Model g;
    REQUIRE(read_model("255\n4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n2\n0 1 3\n0 3 2\n", ModelFileKind::basic, &g).ok());
    CHECK(require_gray(g, "x").ok());
}

TEST_CASE("colour reconstruction: every channel is the gray reconstruction of its values", "[colour]") {
    for (const char* method : {"gpi", "erdgpi"}) {
        const Model gray = gray_model(method, 80);
        const Model m = colourise(gray, kOffsets);
        for (bool aa : {false, true}) {
            INFO(method << " supersample " << aa);
            Image im;
            REQUIRE(reconstruct(m, aa, &im).ok());
            REQUIRE(im.channels == 3);
            REQUIRE(im.samples.size() == im.pixels() * 3);
            for (int c = 0; c < 3; ++c) {
                Image want;
                REQUIRE(reconstruct(channel_model(m, c), aa, &want).ok());
                CHECK(channel_plane(im, c).samples == want.samples);
            }
        }
        // The basic model's integer vertex values come back at the vertices, in every channel.
        if (m.kind == ModelKind::basic) {
            Image im;
            REQUIRE(reconstruct(m, false, &im).ok());
            int checked = 0;
            for (std::size_t v = 0; v < m.vertices.size(); ++v)
                for (int c = 0; c < 3; ++c, ++checked)
                    CHECK(im.at(m.vertices[v].x / 2, m.vertices[v].y / 2, c) == m.values[v * 3 + std::size_t(c)]);
            CHECK(checked == 3 * 80);
        }
    }
    // A model whose three channels are equal reconstructs to three copies of the gray image.
    const Model gray = gray_model("erdgpi", 50);
    const double zero[3] = {0.0, 0.0, 0.0};
    Image g, rgb;
    REQUIRE(reconstruct(gray, true, &g).ok());
    REQUIRE(reconstruct(colourise(gray, zero), true, &rgb).ok());
    for (int c = 0; c < 3; ++c) CHECK(channel_plane(rgb, c).samples == g.samples);
    // Inconsistent sizes are refused, not read out of bounds.
    Model bad = colourise(gray, zero);
    bad.values.pop_back();
    CHECK(reconstruct(bad, true, &rgb).code == Code::input);
    bad = colourise(gray, zero);
    bad.channels = 2;
    CHECK(reconstruct(bad, true, &rgb).code == Code::input);
}

TEST_CASE("colour export: PLY red green blue, OBJ v x y z r g b, STL the luma surface", "[colour]") {
    // 2x2 basic model: values (R, G, B) = (255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255).
    Model m;
    REQUIRE(read_model("erd-header 1\nchannels 3\nend\n255\n4\n0 0 255 0 0\n1 0 0 255 0\n0 1 0 0 255\n1 1 255 255 255\n2\n0 1 3\n0 3 2\n",
                       ModelFileKind::basic, &m)
                .ok());
    ExportOptions o;
    o.zscale = 1.0;
    std::string ply, obj, stl;
    o.format = MeshFormat::ply;
    REQUIRE(export_mesh(m, o, &ply).ok());
    CHECK(ply.find("property double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face") != std::string::npos);
    // (x, y) = (0, 1) with y flipped, z = 0.299 * 255.
    CHECK(ply.find("\n0 1 76.245 255 0 0\n") != std::string::npos);
    CHECK(ply.find("\n1 0 255 255 255 255\n") != std::string::npos);
    o.format = MeshFormat::obj;
    REQUIRE(export_mesh(m, o, &obj).ok());
    CHECK(obj.find("\nv 1 1 149.685 0 1 0\n") != std::string::npos);
    CHECK(obj.find("\nv 0 0 29.07 0 0 1\n") != std::string::npos);
    o.format = MeshFormat::stl;
    ExportCounts n;
    REQUIRE(export_mesh(m, o, &stl, &n).ok());
    CHECK(n.facets == 2);
    // An ERD model: a copy per wedge, each with its wedge's colour.
    const Model e = colourise(gray_model("erdgpi", 60), kOffsets);
    o.format = MeshFormat::ply;
    REQUIRE(export_mesh(e, o, &ply, &n).ok());
    CHECK(n.vertices > e.vertices.size());
    // Gray exports keep their old form (no colour properties).
    REQUIRE(export_mesh(channel_model(e, 1), o, &ply).ok());
    CHECK(ply.find("red") == std::string::npos);
}

TEST_CASE("colour render: backgrounds in colour, error maps refuse gray against colour", "[colour]") {
    Image im(2, 1, 255, 3);
    im.samples = {255, 0, 0, 0, 128, 255};
    const RgbImage rgb = image_to_rgb(im);
    CHECK(rgb.pixels == std::vector<std::uint8_t>{255, 0, 0, 0, 128, 255});
    Image g(2, 1, 255);
    g.samples = {7, 9};
    CHECK(image_to_rgb(g).pixels == std::vector<std::uint8_t>{7, 7, 7, 9, 9, 9});
    RgbImage map;
    const Status st = error_map(im, g, 0, &map);
    CHECK(st.code == Code::input);
    CHECK(st.message == "original is colour (3 channels) but the model is gray");
    Image approx = im;
    approx.samples[4] = 128 + 31;  // an error of 31 in the green of pixel 1 (maxval / 8 = 31.875)
    REQUIRE(error_map(im, approx, 0, &map).ok());
    CHECK(map.pixels[0] == 0);
    CHECK(map.pixels[3] > 200);  // nearly white
}

TEST_CASE("API: colour views in, colour reconstructions out", "[colour][api]") {
    const Model m = colourise(gray_model("erdgpi", 60), kOffsets);
    Image out;
    REQUIRE(api::reconstruct(m, true, &out).ok());
    CHECK(out.channels == 3);
    const api::ImageView v = api::view_of(out);
    CHECK(v.channels == 3);
    CHECK(v.stride == std::size_t(out.width) * 3);
    // A gray view written the old way still means gray.
    std::vector<std::uint16_t> px(6, 1);
    const api::ImageView gray{3, 2, 255, px.data()};
    CHECK(gray.channels == 1);
    // A colour view with a padded stride, and the checks of a bad one.
    std::vector<std::uint16_t> rgb = {1, 2, 3, 4, 5, 6, 99, 7, 8, 9, 10, 11, 12, 99};
    api::ImageView c{2, 2, 255, rgb.data(), 7, 3};
    double db = 0;
    c.channels = 2;
    CHECK(api::psnr(c, c, &db).message == "original: image view has 2 channels (1 gray or 3 RGB)");
    c.channels = 3;
    c.stride = 5;
    CHECK(api::psnr(c, c, &db).message == "original: image view stride is smaller than its width times its channels");
    c.stride = 7;
    rgb[5] = 300;
    CHECK(api::psnr(c, c, &db).message == "original: sample 300 at (1,0) channel 2 exceeds maxval 255");
}

TEST_CASE("colour CLI: a colour .erd on stdin reads as from a file (the stream framer)", "[colour]") {
    if (!erd_test::need_binary()) return;
    const Model m = colourise(gray_model("erdgpi", 300), kOffsets);
    std::string text;
    REQUIRE(write_model(m, &text).ok());
    REQUIRE(text.size() > 4 * 4096);  // past the framer's first trial parses
    erd_test::TempDir d;
    erd_test::spit(d.file("c.erd"), text);
    const erd_test::RunResult file = erd_test::run_erd("reconstruct " + erd_test::sh_quote(d.file("c.erd")));
    const erd_test::RunResult in = erd_test::run_erd("reconstruct < " + erd_test::sh_quote(d.file("c.erd")));
    CHECK(file.status == 0);
    CHECK(in.status == 0);
    CHECK(in.err.empty());
    CHECK(in.out == file.out);
    CHECK(file.out.rfind("P6\n48 40\n255\n", 0) == 0);
}
