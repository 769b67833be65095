// The memory estimate (algorithms/methods/memory_estimate.h): the image estimate holds within 25%
// of the peak a fresh `erd generate` process measures (--stats: getrusage beside the estimate the
// memory cap compared), on the kinds of image that move the ERD peak: hard-edged synth, the same
// synth with soft edges (the edge-richest step 1), and a 16-bit heightmap; and it never exceeds
// the size bound.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "algorithms/imaging/synth.h"
#include "algorithms/methods/memory_estimate.h"
#include "algorithms/methods/methods.h"
#include "cli/memory_cap.h"
#include "tests/output_util.h"
#include "tests/synth_util.h"

using namespace erd;
using namespace output_test;

TEST_CASE("memory estimate: within 25% of the measured peak of erd generate", "[memory]") {
    if (!erd_test::need_binary()) return;
    if (std::getenv("ERD_SANITIZED")) {
        // The sanitizers' shadow memory and quarantine multiply every peak; the plain build's
        // run of this test is the check.
        WARN("sanitized build: the estimate is fitted to the plain binary's peaks, not compared here");
        return;
    }
    using namespace erd_test;
    TempDir dir;
    const std::string synth = dir.file("s.pgm"), height = dir.file("h.pgm");
    REQUIRE(run_erd("synth -q -W 640 -H 480 -o " + sh_quote(synth)).status == 0);
    REQUIRE(run_erd("synth -q -W 640 -H 480 --bits 16 --no-noise -o " + sh_quote(height)).status == 0);
    struct Case {
        const char* image;
        const char* method;
        const char* flags;
    };
    const Case cases[] = {
        {"s", "gpi", ""},     {"s", "ed", ""},     {"s", "erded", ""}, {"s", "erdgpi", ""},
        {"s", "erdgpi", "--edges soft"},           {"s", "erded", "--edges soft"},
        {"h", "gpi", ""},     {"h", "erdgpi", ""},
    };
    for (const Case& c : cases) {
        const std::string img = c.image[0] == 's' ? synth : height;
        INFO(c.image << " " << c.method << " " << c.flags);
        RunResult r = run_erd(std::string("generate -q -x 2 -d 1 -m ") + c.method + " " + c.flags + " -i " + sh_quote(img) +
                              " -o " + sh_quote(dir.file("out")) + " --stats " + sh_quote(dir.file("st.json")));
        INFO(r.err);
        REQUIRE(r.status == 0);
        Json j = parse_json(slurp(dir.file("st.json")));
        const double peak = j["peak_memory_bytes"].n, est = j["memory_estimate_bytes"].n;
        INFO("peak " << peak << " estimate " << est);
        REQUIRE(peak > 1e6);
        CHECK(std::fabs(est / peak - 1.0) <= 0.25);
    }
}

TEST_CASE("memory estimate: never above the size bound, grows with the edges", "[memory]") {
    Image flat(300, 200, 255);
    for (auto& s : flat.samples) s = 90;
    Image busy = erd_test::synth_image(300, 200);
    GenerateOptions o;
    o.density = 1;
    o.density_given = true;
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    for (std::size_t i = 0; i < count; ++i) {
        INFO(table[i].name);
        for (const Image* im : {&flat, &busy}) {
            const std::size_t e = memory_estimate(table[i], *im, o);
            CHECK(e > 0);
            CHECK(e <= memory_bound(table[i], im->width, im->height, 1, o));
        }
    }
    // Soft edges on the noisy synth: step 1 keeps most of the half-pixel grid, a flat image none.
    o.edges = EdgeChoice::soft;
    const MethodInfo* erdgpi = find_method("erdgpi");
    REQUIRE(erdgpi);
    const ErdMemoryBasis fb = erd_memory_basis(flat, o, 600, false), bb = erd_memory_basis(busy, o, 600, false);
    CHECK(fb.beta == 0.055);  // the simple test's detection is the widest at 1%
    CHECK(bb.kept > 10 * fb.kept);
    CHECK(memory_estimate(*erdgpi, busy, o) > memory_estimate(*erdgpi, flat, o));
}

// The default cap is what the machine has available: a MemAvailable that did not parse would be 0,
// which means no cap at all, so the reader is checked against the file's own MemTotal.
TEST_CASE("memory cap: the available memory is read from /proc/meminfo", "[memory]") {
    std::FILE* f = std::fopen("/proc/meminfo", "r");
    REQUIRE(f != nullptr);
    char line[256];
    long long total_kb = 0;
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "MemTotal: %lld kB", &total_kb) == 1) break;
    std::fclose(f);
    REQUIRE(total_kb > 0);
    const std::size_t avail = cli::available_memory();
    INFO("available " << avail << " bytes, MemTotal " << total_kb << " kB");
    CHECK(avail > 0);
    CHECK(avail <= std::size_t(total_kb) * 1024);
}
