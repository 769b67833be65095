// Leaks of the erd program. make test's sanitizer run (tests/run_all.sh) checks leaks in the test
// process itself and, through this file, in the erd processes of one chosen set of runs: every
// subcommand, every method, each input format, the codec, a batch over a folder, and the error
// paths that hold raw resources (stb's decoders on truncated files, fopen, opendir). The other
// tests' erd runs take ERD_CHILD_ASAN_OPTIONS (detect_leaks=0 there): LeakSanitizer's check at
// exit costs a sanitized erd process 35 ms, 31 s of that run's ~900 processes (DECISIONS
// "Testing").
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "tests/erd_run.h"

namespace {

using erd_test::sh_quote;
using erd_test::spit;
using erd_test::TempDir;

// The erd runs of the other tests get ERD_CHILD_ASAN_OPTIONS as their ASAN_OPTIONS. This process
// parsed its own ASAN_OPTIONS before any static initialiser ran, so it keeps them.
const bool child_options_set = [] {
    const char* o = std::getenv("ERD_CHILD_ASAN_OPTIONS");
    return o && ::setenv("ASAN_OPTIONS", o, 1) == 0;
}();

struct Run {
    const char* args;  // after "erd "
    int status;        // the exit status it must have
};

}  // namespace

TEST_CASE("the erd program leaks nothing on any subcommand, method, format or error path (LeakSanitizer in sanitized runs)",
          "[robust][leaks]") {
    if (!erd_test::need_binary()) return;
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    const std::string jpeg = erd_test::absolute("fuzz/corpus/fuzz_jpeg");  // the commands run in a temporary folder
    if (!erd_test::have_input(erd_test::exists(jpeg + "/rgb_16x8_420.jpg"),
                              jpeg + " not found: run the tests from the repository root"))
        return;
    TempDir t;
    // A colour image with a soft disc and a hard step (P6, 40 x 32).
    std::string ppm = "P6\n40 32\n255\n";
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 40; ++x) {
            const int d = (x - 14) * (x - 14) + (y - 15) * (y - 15);
            ppm += char(d < 90 ? 220 : 40 + 3 * y);
            ppm += char(x > 25 ? 200 : 60 + 2 * x);
            ppm += char((x + y) % 7 * 30);
        }
    spit(t.file("c.ppm"), ppm);
    spit(t.file("bad.erd"), "erd-model 1\nthis is not a model\n");
    spit(t.file("bad.txt"), "erd-polylines 1\n3\n0 0\n");
    const std::string env = sanitized ? "ASAN_OPTIONS=detect_leaks=1 " : "";
    auto check = [&](const Run& r) {
        std::string args = r.args;
        const std::size_t at = args.find("JPEG/");
        if (at != std::string::npos) args.replace(at, 4, sh_quote(jpeg));
        const erd_test::RunResult res = erd_test::run_in(t.path, env + sh_quote(erd_test::erd_bin()) + " " + args);
        INFO("erd " << args << "\nstderr: " << res.err);
        CHECK(res.err.find("LeakSanitizer") == std::string::npos);
        CHECK(res.status == r.status);
    };
    check({"synth -W 48 -H 40 -o g.pgm", 0});
    check({"synth -W 48 -H 40 --bits 16 -o h.png", 0});
    // A PNG cut short (stb's error path), and a folder holding it beside a good image.
    const std::string png = erd_test::slurp(t.file("h.png"));
    REQUIRE(png.size() > 60);
    REQUIRE(erd_test::run_in(t.path, "mkdir many && cp g.pgm many/a.pgm").status == 0);
    spit(t.file("cut.png"), png.substr(0, 60));
    spit(t.file("many/b.png"), png.substr(0, 60));
    const std::vector<Run> runs = {
        {"info g.pgm", 0},
        {"info cut.png", 2},
        {"info h.png --json", 0},
        {"info c.ppm", 0},
        {"info JPEG/rgb_16x8_420.jpg", 0},
        {"info JPEG/truncated.jpg", 2},
        {"info missing.pgm", 2},
        {"generate -q -x 2 -m ed -i g.pgm -d 5 -o ed.model", 0},
        {"generate -q -x 2 -m gpi -i g.pgm -d 5 -o gpi.model --optimize -t gpi.tri", 0},
        {"generate -q -x 2 -m erded -i g.pgm -d 5 -o erded.erd -p erded.txt --stats s.json", 0},
        {"generate -q -x 2 -m erdgpi -i h.png -d 5 -o erdgpi.erd --edges soft --psnr-report", 0},
        {"generate -q -x 2 -m erdgpi -i c.ppm -o c.erdz --step-psnr 24 --choose-density", 0},
        {"generate -q -x 2 -m erded -i JPEG/rgb_16x8_420.jpg -d 20 -o j.erd --thesis", 0},
        {"generate -q -x 2 -m erdgpi -i g.pgm -d 5 -o k.erd --constraints erded.txt --no-detect", 0},
        {"generate -q -x 2 -m erdgpi -i g.pgm -d 5 -o k.erd --constraints bad.txt", 2},
        {"generate -q -m gpi -i g.pgm -n 99999 -o big.model", 2},
        {"generate -q -m gpi -i g.pgm -d 5 -o x.model --no-such-flag", 2},
        {"generate -q -x 2 -m gpi -i many -o 'out/{name}.model' --summary sum.csv", 1},
        {"reconstruct erdgpi.erd -o r.png", 0},
        {"reconstruct c.erdz -o r.ppm --no-aa", 0},
        {"reconstruct bad.erd -o r2.pgm", 2},
        {"psnr g.pgm r.png --json", 2},
        {"psnr c.ppm r.ppm --channels", 0},
        {"edges g.pgm -o e.pgm -p e.txt", 0},
        {"render erded.erd -o m.svg --vector", 0},
        {"render gpi.model -o m.png --vertices --error g.pgm", 0},
        {"export gpi.model -o m.stl --zscale 0.5 --base 2", 0},
        {"export erdgpi.erd -o m.stl --base 2", 2},
        {"export erdgpi.erd -o m.ply", 0},
        {"convert erded.erd e.erdz --step-psnr 30 -i g.pgm", 0},
        {"convert e.erdz e2.erd", 0},
        {"info e.erdz --json", 0},
    };
    for (const Run& r : runs) check(r);
}
