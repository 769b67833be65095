// Model files: .model, .erd, -t and -p round trips, lenient reading, and one message per malformed case.
#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/imaging/polylines.h"
#include "algorithms/imaging/synth.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/model/reconstruct.h"
#include "tests/synth_util.h"
#include "tests/test_raster_util.h"

using erd::Model;
using erd::ModelFileKind;
using erd::ModelKind;

namespace {

// 3x3 image, centre vertex 4 (doubled (2, 2)), four faces around it.
const char* kSquare = "255\n5\n0 0 10\n2 0 20\n0 2 30\n2 2 40\n1 1 25\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n";

std::string read_error(const std::string& text, ModelFileKind kind) {
    Model m;
    const erd::Status st = erd::read_model(text, kind, &m);
    if (st.ok()) return "OK";
    CHECK(st.code == erd::Code::input);
    return st.message;
}

// An .erd with the centre vertex (2, 2) of a 3x3 image and the wedge lines given.
std::string square_erd(const std::string& wedges) {
    return "255\n5\n0 0 10\n4 0 20\n0 4 30\n4 4 40\n2 2 25\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n" + wedges;
}

}  // namespace

TEST_CASE("model_io: format_value is canonical and round-trips", "[model_io]") {
    CHECK(erd::format_value(3.0) == "3");
    CHECK(erd::format_value(-0.0) == "0");
    CHECK(erd::format_value(2.5) == "2.5");
    CHECK(erd::format_value(0.1) == "0.1");
    CHECK(erd::format_value(-7.0) == "-7");
    const double third = 1.0 / 3.0;
    CHECK(std::stod(erd::format_value(third)) == third);
}

namespace {

// The writers' value format as it was first written, with std::to_string and std::floor: the
// reference the hand-written integer path of format_value must reproduce character for character.
std::string reference_format(double v) {
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

}  // namespace

TEST_CASE("model_io: format_value matches the std::to_string / std::to_chars reference", "[model_io]") {
    std::vector<double> vs = {0.0, -0.0, 1.0, -1.0, 9.0, 10.0, 99.0, 100.0, 255.0, 65535.0, 0.5, -0.5, 1e-300,
                              5e-324, -5e-324, 2.2250738585072014e-308, 1.7976931348623157e308, -1.7976931348623157e308,
                              1e15, -1e15, 1e15 - 1, -(1e15 - 1), 999999999999999.5, 1e15 + 2, 9007199254740992.0,
                              std::nextafter(1e15, 0.0), std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0),
                              std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()};
    for (int d = 0; d <= 15; ++d) {  // every digit count, at the edges of each decade
        const double p = std::pow(10.0, d);
        for (double v : {p, p - 1, p + 1, -p, -(p - 1), p / 2, p + 0.25}) vs.push_back(v);
    }
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        vs.push_back(std::floor(unit(rng) * 65536.0));                     // integral sample values
        vs.push_back(unit(rng) * 65535.0);                                 // wedge values
        vs.push_back((unit(rng) - 0.5) * std::pow(10.0, int(rng() % 40) - 20));  // any magnitude
        vs.push_back(double(std::int64_t(rng() % 2000000000000000ull) - 1000000000000000ll));  // big integers
        std::uint64_t bits = rng();
        double any = 0;
        std::memcpy(&any, &bits, sizeof any);  // any bit pattern, NaNs and subnormals included
        vs.push_back(any);
    }
    std::size_t bad = 0;
    for (double v : vs)
        if (erd::format_value(v) != reference_format(v)) {
            if (++bad <= 5) FAIL_CHECK(std::to_string(v) << ": " << erd::format_value(v) << " vs " << reference_format(v));
        }
    CHECK(bad == 0);
}

TEST_CASE("model_io: kind from the file name", "[model_io]") {
    CHECK(erd::model_kind_from_name("a/b.model") == ModelFileKind::basic);
    CHECK(erd::model_kind_from_name("X.ERD") == ModelFileKind::erd);
    CHECK(erd::model_kind_from_name("t.tri") == ModelFileKind::triangulation);
    CHECK(erd::model_kind_from_name("-") == ModelFileKind::unknown);
}

