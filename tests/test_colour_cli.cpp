// Colour models through the real binary (ERD_BIN): `erd reconstruct` writes PPM (P6, P3) or PNG
// RGB, `erd export` per-vertex colours, `erd render` colour backgrounds, `--stats` the channels.
#include <catch2/catch.hpp>

#include <string>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// 2x2 colour image, each channel z = a + b x: point evaluation (10 18, 10 18), (0 100, 0 100), (7 7, 7 7).
const char* kColourModel =
    "erd-header 1\nchannels 3\nend\n255\n4\n0 0 10 0 7\n1 0 18 100 7\n0 1 10 0 7\n1 1 18 100 7\n2\n0 1 3\n0 3 2\n";

std::string rgb(std::initializer_list<int> v) {
    std::string s;
    for (int x : v) s += char(x);
    return s;
}

}  // namespace

TEST_CASE("colour CLI: reconstruct writes P6, P3 and PNG RGB", "[colour]") {
    if (!need_binary()) return;
    TempDir d;
    spit(d.file("c.model"), kColourModel);
    RunResult r = run_erd("reconstruct " + sh_quote(d.file("c.model")));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == "P6\n2 2\n255\n" + rgb({10, 0, 7, 18, 100, 7, 10, 0, 7, 18, 100, 7}));
    r = run_erd("reconstruct --plain " + sh_quote(d.file("c.model")));
    CHECK(r.out == "P3\n2 2\n255\n10 0 7 18 100 7 10 0 7 18 100 7\n");
    r = run_erd("reconstruct " + sh_quote(d.file("c.model")) + " -o " + sh_quote(d.file("c.png")));
    CHECK(r.status == 0);
    const std::string png = slurp(d.file("c.png"));
    REQUIRE(png.size() > 26);
    CHECK(png.compare(1, 3, "PNG") == 0);
    CHECK(int(png[25]) == 2);  // IHDR colour type 2: RGB
    // A colour model with a broken line: one line, exit 2.
    spit(d.file("bad.model"), std::string(kColourModel).replace(std::string(kColourModel).find("1 0 18 100 7"), 12, "1 0 18 100"));
    r = run_erd("reconstruct " + sh_quote(d.file("bad.model")) + " -o " + sh_quote(d.file("x.ppm")));
    CHECK(r.status == 2);
    CHECK(r.err == "erd reconstruct: " + d.file("bad.model") +
                       ": line 7: vertex 1 has 2 values on its line, expected 3 (the header says channels 3)\n");
    CHECK_FALSE(exists(d.file("x.ppm")));
}

TEST_CASE("colour CLI: export colours, render over the colour reconstruction", "[colour]") {
    if (!need_binary()) return;
    TempDir d;
    spit(d.file("c.model"), kColourModel);
    RunResult r = run_erd("export " + sh_quote(d.file("c.model")) + " -o " + sh_quote(d.file("c.ply")) + " --zscale 1");
    CHECK(r.status == 0);
    const std::string ply = slurp(d.file("c.ply"));
    CHECK(ply.find("property uchar red\nproperty uchar green\nproperty uchar blue\n") != std::string::npos);
    CHECK(ply.find("\n1 1 64.88 18 100 7\n") != std::string::npos);  // z = 0.299 18 + 0.587 100 + 0.114 7
    r = run_erd("export " + sh_quote(d.file("c.model")) + " -o " + sh_quote(d.file("c.obj")) + " --zscale 1");
    CHECK(r.status == 0);
    CHECK(slurp(d.file("c.obj")).find("\nv 1 1 64.88 0.0705882 0.392157 0.027451\n") != std::string::npos);
    r = run_erd("render " + sh_quote(d.file("c.model")) + " --over-reconstruction --scale 2 -o " + sh_quote(d.file("c.png")));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    r = run_erd("render --vector " + sh_quote(d.file("c.model")) + " -o " + sh_quote(d.file("c.svg")));
    CHECK(r.status == 0);  // one layer per channel (tests/test_vector_svg.cpp)
    CHECK(slurp(d.file("c.svg")).find("mix-blend-mode:screen") != std::string::npos);
}
