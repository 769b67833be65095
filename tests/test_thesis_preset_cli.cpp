// `erd generate` flags of the ERD methods that choose between the thesis's method and ours:
// --thesis, --wedge-fit, --alpha-min/--alpha-max, --edge-zero-radius (through the real binary).
#include <catch2/catch.hpp>

#include <string>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// A 40x32 8-bit P2 image: a bright disc and a diagonal step on a textured ramp, so step 1 finds edges and
// vertices with several wedges.
std::string scene_pgm() {
    const int w = 40, h = 32;
    std::string s = "P2\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int v = 30 + 2 * x + (x * 7 + y * 13) % 11;
            if (x + y > 38) v += 90;
            if ((x - 12) * (x - 12) + (y - 12) * (y - 12) < 49) v = 240;
            s += std::to_string(v > 255 ? 255 : v) + (x + 1 < w ? " " : "\n");
        }
    }
    return s;
}

}  // namespace

TEST_CASE("generate --thesis is the thesis's settings; our defaults differ; flags after it override", "[erd]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("scene.pgm");
    spit(img, scene_pgm());
    auto gen = [&](const std::string& method, const std::string& flags, const std::string& name) {
        const std::string out = dir.file(name);
        const RunResult r =
            run_erd("generate -q -m " + method + " -i " + sh_quote(img) + " -n 120 -o " + sh_quote(out) + " " + flags);
        INFO(method << " " << flags << ": " << r.err);
        REQUIRE(r.status == 0);
        return slurp(out);
    };
    for (const std::string m : {"erdgpi", "erded"}) {
        INFO(m);
        const std::string thesis = gen(m, "--thesis", m + "-t.erd");
        const std::string spelled =
            gen(m, "--wedge-fit 0 --flips 0 --alpha-min 1 --alpha-max 1.5 --edge-zero-radius 0 --edges soft --aa-errors 1 --lower-beta 1", m + "-s.erd");
        const std::string ours = gen(m, "", m + "-d.erd");
        const std::string ours_spelled =
            gen(m, "--thesis --wedge-fit 6 --flips 2 --moves 2 --alpha-min 0.75 --alpha-max 1 --edge-zero-radius 1 --edges auto --aa-errors 0 --lower-beta 1", m + "-o.erd");
        CHECK(!thesis.empty());
        CHECK(thesis == spelled);
        CHECK(thesis != ours);
        CHECK(ours == ours_spelled);
    }
    // Only the refit differs: same mesh, other wedge values.
    const std::string fit0 = gen("erdgpi", "--wedge-fit 0", "f0.erd");
    CHECK(fit0 != gen("erdgpi", "", "f6.erd"));
}

TEST_CASE("generate rejects a reversed or out-of-range line-search range and refit count", "[erd]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("scene.pgm");
    spit(img, scene_pgm());
    const std::string base = "generate -q -m erdgpi -i " + sh_quote(img) + " -n 60 -o " + sh_quote(dir.file("x.erd"));
    for (const char* bad : {"--alpha-min 1.5 --alpha-max 1", "--alpha-min -1", "--alpha-max 100",
                            "--wedge-fit -1", "--edge-zero-radius -2", "--alpha-min x", "--flips -1", "--wedge-prior -1"}) {
        INFO(bad);
        const RunResult r = run_erd(base + " " + bad);
        CHECK(r.status == 2);
        CHECK(r.err.find("erd generate") != std::string::npos);
        CHECK_FALSE(exists(dir.file("x.erd")));
    }
    const RunResult help = run_erd("generate --help");
    CHECK(help.status == 0);
    for (const char* flag : {"--thesis", "--wedge-fit", "--alpha-min", "--alpha-max", "--edge-zero-radius"})
        CHECK(help.out.find(flag) != std::string::npos);
}