TEST_CASE("model_io: .model read (lenient), orientation fixed, size from the corners", "[model_io]") {
    // Tabs, CR LF, comments, a clockwise face.
    const std::string text = "# a comment\r\n255 # maxval\r\n5\n0\t0\t10\n2 0 20\n0 2 30\n2 2 40.5\n1 1 25\n4\n0 1 4\n4 3 1\n3 2 4\n2 0 4";
    Model m;
    REQUIRE(erd::read_model(text, ModelFileKind::unknown, &m).ok());
    CHECK(m.kind == ModelKind::basic);
    CHECK(m.width == 3);
    CHECK(m.height == 3);
    CHECK(m.maxval == 255);
    REQUIRE(m.vertices.size() == 5);
    CHECK(m.vertices[3] == erd::LatticePoint{4, 4});  // doubled
    CHECK(m.values[3] == 40.5);
    for (const auto& f : m.faces) CHECK(erd::orient2d(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) > 0);
    std::string out;
    REQUIRE(erd::write_model(m, &out).ok());
    CHECK(out == "255\n5\n0 0 10\n2 0 20\n0 2 30\n2 2 40.5\n1 1 25\n4\n0 1 4\n4 1 3\n3 2 4\n2 0 4\n");
}

TEST_CASE("model_io: .model round trip on random triangulations", "[model_io]") {
    std::mt19937 rng(8);
    for (int trial = 0; trial < 10; ++trial) {
        const int W = 2 + int(rng() % 30), H = 2 + int(rng() % 30);
        Model m = erd_test::random_model(rng, W, H, 40, true);
        m.maxval = 1000;
        for (std::size_t v = 0; v < m.vertices.size(); ++v) m.values.push_back(v % 3 == 0 ? double(rng() % 1000) : double(rng() % 100000) / 97.0);
        std::string text, again;
        REQUIRE(erd::write_model(m, &text).ok());
        Model r;
        REQUIRE(erd::read_model(text, ModelFileKind::basic, &r).ok());
        CHECK(r.kind == ModelKind::basic);
        CHECK(r.width == W);
        CHECK(r.height == H);
        CHECK(r.maxval == 1000);
        CHECK(r.vertices == m.vertices);
        CHECK(r.values == m.values);
        CHECK(r.faces == m.faces);
        REQUIRE(erd::write_model(r, &again).ok());
        CHECK(again == text);
    }
}

TEST_CASE("model_io: .erd round trip keeps every corner value", "[model_io]") {
    std::mt19937 rng(9);
    for (int trial = 0; trial < 10; ++trial) {
        const int W = 2 + int(rng() % 12), H = 2 + int(rng() % 12);
        Model m = erd_test::random_model(rng, W, H, 30, false);
        m.kind = ModelKind::erd;
        // Vertex values; some vertices get a different value in a random subset of faces.
        for (std::size_t v = 0; v < m.vertices.size(); ++v) m.values.push_back(double(rng() % 256));
        for (const auto& f : m.faces) {
            std::array<double, 3> c{};
            for (int k = 0; k < 3; ++k)
                c[std::size_t(k)] = f[std::size_t(k)] % 4 == 0 ? double(rng() % 4) * 0.5 : m.values[f[std::size_t(k)]];
            m.corner_values.push_back(c);
        }
        // The mean of the wedge values, as the reader computes it.
        erd::ModelTopology topo;
        REQUIRE(erd::build_topology(m, &topo).ok());
        for (std::uint32_t v = 0; v < m.vertices.size(); ++v) m.values[v] = erd::vertex_wedges(m, topo, v).mean;
        std::string text, again;
        REQUIRE(erd::write_model(m, &text).ok());
        Model r;
        REQUIRE(erd::read_model(text, ModelFileKind::unknown, &r).ok());
        CHECK(r.kind == ModelKind::erd);
        CHECK(r.width == W);
        CHECK(r.height == H);
        CHECK(r.vertices == m.vertices);
        CHECK(r.faces == m.faces);
        CHECK(r.corner_values == m.corner_values);
        CHECK(r.values == m.values);
        REQUIRE(erd::write_model(r, &again).ok());
        CHECK(again == text);
    }
}

