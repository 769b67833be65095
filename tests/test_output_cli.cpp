// Pictures, exports, statistics through the real binary (ERD_BIN): erd render, erd export,
// erd generate --stats, and the manual's coverage of every subcommand's options.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/model/model_io.h"
#include "cli/image_io.h"
#include "tests/output_util.h"

using namespace erd;
using namespace output_test;

TEST_CASE("erd export: OBJ and PLY files of the A.4.2 example, wedge copies", "[output]") {
    if (!erd_test::need_binary()) return;
    using namespace erd_test;
    TempDir dir;
    spit(dir.file("d.erd"), kDiagonalErd);
    RunResult r = run_erd("export " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.obj")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::string obj = slurp(dir.file("d.obj"));
    CHECK(lines_starting(obj, "v ").size() == 6);
    CHECK(lines_starting(obj, "f ").size() == 2);
    // Default zscale 50 / 2550: vertex 0 (127) at 127 * 50 / 2550 = 2.4901961.
    CHECK(lines_starting(obj, "v 0 49 2.4901960").size() == 1);

    r = run_erd("export " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.ply")) + " --zscale 1");
    REQUIRE(r.status == 0);
    std::string ply = slurp(dir.file("d.ply"));
    CHECK(count(ply, "element vertex 6\n") == 1);
    CHECK(count(ply, "element face 2\n") == 1);

    // As a .model (continuous): 4 vertices.
    spit(dir.file("d.model"), "255\n4\n0 0 127\n0 49 64\n49 0 64\n49 49 90\n2\n0 2 1\n1 2 3\n");
    r = run_erd("export " + sh_quote(dir.file("d.model")) + " --format ply -o -");
    REQUIRE(r.status == 0);
    CHECK(count(r.out, "element vertex 4\n") == 1);

    // Usage and input errors: exit 2, one line naming the problem.
    CHECK(run_erd("export " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.xyz"))).status == 2);
    CHECK(run_erd("export " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("x.obj")) + " --zscale 0").status == 2);
    CHECK(run_erd("export " + sh_quote(dir.file("missing.erd")) + " -o " + sh_quote(dir.file("x.obj"))).status == 2);
    CHECK(run_erd("export " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.erd")) + " --format obj").status == 2);
    CHECK(slurp(dir.file("d.erd")) == kDiagonalErd);
}

TEST_CASE("erd render: SVG elements, PNG size, backgrounds and errors", "[output]") {
    if (!erd_test::need_binary()) return;
    using namespace erd_test;
    TempDir dir;
    spit(dir.file("d.erd"), kDiagonalErd);
    RunResult r = run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.svg")) +
                          " --scale 2 --vertices");
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::string svg = slurp(dir.file("d.svg"));
    CHECK(count(group(svg, "edges"), "<line ") == 4);
    CHECK(count(group(svg, "constrained"), "<line ") == 1);
    CHECK(count(group(svg, "vertices"), "<circle ") == 4);

    // PNG over an image of the right size; default scale makes the side 550 (11 x 50).
    erd::Image im(50, 50, 255);
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 50; ++x) im.at(x, y) = std::uint16_t(x + y < 49 ? 90 : 60);
    spit(dir.file("d.pgm"), erd::cli::encode_pnm(im, false));
    r = run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("d.png")) + " --over " +
                sh_quote(dir.file("d.pgm")));
    REQUIRE(r.status == 0);
    int w = 0, h = 0;
    REQUIRE(png_size(slurp(dir.file("d.png")), &w, &h));
    CHECK(w == 550);
    CHECK(h == 550);
    r = run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("e.png")) + " --error " +
                sh_quote(dir.file("d.pgm")) + " --scale 1 --crop 10,5,20,30");
    REQUIRE(r.status == 0);
    REQUIRE(png_size(slurp(dir.file("e.png")), &w, &h));
    CHECK(w == 20);
    CHECK(h == 30);
    r = run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("r.svg")) + " --over-reconstruction");
    REQUIRE(r.status == 0);
    CHECK(count(slurp(dir.file("r.svg")), "href=\"data:image/png;base64,iVBORw0KGgo") == 2);

    // Errors: wrong size background, two backgrounds, bad crop, bad extension.
    erd::Image small(10, 10, 255);
    spit(dir.file("s.pgm"), erd::cli::encode_pnm(small, false));
    r = run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("x.png")) + " --over " + sh_quote(dir.file("s.pgm")));
    CHECK(r.status == 2);
    CHECK(r.err.find("10x10") != std::string::npos);
    CHECK(run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("x.png")) +
                  " --over-reconstruction --over " + sh_quote(dir.file("d.pgm"))).status == 2);
    CHECK(run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("x.png")) + " --crop 40,40,20,20").status == 2);
    CHECK(run_erd("render " + sh_quote(dir.file("d.erd")) + " -o " + sh_quote(dir.file("x.gif"))).status == 2);
    CHECK_FALSE(exists(dir.file("x.png")));
}

