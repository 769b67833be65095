// `erd edges` through the real binary (env ERD_BIN): outputs, their sizes and formats, bad flags.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/imaging/polylines.h"
#include "algorithms/model/model_io.h"
#include "cli/image_io.h"
#include "tests/erd_run.h"

using namespace erd_test;

TEST_CASE("erd edges writes the half-pixel edge map and the polylines", "[imaging]") {
    if (!need_binary()) return;
    TempDir dir;
    // 20x12, a vertical step between x = 9 and x = 10.
    erd::Image im(20, 12, 255);
    for (int y = 0; y < 12; ++y)
        for (int x = 10; x < 20; ++x) im.at(x, y) = 200;
    REQUIRE(erd::cli::write_image(dir.file("step.pgm"), im).ok());
    const std::string args = sh_quote(dir.file("step.pgm")) + " -o " + sh_quote(dir.file("e.pgm")) + " -p " +
                             sh_quote(dir.file("p.txt")) + " --draw-polylines " + sh_quote(dir.file("d.png")) +
                             " -b 0.05 -e 1 -l 3";
    RunResult r = run_erd("edges " + args);
    INFO(r.err);
    REQUIRE(r.status == 0);
    erd::Image edges;
    std::string warning;
    REQUIRE(erd::cli::read_image(dir.file("e.pgm"), &edges, &warning).ok());
    CHECK(edges.width == 39);
    CHECK(edges.height == 23);
    for (int Y = 0; Y < edges.height; ++Y) {
        int n = 0;
        for (int X = 0; X < edges.width; ++X)
            if (edges.at(X, Y)) {
                ++n;
                CHECK(edges.at(X, Y) == 255);
                CHECK((X == 19 || X == 18 || X == 20));  // the step lies at x = 9.5: X = 19
            }
        CHECK(n == 1);
    }
    // One straight vertical polyline, simplified to its two ends.
    const std::string text = slurp(dir.file("p.txt"));
    CHECK(text.rfind("erd-polylines 1\n1\n2 ", 0) == 0);
    std::vector<erd::Polyline> lines;
    REQUIRE(erd::read_polylines(text, &lines).ok());
    REQUIRE(lines.size() == 1);
    REQUIRE(lines[0].size() == 2);
    CHECK(lines[0][0].x == lines[0][1].x);
    CHECK(std::abs(lines[0][0].y - lines[0][1].y) >= 18);
    erd::Image drawn;
    REQUIRE(erd::cli::read_image(dir.file("d.png"), &drawn, &warning).ok());
    CHECK(drawn.width == 39);

    RunResult bad = run_erd("edges " + sh_quote(dir.file("step.pgm")) + " -o " + sh_quote(dir.file("x.pgm")) + " --nope");
    CHECK(bad.status == 2);  // a usage error as in every subcommand: the problem, then the usage line
    CHECK_THAT(bad.err, Catch::StartsWith("erd edges: unknown option --nope\nusage: erd edges IMAGE -o EDGES"));
    bad = run_erd("edges " + sh_quote(dir.file("step.pgm")) + " -o " + sh_quote(dir.file("x.pgm")) + " -b 0");
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::StartsWith("erd edges: --beta: 0 is outside [1e-09, 1]\nusage: erd edges"));
    bad = run_erd("edges " + sh_quote(dir.file("step.pgm")));
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::StartsWith("erd edges: missing -o EDGES\nusage: erd edges"));
    bad = run_erd("edges -o " + sh_quote(dir.file("x.pgm")));
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::StartsWith("erd edges: expected one IMAGE\nusage: erd edges"));
    bad = run_erd("edges " + sh_quote(dir.file("step.pgm")) + " -o " + sh_quote(dir.file("step.pgm")));
    CHECK(bad.status == 2);  // would overwrite the input
}