TEST_CASE("model_io: the thesis's .erd example (one wedge line per face)", "[model_io]") {
    const std::string text = "255\n4\n0 0 127\n0 98 64\n98 0 64\n98 98 0\n2\n0 1 2\n1 2 3\n4\n1 0 73\n1 1 54\n2 0 73\n2 1 54\n";
    Model m;
    REQUIRE(erd::read_model(text, ModelFileKind::unknown, &m).ok());
    CHECK(m.kind == ModelKind::erd);
    CHECK(m.width == 50);
    CHECK(m.values[0] == 127);
    CHECK(m.values[1] == 63.5);  // mean of its wedges; the 64 of the file is ignored (thesis A.4.2)
    CHECK(m.values[2] == 63.5);
    REQUIRE(m.constraints.size() == 1);
    CHECK(m.constraints[0] == std::array<std::uint32_t, 2>{1, 2});
    // Face 0 was clockwise: stored as 0 2 1 with its corner values.
    CHECK(m.faces[0] == std::array<std::uint32_t, 3>{0, 2, 1});
    CHECK(m.corner_values[0] == std::array<double, 3>{127, 73, 73});
    CHECK(m.corner_values[1] == std::array<double, 3>{54, 54, 0});
    std::string out;
    REQUIRE(erd::write_model(m, &out).ok());
    CHECK(out == "255\n4\n0 0 127\n0 98 63.5\n98 0 63.5\n98 98 0\n2\n0 2 1\n1 2 3\n4\n1 0 73\n1 1 54\n2 0 73\n2 1 54\n");
}

TEST_CASE("model_io: wedge lines of the thesis form are propagated when determined", "[model_io]") {
    SECTION("both neighbours agree") {
        Model m;
        REQUIRE(erd::read_model(square_erd("2\n4 0 7\n4 2 7\n"), ModelFileKind::erd, &m).ok());
        for (const auto& c : m.corner_values) CHECK(c[2] == 7);
        CHECK(m.values[4] == 7);
    }
    SECTION("neighbours disagree") {
        CHECK(read_error(square_erd("2\n4 0 7\n4 2 9\n"), ModelFileKind::erd) ==
              "the wedge of face 3 at vertex 4 is undetermined (give a wedge line for every face of a vertex with several wedges)");
    }
    SECTION("open fan of a border vertex: the end faces follow their only neighbour") {
        // 3x2 image, bottom-middle vertex 4 at (2, 2) with three faces 0, 1, 2 around it.
        const std::string t = "255\n5\n0 0 1\n4 0 2\n0 2 3\n4 2 4\n2 2 5\n3\n0 1 4\n0 4 2\n1 3 4\n";
        Model m;
        REQUIRE(erd::read_model(t + "2\n4 0 10\n4 2 20\n", ModelFileKind::erd, &m).ok());
        CHECK(m.corner_values[1][1] == 10);  // face 1 (0 4 2): between face 0 and the border
        CHECK(m.values[4] == 15);
        CHECK(read_error(t + "2\n4 1 10\n4 2 20\n", ModelFileKind::erd).find("undetermined") != std::string::npos);
    }
}

