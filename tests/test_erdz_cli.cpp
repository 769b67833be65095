// The .erdz file through the erd program: generate writes it by name, reconstruct / render /
// convert / info read it (also from stdin), convert goes both ways, and bad files or misplaced
// flags get one line and exit 2. Small synthetic images (about a second).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/erd_run.h"

using namespace erd_test;

TEST_CASE("erdz through the CLI: generate, info, reconstruct, convert both ways", "[erdz][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("s.pgm"), z = dir.file("m.erdz");
    REQUIRE(run_erd("synth -W 64 -H 48 -o " + sh_quote(img)).status == 0);
    RunResult g = run_erd("generate --method erdgpi -i " + sh_quote(img) + " -d 3 -o " + sh_quote(z) + " --step 2");
    INFO(g.err);
    REQUIRE(g.status == 0);
    RunResult info = run_erd("info " + sh_quote(z));
    REQUIRE(info.status == 0);
    CHECK(info.out.find("method erdgpi") != std::string::npos);
    CHECK(info.out.find("positions:") != std::string::npos);
    CHECK(info.out.find("step:      2 (values within 1)") != std::string::npos);
    RunResult j = run_erd("info --json " + sh_quote(z));
    CHECK(j.out.find("\"total_bits\":") != std::string::npos);
    // Reconstruct from the file and from stdin: the same image.
    REQUIRE(run_erd("reconstruct " + sh_quote(z) + " -o " + sh_quote(dir.file("a.pgm"))).status == 0);
    REQUIRE(run_shell(sh_quote(erd_bin()) + " reconstruct -o " + sh_quote(dir.file("b.pgm")) + " < " + sh_quote(z)).status == 0);
    CHECK(slurp(dir.file("a.pgm")) == slurp(dir.file("b.pgm")));
    CHECK(run_erd("render " + sh_quote(z) + " -o " + sh_quote(dir.file("m.svg"))).status == 0);
    // .erdz -> .erd -> .erdz at the same step: the same model (values already on the step), so
    // the same reconstruction.
    REQUIRE(run_erd("convert -q " + sh_quote(z) + " " + sh_quote(dir.file("m.erd"))).status == 0);
    REQUIRE(run_erd("convert -q " + sh_quote(dir.file("m.erd")) + " " + sh_quote(dir.file("n.erdz")) + " --step 2 -m erdgpi").status == 0);
    REQUIRE(run_erd("reconstruct " + sh_quote(dir.file("n.erdz")) + " -o " + sh_quote(dir.file("c.pgm"))).status == 0);
    CHECK(slurp(dir.file("a.pgm")) == slurp(dir.file("c.pgm")));
    // A PSNR target through convert.
    RunResult t = run_erd("convert " + sh_quote(dir.file("m.erd")) + " " + sh_quote(dir.file("t.erdz")) + " --step-psnr 20 -i " + sh_quote(img));
    CHECK(t.status == 0);
    CHECK(t.err.find("encodings") != std::string::npos);
}

TEST_CASE("erdz through the CLI: bad files and misplaced flags", "[erdz][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("s.pgm"), z = dir.file("m.erdz");
    REQUIRE(run_erd("synth -W 48 -H 32 -o " + sh_quote(img)).status == 0);
    REQUIRE(run_erd("generate -q --method gpi -i " + sh_quote(img) + " -d 3 -o " + sh_quote(z)).status == 0);
    const std::string bytes = slurp(z);
    spit(dir.file("cut.erdz"), bytes.substr(0, bytes.size() - 3));
    RunResult r = run_erd("reconstruct " + sh_quote(dir.file("cut.erdz")) + " -o " + sh_quote(dir.file("x.pgm")));
    CHECK(r.status == 2);
    CHECK(r.err.find("cut.erdz: ") != std::string::npos);
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK(!exists(dir.file("x.pgm")));
    RunResult s = run_erd("generate -q --method gpi -i " + sh_quote(img) + " -o " + sh_quote(dir.file("m.model")) + " --step 3");
    CHECK(s.status == 2);
    CHECK(s.err.find(".erdz outputs only") != std::string::npos);
    RunResult k = run_erd("convert " + sh_quote(z) + " " + sh_quote(dir.file("m.erd")));
    CHECK(k.status == 2);
    CHECK(k.err.find("basic model") != std::string::npos);
}

