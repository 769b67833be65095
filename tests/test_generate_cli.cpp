// `erd generate` through the real binary (ERD_BIN): outputs, exit modes 0/1/2, bad flags.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_io.h"
#include "cli/image_io.h"
#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// 24 x 18, a bump and a step: GPI and ED reach any N here.
std::string textured_pgm() {
    erd::Image im(24, 18, 255);
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 24; ++x)
            im.at(x, y) = std::uint16_t(std::lround(100 + 60 * std::sin(x / 3.0) * std::cos(y / 4.0) + (x > 11 ? 40 : 0)));
    return erd::cli::encode_pnm(im, false);
}

// An exact plane: GPI stops at the four corners.
std::string planar_pgm() {
    erd::Image im(20, 10, 255);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 20; ++x) im.at(x, y) = std::uint16_t(10 + 5 * x + 3 * y);
    return erd::cli::encode_pnm(im, false);
}

}  // namespace

TEST_CASE("generate gpi and ed: exact N, model and triangulation files", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("in.pgm"), textured_pgm());
    for (const char* method : {"gpi", "ed"}) {
        INFO(method);
        std::string m = dir.file(std::string(method) + ".model"), t = dir.file(std::string(method) + ".tri");
        RunResult r = run_erd("generate --method " + std::string(method) + " -i " + sh_quote(dir.file("in.pgm")) +
                              " -n 40 -o " + sh_quote(m) + " -t " + sh_quote(t) + " -q");
        INFO(r.err);
        REQUIRE(r.status == 0);
        CHECK(r.err.empty());
        erd::Model model;
        REQUIRE(erd::read_model(slurp(m), erd::ModelFileKind::basic, &model).ok());
        CHECK(model.size() == 40);
        CHECK(model.width == 24);
        CHECK(model.height == 18);
        erd::Model tri;
        REQUIRE(erd::read_triangulation(slurp(t), &tri).ok());
        CHECK(tri.vertices == model.vertices);
        CHECK(tri.faces.size() == model.faces.size());
        CHECK(tri.constraints.empty());
    }
}

TEST_CASE("generate: reconstruct reproduces the samples at every vertex", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    std::string pgm = textured_pgm();
    spit(dir.file("in.pgm"), pgm);
    RunResult r = run_erd("generate --method gpi -i " + sh_quote(dir.file("in.pgm")) + " -n 60 -o " +
                          sh_quote(dir.file("m.model")) + " -q");
    REQUIRE(r.status == 0);
    r = run_erd("reconstruct " + sh_quote(dir.file("m.model")) + " -o " + sh_quote(dir.file("r.pgm")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    erd::Image orig, rec;
    std::string w = slurp(dir.file("r.pgm"));
    REQUIRE(erd::cli::decode_pnm(reinterpret_cast<const unsigned char*>(pgm.data()), pgm.size(), &orig, nullptr).ok());
    REQUIRE(erd::cli::decode_pnm(reinterpret_cast<const unsigned char*>(w.data()), w.size(), &rec, nullptr).ok());
    erd::Model model;
    REQUIRE(erd::read_model(slurp(dir.file("m.model")), erd::ModelFileKind::basic, &model).ok());
    for (erd::LatticePoint p : model.vertices) REQUIRE(rec.at(p.x / 2, p.y / 2) == orig.at(p.x / 2, p.y / 2));
}

TEST_CASE("generate: same input, same output bytes", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("in.pgm"), textured_pgm());
    for (const char* method : {"gpi", "ed"}) {
        std::string base = "generate --method " + std::string(method) + " -i " + sh_quote(dir.file("in.pgm")) + " -d 20 -q -o ";
        REQUIRE(run_erd(base + sh_quote(dir.file("a"))).status == 0);
        REQUIRE(run_erd(base + sh_quote(dir.file("b"))).status == 0);
        CHECK(slurp(dir.file("a")) == slurp(dir.file("b")));
        CHECK(!slurp(dir.file("a")).empty());
    }
}

TEST_CASE("generate: exit modes when N is not reached", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("plane.pgm"), planar_pgm());
    const std::string line = "target sampling density not achieved exactly (requested 50 but got 4)\n";
    const std::string base = "generate --method gpi -q -n 50 -i " + sh_quote(dir.file("plane.pgm")) + " -o ";

    RunResult r = run_erd(base + sh_quote(dir.file("x0.model")));  // default -x 0
    CHECK(r.status == 3);
    CHECK(r.err == "ERROR: " + line);
    CHECK_FALSE(exists(dir.file("x0.model")));

    r = run_erd(base + sh_quote(dir.file("x1.model")) + " -x 1");
    CHECK(r.status == 0);
    CHECK(r.err == "WARNING: " + line);
    CHECK(exists(dir.file("x1.model")));

    r = run_erd(base + sh_quote(dir.file("x2.model")) + " --exit-mode 2");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    erd::Model model;
    REQUIRE(erd::read_model(slurp(dir.file("x2.model")), erd::ModelFileKind::basic, &model).ok());
    CHECK(model.size() == 4);
}