TEST_CASE("model_io: every malformed file gets its message", "[model_io]") {
    const auto E = ModelFileKind::erd, B = ModelFileKind::basic, U = ModelFileKind::unknown;
    CHECK(read_error("", U) == "empty file");
    CHECK(read_error("  # only a comment\n", U) == "empty file");
    CHECK(read_error("abc", U) == "line 1: expected maxval, found 'abc'");
    CHECK(read_error("+4", U) == "line 1: expected maxval, found '+4'");
    CHECK(read_error("0", U) == "line 1: maxval 0 out of range (1..65535)");
    CHECK(read_error("4294967297", U) == "line 1: maxval 4294967297 out of range (1..65535)");
    CHECK(read_error("99999999999999999999999", U).find("too large") != std::string::npos);
    CHECK(read_error("255\n3\n", U) == "line 2: vertex count 3 out of range (4..1099511627776)");
    CHECK(read_error("255\n1000000\n0 0 0\n", U) ==
          "line 2: vertex count 1000000 is more than the rest of the file holds (the file ends early or the count is wrong)");
    CHECK(read_error("255\n4\n0 0 1\n2 0 1\n0 2", U) ==
          "line 2: vertex count 4 is more than the rest of the file holds (the file ends early or the count is wrong)");
    CHECK(read_error("255\n4\n0 0 1.000000\n2 0 1.000000\n0 2", U) == "file ends early: expected value of vertex 2");
    CHECK(read_error("255\n4\n0 0 1\n-2 0 1\n0 2 1\n2 2 1\n", U) == "line 4: x coordinate of vertex 1 -2 outside the image (0..65534)");
    CHECK(read_error("255\n4\n0 0 1\n70000 0 1\n0 2 1\n2 2 1\n", U) == "line 4: x coordinate of vertex 1 70000 outside the image (0..65534)");
    CHECK(read_error("255\n4\n0 0 1\n40000 0 1\n0 2 1\n40000 2 1\n2\n0 1 3\n0 3 2\n", B) ==
          "line 4: vertex 1 (40000, 0) outside the image (0..32767)");
    CHECK(read_error("255\n4\n0 0 nan\n2 0 1\n0 2 1\n2 2 1\n", U) == "line 3: value of vertex 0 'nan' is not a finite number");
    CHECK(read_error("255\n4\n0 0 inf\n2 0 1\n0 2 1\n2 2 1\n", U) == "line 3: value of vertex 0 'inf' is not a finite number");
    CHECK(read_error("255\n4\n0 0 1e400\n2 0 1\n0 2 1\n2 2 1\n", U) == "line 3: value of vertex 0 '1e400' is not a finite number");
    CHECK(read_error("255\n4\n0 0 1x\n2 0 1\n0 2 1\n2 2 1\n", U) == "line 3: expected value of vertex 0, found '1x'");
    const std::string v4 = "255\n4\n0 0 1\n2 0 1\n0 2 1\n2 2 1\n";
    CHECK(read_error(v4 + "2\n0 1 3\n0 3 9\n", U) == "line 9: face 1: vertex index 9 out of range (4 vertices)");
    CHECK(read_error(v4 + "2\n0 1 3\n0 3 3\n", U) == "line 9: face 1 repeats a vertex");
    CHECK(read_error("255\n5\n0 0 1\n2 0 1\n0 2 1\n2 2 1\n1 1 1\n3\n0 4 3\n0 1 3\n0 3 2\n", U) ==
          "line 9: face 0 is degenerate (its vertices are collinear)");
    CHECK(read_error(v4 + "3\n0 1 3\n0 3 2\n3 1 0\n", U) == "line 10: faces 0 and 2 are the same triangle");
    CHECK(read_error(v4 + "2\n0 1 3\n", U).find("line 7: face count 2 is more than the rest of the file holds") == 0);
    CHECK(read_error(v4 + "2\n0 1 3\n0      ", U) == "file ends early: expected vertex index 2 of face 1");
    CHECK(read_error(v4 + "1\n0 1 3\n0 3 2\n", B) == "line 9: unexpected '0' after the last face (check the counts)");
    CHECK(read_error(v4 + "2\n0 1 3\n0 3 2\n0\n", B) == "line 10: unexpected '0' after the last face (check the counts)");
    CHECK(read_error("255\n4\n0 0 1\n2 0 1\n0 0 1\n2 2 1\n2\n0 1 3\n1 3 2\n", U) == "line 5: vertices 0 and 2 coincide at (0, 0)");
    CHECK(read_error("255\n4\n0 0 1\n2 0 1\n0 2 1\n3 3 1\n2\n0 1 3\n0 3 2\n0\n", E) ==
          "the largest coordinates (3, 3) are not even: the domain [0, 2W-2] x [0, 2H-2] must end on a pixel");
    CHECK(read_error("255\n4\n0 0 1\n4 0 1\n0 2 1\n2 2 1\n2\n0 1 3\n0 3 2\n", U) == "corner (4, 2) of the image domain is not a vertex");
    CHECK(read_error(v4 + "2\n0 1 3\n0 3 2\n", E) == "file ends early: expected wedge count");
    const std::string erd2 = v4 + "2\n0 1 3\n0 3 2\n";
    CHECK(read_error(erd2 + "2\n0 0 5\n", E).find("line 10: wedge count 2 is more than") == 0);
    CHECK(read_error(erd2 + "2\n0 0 5.00000\n", E) == "file ends early: expected vertex index of wedge line 1");
    CHECK(read_error(erd2 + "1\n7 0 5\n", E) == "line 11: wedge line 0: vertex index 7 out of range (4 vertices)");
    CHECK(read_error(erd2 + "1\n0 5 5\n", E) == "line 11: wedge line 0: face index 5 out of range (2 faces)");
    CHECK(read_error(erd2 + "1\n1 1 5\n", E) == "line 11: wedge line 0: face 1 is not incident on vertex 1");
    CHECK(read_error(erd2 + "1\n0 0 nan\n", E) == "line 11: wedge value of wedge line 0 'nan' is not a finite number");
    CHECK(read_error(erd2 + "2\n0 0 5\n0 0 6\n", E) == "line 12: wedge line 1: conflicting values for vertex 0 in face 0");
    CHECK(read_error(erd2 + "1\n0 0 5\n1\n", E) == "line 12: unexpected '1' after the last wedge line (check the counts)");
    // Overlapping faces of an .erd: the wedges cannot be told apart.
    CHECK(read_error("255\n5\n0 0 1\n4 0 1\n0 4 1\n4 4 1\n2 2 1\n3\n0 1 4\n0 1 3\n3 2 0\n0\n", E)
              .find("not a triangulation of the image domain: faces") == 0);
    CHECK(read_error(kSquare, U) == "OK");
}