TEST_CASE("erd generate --stats -: one JSON object with the run's facts", "[output]") {
    if (!erd_test::need_binary()) return;
    using namespace erd_test;
    TempDir dir;
    erd::Image im = wave_disc_image();
    spit(dir.file("in.pgm"), erd::cli::encode_pnm(im, false));
    for (const char* method : {"gpi", "erdgpi"}) {
        INFO(method);
        bool erd_kind = std::string(method) == "erdgpi";
        std::string model = dir.file(std::string("m.") + (erd_kind ? "erd" : "model"));
        RunResult r = run_erd("generate -m " + std::string(method) + " -i " + sh_quote(dir.file("in.pgm")) +
                              " -n 60 -o " + sh_quote(model) + " --stats - --psnr-report -q");
        INFO(r.err);
        REQUIRE(r.status == 0);
        REQUIRE(std::count(r.out.begin(), r.out.end(), '\n') == 1);
        Json j = parse_json(r.out.substr(0, r.out.size() - 1));
        CHECK(j["method"].s == method);
        CHECK(j["model"].s == (erd_kind ? "erd" : "basic"));
        CHECK(j["image"]["width"].n == 40);
        CHECK(j["image"]["height"].n == 30);
        CHECK(j["image"]["maxval"].n == 255);
        CHECK(j["points"]["requested"].n == 60);
        CHECK(j["points"]["achieved"].n == 60);
        CHECK(j["vertices"].n == 60);
        // Every vertex inside a triangulation of a rectangle: F = 2V - 2 - hull vertices.
        CHECK(j["faces"].n > 60);
        CHECK(j["faces"].n <= 2 * 60 - 6);
        if (erd_kind) {
            CHECK(j["parameters"].kind == Json::object);
            CHECK(j["parameters"]["r"].n == 0.4);
            CHECK(j["constrained_edges"].n > 0);
            CHECK(j["constrained_vertices"].n > 2);
        } else {
            CHECK(j["parameters"].kind == Json::null);
            CHECK(j["constrained_edges"].n == 0);
        }
        CHECK(j["stop"].s == "target");
        CHECK(j["stages"].items.size() >= 3);
        CHECK(j["total_seconds"].n >= 0);
        CHECK(j["peak_memory_bytes"].n > 1e5);
        // The PSNR of the proper reconstruction, as `erd reconstruct` + `erd psnr` give it.
        REQUIRE(j.has("psnr"));
        RunResult rec = run_erd("reconstruct " + sh_quote(model) + " -o " + sh_quote(dir.file("r.pgm")));
        REQUIRE(rec.status == 0);
        RunResult p = run_erd("psnr " + sh_quote(dir.file("in.pgm")) + " " + sh_quote(dir.file("r.pgm")));
        REQUIRE(p.status == 0);
        CHECK(j["psnr"].n == Approx(std::stod(p.out)).margin(1e-4));
    }
}

TEST_CASE("the manual names every long option of every subcommand", "[output]") {
    if (!erd_test::need_binary()) return;
    using namespace erd_test;
    const char* env = std::getenv("ERD_MANUAL");
    std::string manual = slurp(env && *env ? env : "docs/manual.md");
    if (manual.empty()) {
        WARN("docs/manual.md not found (run from the repository root or set ERD_MANUAL)");
        return;
    }
    RunResult help = run_erd("help");
    REQUIRE(help.status == 0);
    // Subcommand names: the lines "  name  summary" after "Subcommands:".
    std::vector<std::string> subs;
    std::istringstream in(help.out.substr(help.out.find("Subcommands:")));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && line.size() > 2 && line[0] == ' ') {
        std::istringstream words(line);
        std::string name;
        words >> name;
        if (name != "help") subs.push_back(name);
    }
    REQUIRE(subs.size() >= 8);
    for (const std::string& sub : subs) {
        INFO("erd " << sub);
        CHECK(manual.find("### erd " + sub + "\n") != std::string::npos);
        RunResult r = run_erd(sub + " --help");
        REQUIRE(r.status == 0);
        for (std::size_t p = r.out.find("--"); p != std::string::npos; p = r.out.find("--", p + 2)) {
            std::size_t e = p + 2;
            while (e < r.out.size() && (std::isalnum(static_cast<unsigned char>(r.out[e])) || r.out[e] == '-')) ++e;
            std::string flag = r.out.substr(p, e - p);
            if (flag.size() < 4 || flag == "--help") continue;
            INFO(flag);
            CHECK(manual.find(flag) != std::string::npos);
            p = e;
        }
    }
}

TEST_CASE("erd render draws a -t triangulation file with the method's constrained edges", "[output]") {
    if (!erd_test::need_binary()) return;
    using namespace erd_test;
    TempDir dir;
    erd::Image im = wave_disc_image();
    spit(dir.file("in.pgm"), erd::cli::encode_pnm(im, false));
    RunResult r = run_erd("generate -m erdgpi -i " + sh_quote(dir.file("in.pgm")) + " -n 60 -o " + sh_quote(dir.file("m.erd")) +
                          " -t " + sh_quote(dir.file("m.tri")) + " -q");
    INFO(r.err);
    REQUIRE(r.status == 0);
    Model tri;
    REQUIRE(read_triangulation(slurp(dir.file("m.tri")), &tri).ok());
    REQUIRE(run_erd("render " + sh_quote(dir.file("m.tri")) + " -o " + sh_quote(dir.file("t.svg"))).status == 0);
    REQUIRE(run_erd("render " + sh_quote(dir.file("m.erd")) + " -o " + sh_quote(dir.file("e.svg"))).status == 0);
    std::string t = slurp(dir.file("t.svg")), e = slurp(dir.file("e.svg"));
    // The file's own list, drawn as given; the .erd shows those whose values differ (a subset).
    CHECK(count(group(t, "constrained"), "<line ") == tri.constraints.size());
    CHECK(tri.constraints.size() > 0);
    CHECK(count(group(e, "constrained"), "<line ") <= tri.constraints.size());
    CHECK(count(t, "<line ") == count(e, "<line "));
    // Nothing to reconstruct or export in a triangulation file.
    CHECK(run_erd("render " + sh_quote(dir.file("m.tri")) + " -o " + sh_quote(dir.file("x.png")) + " --over-reconstruction").status == 2);
    CHECK(run_erd("export " + sh_quote(dir.file("m.tri")) + " -o " + sh_quote(dir.file("x.obj"))).status == 2);
}

