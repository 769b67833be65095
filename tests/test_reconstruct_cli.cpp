// `erd reconstruct` through the real binary (ERD_BIN): stdout, -o, --plain, --no-aa, stdin,
// and the "erd reconstruct: FILE: problem" lines with exit status 2.
#include <catch2/catch.hpp>

#include <string>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// 2x2 image, z = 10 + 8x: point evaluation 10 18 / 10 18 (see test_reconstruct.cpp).
const char* kModel = "255\n4\n0 0 10\n1 0 18\n0 1 10\n1 1 18\n2\n0 1 3\n0 3 2\n";
// The same function as an .erd (doubled coordinates, no wedge lines): supersampled 11 17.
const char* kErd = "255\n4\n0 0 10\n2 0 18\n0 2 10\n2 2 18\n2\n0 1 3\n0 3 2\n0\n";

}  // namespace

TEST_CASE("reconstruct CLI: .model to stdout, -o, --plain", "[model_io]") {
    if (!need_binary()) return;
    TempDir d;
    spit(d.file("a.model"), kModel);
    RunResult r = run_erd("reconstruct " + sh_quote(d.file("a.model")));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == std::string("P5\n2 2\n255\n") + char(10) + char(18) + char(10) + char(18));
    r = run_erd("reconstruct " + sh_quote(d.file("a.model")) + " -o " + sh_quote(d.file("out.pgm")));
    CHECK(r.status == 0);
    CHECK(r.out.empty());
    CHECK(slurp(d.file("out.pgm")) == std::string("P5\n2 2\n255\n") + char(10) + char(18) + char(10) + char(18));
    r = run_erd("reconstruct --plain " + sh_quote(d.file("a.model")));
    CHECK(r.out == "P2\n2 2\n255\n10 18 10 18\n");
    // stdin, kind told from the content.
    r = run_erd("reconstruct --plain < " + sh_quote(d.file("a.model")));
    CHECK(r.out == "P2\n2 2\n255\n10 18 10 18\n");
}

TEST_CASE("reconstruct CLI: .erd supersampled unless --no-aa", "[model_io]") {
    if (!need_binary()) return;
    TempDir d;
    spit(d.file("a.erd"), kErd);
    RunResult r = run_erd("reconstruct --plain " + sh_quote(d.file("a.erd")));
    CHECK(r.status == 0);
    CHECK(r.out == "P2\n2 2\n255\n11 17 11 17\n");
    r = run_erd("reconstruct --plain --no-aa " + sh_quote(d.file("a.erd")));
    CHECK(r.out == "P2\n2 2\n255\n10 18 10 18\n");
    r = run_erd("reconstruct - --plain < " + sh_quote(d.file("a.erd")));
    CHECK(r.out == "P2\n2 2\n255\n11 17 11 17\n");
    r = run_erd("reconstruct " + sh_quote(d.file("a.erd")) + " -o " + sh_quote(d.file("a.png")));
    CHECK(r.status == 0);
    CHECK(slurp(d.file("a.png")).substr(1, 3) == "PNG");
}

TEST_CASE("reconstruct CLI: bad input is one line and exit status 2", "[model_io]") {
    if (!need_binary()) return;
    TempDir d;
    const std::string bad = d.file("bad.model");
    spit(bad, "255\n4\n0 0 10\n1 0 18\n0 1 10\n1 1 18\n2\n0 1 3\n0 3 9\n");
    RunResult r = run_erd("reconstruct " + sh_quote(bad) + " -o " + sh_quote(d.file("o.pgm")));
    CHECK(r.status == 2);
    CHECK(r.err == "erd reconstruct: " + bad + ": line 9: face 1: vertex index 9 out of range (4 vertices)\n");
    CHECK_FALSE(exists(d.file("o.pgm")));
    const std::string hole = d.file("hole.model");
    // Every vertex in a face (else the reader refuses it first), one face of the fan missing.
    spit(hole, "255\n5\n0 0 10\n2 0 18\n0 2 10\n2 2 18\n1 1 14\n3\n0 1 4\n1 3 4\n3 2 4\n");
    r = run_erd("reconstruct " + sh_quote(hole));
    CHECK(r.status == 2);
    CHECK(r.err == "erd reconstruct: " + hole +
                       ": not a triangulation of the image domain: the faces leave holes (their areas add up to less than the rectangle)\n");
    const std::string lone = d.file("lone.model");
    spit(lone, "255\n4\n0 0 10\n1 0 18\n0 1 10\n1 1 18\n1\n0 1 3\n");
    r = run_erd("reconstruct " + sh_quote(lone));
    CHECK(r.status == 2);
    CHECK(r.err == "erd reconstruct: " + lone + ": line 5: vertex 2 (0, 1) belongs to no face\n");
    r = run_erd("reconstruct " + sh_quote(d.file("missing.erd")));
    CHECK(r.status == 2);
    CHECK(r.err.find("erd reconstruct: ") == 0);
    CHECK(r.err.find("missing.erd") != std::string::npos);
    r = run_erd("reconstruct a b");
    CHECK(r.status == 2);
}