TEST_CASE("model_io: a model that passed the reader but is no triangulation is refused by reconstruct", "[model_io]") {
    // A hole: the face 2 0 4 is missing.
    Model m;
    REQUIRE(erd::read_model("255\n5\n0 0 10\n2 0 20\n0 2 30\n2 2 40\n1 1 25\n3\n0 1 4\n1 3 4\n3 2 4\n", ModelFileKind::basic, &m).ok());
    erd::Image im;
    const erd::Status st = erd::reconstruct(m, false, &im);
    CHECK(st.code == erd::Code::input);
    CHECK(st.message == "not a triangulation of the image domain: the faces leave holes (their areas add up to less than the rectangle)");
}

TEST_CASE("model_io: triangulation files (-t)", "[model_io]") {
    Model m;
    REQUIRE(erd::read_model(square_erd("4\n4 0 1\n4 1 1\n4 2 2\n4 3 2\n"), ModelFileKind::erd, &m).ok());
    REQUIRE(m.constraints.size() == 2);  // 0-4 and 3-4 separate the 1s (faces 0, 1) from the 2s
    std::string text;
    REQUIRE(erd::write_triangulation(m, &text).ok());
    CHECK(text == "erd-triangulation 1\n3 3\n5\n0 0\n4 0\n0 4\n4 4\n2 2\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n2\n0 4\n3 4\n");
    Model t;
    REQUIRE(erd::read_triangulation(text, &t).ok());
    CHECK(t.width == 3);
    CHECK(t.vertices == m.vertices);
    CHECK(t.faces == m.faces);
    CHECK(t.constraints == m.constraints);
    CHECK(erd::read_model(text, ModelFileKind::triangulation, &t).ok());
    const auto err = [](const std::string& s) {
        Model x;
        return erd::read_triangulation(s, &x).message;
    };
    CHECK(err("") == "empty file");
    CHECK(err("erd-polylines 1\n") ==
          "line 1: not an erd triangulation file (expected 'erd-triangulation 1', found 'erd-polylines')");
    CHECK(err("erd-triangulation 2\n") == "line 1: format version 2 out of range (1..1)");
    CHECK(err("erd-triangulation 1\n3 3\n4\n0 0\n4 0\n0 4\n4 4\n2\n0 1 3\n0 3 2\n1\n0 3\n").empty());
    CHECK(err("erd-triangulation 1\n3 3\n4\n0 0\n4 0\n0 4\n4 4\n2\n0 1 3\n0 3 2\n1\n1 2\n") ==
          "line 12: constraint 0 (1, 2) is not an edge of any face");
    CHECK(err("erd-triangulation 1\n3 3\n4\n0 0\n6 0\n0 4\n4 4\n") == "line 5: x coordinate of vertex 1 6 outside the image (0..4)");
    CHECK(err("erd-triangulation 1\n4 3\n4\n0 0\n4 0\n0 4\n4 4\n2\n0 1 3\n0 3 2\n0\n") ==
          "the vertices span 3 x 3 pixels, not the 4 x 3 of the header");
    CHECK(err("erd-triangulation 1\n3 3\n4\n0 0\n4 0\n0 4\n4 4\n2\n0 1 3\n0 3 2\n0\n7\n") ==
          "line 12: unexpected '7' after the last constraint (check the counts)");
}