TEST_CASE("generate: -o - writes the model to stdout", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("in.pgm"), textured_pgm());
    RunResult r = run_erd("generate --method gpi -q -n 12 -i " + sh_quote(dir.file("in.pgm")) + " -o -");
    REQUIRE(r.status == 0);
    erd::Model model;
    REQUIRE(erd::read_model(r.out, erd::ModelFileKind::basic, &model).ok());
    CHECK(model.size() == 12);
}

TEST_CASE("generate: bad flags and impossible requests exit 2 with one line", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("in.pgm"), textured_pgm());
    const std::string in = " -i " + sh_quote(dir.file("in.pgm"));
    const std::string out = " -o " + sh_quote(dir.file("o.model"));
    struct Case {
        std::string args;
        std::string expect;  // a piece of the first stderr line
    };
    const Case cases[] = {
        {"--method gpi" + in + out + " --bogus", "unknown option --bogus"},
        {"--method gpi" + in + out + " -n 3", "below 4"},
        {"--method gpi" + in + out + " -n 433", "exceeds the 432 pixels"},
        {"--method gpi" + in + out + " -d 0", "0 is outside (0, 100]"},
        {"--method gpi" + in + out + " -d -2", "-2 is outside (0, 100]"},
        {"--method gpi" + in + out + " -d abc", "not a number"},
        {"--method gpi" + in + out + " -n 1.5", "not an integer"},
        {"--method gpi" + in + out + " -x 3", "exit-mode"},
        {"--method gpi" + in + out + " --psnr -1", "--psnr"},
        {"--method nonesuch" + in + out, "available: ed, gpi"},
        {"--method gpi" + out + " </dev/null", "stdin"},  // no -i: stdin, empty here
        {"--method gpi" + in, "-o OUT is required"},
        {in + out, "--method is required"},
        {"--method gpi" + in + " -o " + sh_quote(dir.file("in.pgm")), "in.pgm"},
        {"--method gpi -i " + sh_quote(dir.file("missing.pgm")) + out, "missing.pgm"},
    };
    for (const Case& c : cases) {
        INFO(c.args);
        RunResult r = run_erd("generate " + c.args);
        INFO(r.err);
        CHECK(r.status == 2);
        CHECK(r.err.rfind("erd generate: ", 0) == 0);
        CHECK(r.err.substr(0, r.err.find('\n')).find(c.expect) != std::string::npos);
        CHECK_FALSE(exists(dir.file("o.model")));
    }
    CHECK(slurp(dir.file("in.pgm")) == textured_pgm());
}

TEST_CASE("generate --stats and --psnr-report", "[generate][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    spit(dir.file("in.pgm"), textured_pgm());
    RunResult r = run_erd("generate --method gpi -n 30 -i " + sh_quote(dir.file("in.pgm")) + " -o " +
                          sh_quote(dir.file("m.model")) + " --stats " + sh_quote(dir.file("s.json")) + " --psnr-report");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("erd generate: psnr: ") != std::string::npos);
    std::string json = slurp(dir.file("s.json"));
    CHECK(json.find("\"method\":\"gpi\"") != std::string::npos);
    CHECK(json.find("\"points\":{\"requested\":30,\"achieved\":30}") != std::string::npos);
    CHECK(json.find("\"stop\":\"target\"") != std::string::npos);
    CHECK(json.find("\"psnr\":") != std::string::npos);
    CHECK(json.find("\"psnr\":null") == std::string::npos);
}