namespace {

// The last "X bpp, Y dB" of an erdz note line (generate -v).
bool note_figures(const std::string& err, const std::string& lead, double* bpp, double* db) {
    const std::size_t at = err.rfind(lead);
    if (at == std::string::npos) return false;
    const std::size_t line_end = err.find('\n', at);
    const std::string line = err.substr(at, line_end == std::string::npos ? std::string::npos : line_end - at);
    const std::size_t unit = line.rfind(" bpp, ");
    if (unit == std::string::npos || unit == 0) return false;
    const std::size_t start = line.rfind(' ', unit - 1) + 1;
    return std::sscanf(line.c_str() + start, "%lf bpp, %lf dB", bpp, db) == 2;
}

}  // namespace

TEST_CASE("erdz through the CLI: --choose-density trades the point count against the step", "[erdz][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("s.pgm");
    REQUIRE(run_erd("synth -W 128 -H 96 -o " + sh_quote(img)).status == 0);
    const std::string gen = "generate -v --method erdgpi -i " + sh_quote(img) + " ";
    // A size target: the chosen file fits and reconstructs at least as well as the fixed 2%
    // (one of the densities tried) within the same size.
    RunResult fixed = run_erd(gen + "-d 2 --bpp 0.5 -o " + sh_quote(dir.file("f.erdz")));
    REQUIRE(fixed.status == 0);
    RunResult chosen = run_erd(gen + "--bpp 0.5 --choose-density -o " + sh_quote(dir.file("c.erdz")));
    INFO(chosen.err);
    REQUIRE(chosen.status == 0);
    double fb = 0, fdb = 0, cb = 0, cdb = 0;
    REQUIRE(note_figures(fixed.err, "erdz: step", &fb, &fdb));
    REQUIRE(note_figures(chosen.err, "erdz: density", &cb, &cdb));
    CHECK(chosen.err.find("tried 2%:") != std::string::npos);
    CHECK(cb <= 0.5);
    CHECK(cdb >= fdb);
    // The note's PSNR is the file's: reconstruct it and measure.
    REQUIRE(run_erd("reconstruct " + sh_quote(dir.file("c.erdz")) + " -o " + sh_quote(dir.file("c.pgm"))).status == 0);
    RunResult p = run_erd("psnr " + sh_quote(img) + " " + sh_quote(dir.file("c.pgm")));
    REQUIRE(p.status == 0);
    CHECK(std::abs(std::stod(p.out) - cdb) < 1e-3);
    RunResult j = run_erd("info --json " + sh_quote(dir.file("c.erdz")));
    const std::size_t tb = j.out.find("\"total_bits\":");
    REQUIRE(tb != std::string::npos);
    CHECK(std::stod(j.out.substr(tb + 13)) / (128.0 * 96.0) <= 0.5);
    // A quality target: the chosen file reaches it and is no larger than the fixed 2%'s.
    fixed = run_erd(gen + "-d 2 --step-psnr 35 -o " + sh_quote(dir.file("f2.erdz")));
    REQUIRE(fixed.status == 0);
    chosen = run_erd(gen + "--step-psnr 35 --choose-density -o " + sh_quote(dir.file("c2.erdz")));
    REQUIRE(chosen.status == 0);
    REQUIRE(note_figures(fixed.err, "erdz: step", &fb, &fdb));
    REQUIRE(note_figures(chosen.err, "erdz: density", &cb, &cdb));
    CHECK(cdb >= 35.0);
    CHECK(cb <= fb);
    // Unreachable targets and misplaced flags: one line, exit 2.
    RunResult r = run_erd(gen + "--step-psnr 200 --choose-density -o " + sh_quote(dir.file("x.erdz")));
    CHECK(r.status == 2);
    CHECK(r.err.find("no density up to 8% reaches 200 dB") != std::string::npos);
    CHECK(!exists(dir.file("x.erdz")));
    CHECK(run_erd(gen + "--choose-density -o " + sh_quote(dir.file("x.erdz"))).status == 2);
    CHECK(run_erd(gen + "-d 1 --bpp 0.5 --choose-density -o " + sh_quote(dir.file("x.erdz"))).status == 2);
    CHECK(run_erd(gen + "--bpp 0.5 --choose-density -o " + sh_quote(dir.file("x.erd"))).status == 2);
}