TEST_CASE("model_io: polylines files (-p) round-trip", "[model_io]") {
    // The polylines of step 1 on the synthetic test image: many, of every length.
    const erd::Image im = erd_test::synth_image(160, 120);
    erd::EdgePolylineParams params;
    params.canny.beta = 0.2;
    params.min_length = 2;
    erd::EdgePolylineResult step1;
    REQUIRE(erd::edge_polylines(im, params, &step1).ok());
    std::vector<erd::Polyline> lines = step1.polylines;
    REQUIRE(lines.size() > 10);
    lines.push_back({});                                    // an empty polyline
    lines.push_back({{4, 4}});                              // one point
    lines.push_back({{0, 0}, {2, 0}, {2, 2}, {0, 0}});      // a closed loop repeats its first point
    lines.push_back({{0, 0}, {2 * erd::kMaxImageSide - 2, 2 * erd::kMaxImageSide - 2}});  // the largest coordinates
    std::string text;
    erd::write_polylines(lines, &text);
    std::vector<erd::Polyline> back;
    REQUIRE(erd::read_polylines(text, &back).ok());
    CHECK(back == lines);
    std::string again;
    erd::write_polylines(back, &again);
    CHECK(again == text);

    erd::write_polylines({{{1, 2}, {30, 4}}, {{7, 8}}}, &text);
    CHECK(text == "erd-polylines 1\n2\n2 1 2 30 4\n1 7 8\n");
    erd::write_polylines({}, &text);
    CHECK(text == "erd-polylines 1\n0\n");
    // Read leniently: any whitespace, comments.
    REQUIRE(erd::read_polylines("erd-polylines 1 # two\n2\n2 1 2\n 30 4 1 7 8", &back).ok());
    CHECK(back == std::vector<erd::Polyline>{{{1, 2}, {30, 4}}, {{7, 8}}});

    const auto err = [](const std::string& s) {
        std::vector<erd::Polyline> x;
        const erd::Status st = erd::read_polylines(s, &x);
        CHECK((st.ok() || st.code == erd::Code::input));
        return st.message;
    };
    CHECK(err("") == "empty file");
    CHECK(err("erd-triangulation 1\n") ==
          "line 1: not an erd polylines file (expected 'erd-polylines 1', found 'erd-triangulation')");
    CHECK(err("erd-polylines 2\n0\n") == "line 1: format version 2 out of range (1..1)");
    CHECK(err("erd-polylines 1\n") == "file ends early: expected polyline count");
    CHECK(err("erd-polylines 1\n900\n2 0 0 1 1\n") ==
          "line 2: polyline count 900 is more than the rest of the file holds (the file ends early or the count is wrong)");
    CHECK(err("erd-polylines 1\n1\n2 0 0 10 \n") == "file ends early: expected y coordinate of point 1 of polyline 0");
    CHECK(err("erd-polylines 1\n1\n3 0 0 1 1\n") ==
          "line 3: point count of polyline 0 3 is more than the rest of the file holds (the file ends early or the count is wrong)");
    CHECK(err("erd-polylines 1\n1\n1 -2 0\n") == "line 3: x coordinate of point 0 of polyline 0 -2 outside the image (0..65534)");
    CHECK(err("erd-polylines 1\n1\n1 0 x\n") == "line 3: expected y coordinate of point 0 of polyline 0, found 'x'");
    CHECK(err("erd-polylines 1\n1\n1 0 0\n5\n") == "line 4: unexpected '5' after the last polyline (check the counts)");
}
