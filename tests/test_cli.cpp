// The erd program as a user meets it: help, version, usage errors, atomic output, the
// output-equals-input rule, psnr by hand-computed examples, and synth determinism.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <string>
#include <vector>

#include "algorithms/model/metrics.h"
#include "algorithms/imaging/synth.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "tests/erd_run.h"

using erd::Image;
using namespace erd_test;

namespace {
Image make(int w, int h, std::uint32_t maxval, std::vector<std::uint16_t> v) {
    Image im(w, h, maxval);
    im.samples = std::move(v);
    return im;
}
}  // namespace

TEST_CASE("erd help, --help, --version, help SUB, SUB --help", "[cli]") {
    if (!need_binary()) return;
    RunResult h = run_erd("help");
    CHECK(h.status == 0);
    for (const char* sub : {"generate", "reconstruct", "psnr", "info", "synth"}) CHECK_THAT(h.out, Catch::Contains(sub));
    CHECK_THAT(h.out, Catch::Contains("Exit status"));
    CHECK(run_erd("--help").status == 0);
    RunResult v = run_erd("--version");
    CHECK(v.status == 0);
    CHECK_THAT(v.out, Catch::StartsWith("erd "));
    for (const char* sub : {"info", "psnr", "synth"}) {
        INFO(sub);
        RunResult a = run_erd(std::string("help ") + sub);
        RunResult b = run_erd(std::string(sub) + " --help");
        CHECK(a.status == 0);
        CHECK(b.status == 0);
        CHECK_THAT(a.out, Catch::StartsWith(std::string("usage: erd ") + sub));
        CHECK(a.out == b.out);
        CHECK_THAT(a.out, Catch::Contains("Options:"));
    }
    RunResult none = run_erd("");
    CHECK(none.status == 2);
    CHECK_THAT(none.err, Catch::Contains("usage: erd SUBCOMMAND"));
}

TEST_CASE("unknown subcommand: did you mean; bad options: usage and exit 2", "[cli]") {
    if (!need_binary()) return;
    RunResult r = run_erd("synht");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("'synht' is not a subcommand"));
    CHECK_THAT(r.err, Catch::Contains("Did you mean 'synth'?"));
    RunResult p = run_erd("psnt a b");
    CHECK_THAT(p.err, Catch::Contains("Did you mean 'psnr'?"));
    CHECK(run_erd("help nosuch").status == 2);

    struct Bad { const char* args; const char* fragment; };
    const Bad bad[] = {
        {"info --bogus x.pgm", "erd info: unknown option --bogus"},
        {"info", "erd info: expected one IMAGE"},
        {"info a.pgm b.pgm", "erd info: expected one IMAGE"},
        {"psnr a.pgm", "erd psnr: expected ORIGINAL and APPROX"},
        {"psnr - -", "only one of the images can be stdin"},
        {"synth -W abc -o x.pgm", "erd synth: --width: 'abc' is not an integer"},
        {"synth -W 0 -o x.pgm", "erd synth: --width: 0 is outside [1, 32768]"},
        {"synth --bits 17 -o x.pgm", "erd synth: --bits: 17 is outside [1, 16]"},
        {"synth -W 20000 -H 20000 -o x.pgm", "above the limit of 268435456 pixels"},
        {"synth", "erd synth: missing -o FILE"},
        {"synth -o", "option --output needs a value"},
        {"synth -x -o a.pgm", "unknown option -x"},
    };
    for (const auto& b : bad) {
        INFO(b.args);
        RunResult x = run_erd(b.args);
        CHECK(x.status == 2);
        CHECK(x.out.empty());
        CHECK_THAT(x.err, Catch::Contains(b.fragment));
    }
    // Usage errors show the usage line.
    CHECK_THAT(run_erd("info --bogus").err, Catch::Contains("usage: erd info IMAGE"));
}

TEST_CASE("missing and unreadable inputs: one line, exit 2", "[cli]") {
    if (!need_binary()) return;
    TempDir dir;
    RunResult r = run_erd("info " + sh_quote(dir.file("nope.pgm")));
    CHECK(r.status == 2);
    CHECK(r.err == "erd info: " + dir.file("nope.pgm") + ": No such file or directory\n");
    RunResult d = run_erd("info " + sh_quote(dir.path));
    CHECK(d.status == 2);
    CHECK_THAT(d.err, Catch::Contains(": is a directory"));
}

TEST_CASE("read_file: whole file, cap, directory, missing", "[io]") {
    TempDir dir;
    spit(dir.file("a"), std::string("ab\0cd", 5));
    std::string bytes;
    REQUIRE(erd::cli::read_file(dir.file("a"), &bytes, 5).ok());
    CHECK(bytes == std::string("ab\0cd", 5));
    erd::Status s = erd::cli::read_file(dir.file("a"), &bytes, 4);
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains("above the limit of 4 bytes"));
    CHECK(erd::cli::read_file(dir.path, &bytes).code == erd::Code::input);
    s = erd::cli::read_file(dir.file("missing"), &bytes);
    CHECK(s.message == dir.file("missing") + ": No such file or directory");
}

TEST_CASE("write_file_atomic: replaces whole files, keeps the mode, leaves no temporary", "[io]") {
    TempDir dir;
    std::string f = dir.file("out.pgm");
    REQUIRE(erd::cli::write_file_atomic(f, "first").ok());
    CHECK(slurp(f) == "first");
    ::chmod(f.c_str(), 0640);
    REQUIRE(erd::cli::write_file_atomic(f, "second, longer").ok());
    CHECK(slurp(f) == "second, longer");
    struct stat st;
    REQUIRE(::stat(f.c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == 0640);
    CHECK(dir.listing() == "out.pgm ");
    // A new file gets 0666 less the umask, like any file a program creates.
    mode_t old_mask = ::umask(027);
    erd::Status fresh = erd::cli::write_file_atomic(dir.file("fresh"), "x");
    ::umask(old_mask);
    REQUIRE(fresh.ok());
    REQUIRE(::stat(dir.file("fresh").c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == 0640);
    REQUIRE(::unlink(dir.file("fresh").c_str()) == 0);
    // Through a symbolic link: the link stays, its target changes.
    REQUIRE(::symlink("out.pgm", dir.file("link.pgm").c_str()) == 0);
    REQUIRE(erd::cli::write_file_atomic(dir.file("link.pgm"), "third").ok());
    CHECK(slurp(f) == "third");
    REQUIRE(::lstat(dir.file("link.pgm").c_str(), &st) == 0);
    CHECK(S_ISLNK(st.st_mode));
    // A relative name in the current folder works too (no folder part).
    char* cwd = ::getcwd(nullptr, 0);
    REQUIRE(::chdir(dir.path.c_str()) == 0);
    erd::Status rel = erd::cli::write_file_atomic("plain.txt", "x");
    REQUIRE(::chdir(cwd) == 0);
    std::free(cwd);
    CHECK(rel.ok());
    CHECK(slurp(dir.file("plain.txt")) == "x");
}

TEST_CASE("write failures report the OS error and leave nothing behind", "[io]") {
    TempDir dir;
    SECTION("/dev/full") {
        if (!have_input(exists("/dev/full"), "no /dev/full here")) return;
        erd::Status s = erd::cli::write_file_atomic("/dev/full", "data");
        CHECK(s.code == erd::Code::runtime);
        CHECK(s.message == "/dev/full: No space left on device");
        struct stat st;
        REQUIRE(::stat("/dev/full", &st) == 0);
        CHECK(S_ISCHR(st.st_mode));  // still the device, not replaced by a file
    }
    SECTION("a folder we cannot write into") {
        std::string target;
        if (::geteuid() == 0) {
            // root writes through chmod 0555; a parent that is a file stops everyone.
            spit(dir.file("file"), "x");
            target = dir.file("file") + "/out.pgm";
            erd::Status s = erd::cli::write_file_atomic(target, "data");
            CHECK(s.code == erd::Code::runtime);
            CHECK(s.message == target + ": Not a directory");
            CHECK(dir.listing() == "file ");
        } else {
            std::string ro = dir.file("ro");
            REQUIRE(::mkdir(ro.c_str(), 0555) == 0);
            target = ro + "/out.pgm";
            erd::Status s = erd::cli::write_file_atomic(target, "data");
            CHECK(s.code == erd::Code::runtime);
            CHECK(s.message == target + ": Permission denied");
            CHECK(dir.listing() == "ro ");
        }
    }
    SECTION("a missing folder") {
        erd::Status s = erd::cli::write_file_atomic(dir.file("no/such/dir/x.pgm"), "data");
        CHECK(s.message == dir.file("no/such/dir/x.pgm") + ": No such file or directory");
    }
    SECTION("a folder as output") {
        erd::Status s = erd::cli::write_file_atomic(dir.path, "data");
        CHECK_THAT(s.message, Catch::Contains("is a directory"));
    }
}

TEST_CASE("printed output that cannot be written fails the run (info, psnr, help to /dev/full)", "[cli]") {
    if (!need_binary()) return;
    if (!have_input(exists("/dev/full"), "no /dev/full here")) return;
    TempDir dir;
    REQUIRE(run_erd("synth -o " + sh_quote(dir.file("a.pgm")) + " -W 8 -H 8").status == 0);
    const std::string a = sh_quote(dir.file("a.pgm"));
    for (const std::string& cmd : {"info " + a, "psnr " + a + " " + a, std::string("help")}) {
        INFO(cmd);
        RunResult r = run_shell("{ " + sh_quote(erd_bin()) + " " + cmd + " >/dev/full; }");  // braces: our redirection wins
        CHECK(r.status == 1);
        CHECK_THAT(r.err, Catch::Contains("stdout: No space left on device"));
        CHECK(run_erd(cmd).status == 0);
    }
}

TEST_CASE("erd synth: a failed write leaves no partial file and keeps the old one", "[io][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    if (exists("/dev/full")) {
        RunResult full = run_erd("synth -o /dev/full");
        CHECK(full.status == 1);
        CHECK(full.err == "erd synth: /dev/full: No space left on device\n");
    }

    // A file size limit makes the write fail midway in an ordinary folder (SIGXFSZ ignored so
    // write() returns EFBIG): the temporary file must go and the old contents stay.
    std::string f = dir.file("big.pgm");
    spit(f, "old contents");
    RunResult r = run_erd("synth -W 256 -H 256 -o " + sh_quote(f), "trap '' XFSZ; ulimit -f 8;");
    CHECK(r.status == 1);
    CHECK(r.err == "erd synth: " + f + ": File too large\n");
    CHECK(slurp(f) == "old contents");
    CHECK(dir.listing() == "big.pgm ");

    if (::geteuid() != 0) {
        std::string ro = dir.file("ro");
        REQUIRE(::mkdir(ro.c_str(), 0555) == 0);
        RunResult p = run_erd("synth -o " + sh_quote(ro + "/x.pgm"));
        CHECK(p.status == 1);
        CHECK_THAT(p.err, Catch::Contains("Permission denied"));
    } else {
        RunResult p = run_erd("synth -o " + sh_quote(f + "/x.pgm"));
        CHECK(p.status == 1);
        CHECK(p.err == "erd synth: " + f + "/x.pgm: Not a directory\n");
    }
    CHECK(dir.listing().find(".tmp") == std::string::npos);
}

TEST_CASE("refuse_overwrite: same file by inode, or by normalised path when it does not exist", "[io]") {
    TempDir dir;
    std::string a = dir.file("a.pgm");
    spit(a, "x");
    using erd::cli::refuse_overwrite;
    erd::Status s = refuse_overwrite(a, {a});
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains("output would overwrite the input"));
    CHECK_FALSE(refuse_overwrite(dir.path + "/./sub/../a.pgm", {a}).ok());
    CHECK_FALSE(refuse_overwrite(dir.path + "//a.pgm", {"other.pgm", a}).ok());
    REQUIRE(::link(a.c_str(), dir.file("hard.pgm").c_str()) == 0);
    CHECK_FALSE(refuse_overwrite(dir.file("hard.pgm"), {a}).ok());
    REQUIRE(::symlink("a.pgm", dir.file("soft.pgm").c_str()) == 0);
    CHECK_FALSE(refuse_overwrite(dir.file("soft.pgm"), {a}).ok());
    // Not existing yet: compared by normalised path.
    CHECK_FALSE(refuse_overwrite(dir.file("new.pgm"), {dir.path + "/x/../new.pgm"}).ok());
    CHECK(refuse_overwrite(dir.file("new.pgm"), {a}).ok());
    CHECK(refuse_overwrite(dir.file("b.pgm"), {a}).ok());
    CHECK(refuse_overwrite("-", {"-"}).ok());
    CHECK(refuse_overwrite("/dev/null", {"/dev/null"}).ok());
    // Relative against absolute.
    char* cwd = ::getcwd(nullptr, 0);
    REQUIRE(::chdir(dir.path.c_str()) == 0);
    bool refused = !refuse_overwrite("a.pgm", {a}).ok();
    bool refused_new = !refuse_overwrite("./new2.pgm", {dir.file("new2.pgm")}).ok();
    REQUIRE(::chdir(cwd) == 0);
    std::free(cwd);
    CHECK(refused);
    CHECK(refused_new);
}

TEST_CASE("psnr and mse by hand-computed examples", "[cli][io]") {
    struct Case { Image a, b; double mse, psnr, peak; };
    const Case cases[] = {
        // mse 1, peak 255: 10 log10(65025) = 48.1308
        {make(2, 2, 255, {0, 0, 0, 0}), make(2, 2, 255, {0, 0, 0, 2}), 1.0, 48.1308, 255},
        // (9 + 16) / 4 = 6.25: 10 log10(65025 / 6.25) = 40.1720
        {make(2, 2, 255, {0, 50, 100, 200}), make(2, 2, 255, {3, 50, 96, 200}), 6.25, 40.1720, 255},
        // maxval 1000 is 10 bits: peak 1023; mse 4: 54.1769
        {make(1, 1, 1000, {10}), make(1, 1, 1000, {12}), 4.0, 54.1769, 1023},
        // 16 bits: mse 65536 / 2, peak 65535: 51.1750
        {make(2, 1, 65535, {0, 65535}), make(2, 1, 65535, {256, 65535}), 32768.0, 51.1750, 65535},
    };
    for (const auto& c : cases) {
        double m = 0, p = 0;
        REQUIRE(erd::mse(c.a, c.b, &m).ok());
        REQUIRE(erd::psnr(c.a, c.b, &p).ok());
        CHECK(m == c.mse);
        CHECK(p == Approx(c.psnr).margin(5e-5));
        CHECK(erd::psnr_peak(c.a.maxval) == c.peak);
    }
    double p = 0;
    REQUIRE(erd::psnr(cases[0].a, cases[0].a, &p).ok());
    CHECK(std::isinf(p));
    CHECK(p > 0);
    CHECK(erd::psnr_peak(4095) == 4095);
    CHECK(erd::psnr_peak(1) == 1);
    CHECK(erd::psnr_peak(256) == 511);
    erd::Status s = erd::psnr(make(1, 1, 255, {0}), make(2, 1, 255, {0, 0}), &p);
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains("sizes differ: 1 x 1 and 2 x 1"));
    s = erd::mse(make(1, 1, 255, {0}), make(1, 1, 65535, {0}), &p);
    CHECK_THAT(s.message, Catch::Contains("maxvals differ: 255 and 65535"));
    CHECK(std::isnan(erd::psnr(make(1, 1, 255, {0}), make(2, 1, 255, {0, 0}))));
}

TEST_CASE("erd psnr prints 4 decimals, inf, JSON, and refuses mismatches", "[cli]") {
    if (!need_binary()) return;
    TempDir dir;
    REQUIRE(erd::cli::write_image(dir.file("a.pgm"), make(2, 2, 255, {0, 50, 100, 200})).ok());
    REQUIRE(erd::cli::write_image(dir.file("b.png"), make(2, 2, 255, {3, 50, 96, 200})).ok());
    REQUIRE(erd::cli::write_image(dir.file("c.pgm"), make(3, 2, 255, {0, 0, 0, 0, 0, 0})).ok());
    REQUIRE(erd::cli::write_image(dir.file("d.pgm"), make(2, 2, 1023, {0, 50, 100, 200})).ok());
    std::string a = sh_quote(dir.file("a.pgm")), b = sh_quote(dir.file("b.png"));
    RunResult r = run_erd("psnr " + a + " " + b);
    CHECK(r.status == 0);
    CHECK(r.out == "40.1720\n");
    RunResult j = run_erd("psnr --json " + a + " " + b);
    CHECK(j.out == "{\"mse\":6.25,\"peak\":255,\"psnr\":40.17200343523835}\n");
    CHECK(run_erd("psnr " + a + " " + a).out == "inf\n");
    CHECK(run_erd("psnr --json " + a + " " + a).out == "{\"mse\":0,\"peak\":255,\"psnr\":null}\n");
    CHECK(run_erd("psnr " + a + " - < " + b).out == "40.1720\n");
    RunResult m = run_erd("psnr " + a + " " + sh_quote(dir.file("c.pgm")));
    CHECK(m.status == 2);
    CHECK_THAT(m.err, Catch::Contains("sizes differ: 2 x 2 and 3 x 2"));
    RunResult mv = run_erd("psnr " + a + " " + sh_quote(dir.file("d.pgm")));
    CHECK(mv.status == 2);
    CHECK_THAT(mv.err, Catch::Contains("maxvals differ: 255 and 1023"));
    RunResult missing = run_erd("psnr " + a + " " + sh_quote(dir.file("zz.pgm")));
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("zz.pgm: No such file or directory"));
}

TEST_CASE("synth is deterministic: same bytes twice, seeds differ, library agrees with the binary", "[cli][io]") {
    erd::SynthParams p;
    p.width = 64;
    p.height = 48;
    p.seed = 7;
    Image a, b, c;
    REQUIRE(erd::synth(p, &a).ok());
    REQUIRE(erd::synth(p, &b).ok());
    CHECK(a.samples == b.samples);
    p.seed = 8;
    REQUIRE(erd::synth(p, &c).ok());
    CHECK(a.samples != c.samples);
    // The content is what the brief asks for: sharp edges (large jumps between neighbours)
    // and mild noise (most neighbours close).
    int jumps = 0, close = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 1; x < a.width; ++x) {
            int d = std::abs(int(a.at(x, y)) - int(a.at(x - 1, y)));
            jumps += d > 60;
            close += d <= 6;
        }
    CHECK(jumps >= 20);
    CHECK(close > a.width * a.height * 3 / 4);
    // Invalid parameters.
    erd::SynthParams bad;
    bad.bits = 0;
    CHECK(erd::synth(bad, &c).code == erd::Code::input);
    bad = erd::SynthParams();
    bad.width = 0;
    CHECK(erd::synth(bad, &c).code == erd::Code::input);
    bad.width = 1;
    bad.height = 1;
    CHECK(erd::synth(bad, &c).ok());

    if (!need_binary()) return;
    TempDir dir;
    std::string f1 = dir.file("1.pgm"), f2 = dir.file("2.pgm");
    REQUIRE(run_erd("synth -q -W 64 -H 48 --seed 7 -o " + sh_quote(f1)).status == 0);
    REQUIRE(run_erd("synth -q -W 64 -H 48 --seed 7 -o " + sh_quote(f2)).status == 0);
    CHECK(slurp(f1) == slurp(f2));
    CHECK(slurp(f1) == erd::cli::encode_pnm(a, false));
    // stdout carries the data when -o - is given.
    RunResult s = run_erd("synth -q -W 64 -H 48 --seed 7 -o -");
    CHECK(s.out == slurp(f1));
}

TEST_CASE("synth bytes are pinned: the same at every optimisation level and on every machine", "[cli][io]") {
    // FNV-1a of the default 256 x 256 8-bit image and of a 16-bit one. The normal build (-O2)
    // and the sanitizer build (-O1) both run this, so a compiler-dependent result shows here.
    auto fnv = [](const Image& im) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint16_t v : im.samples) {
            h = (h ^ (v & 0xffu)) * 1099511628211ull;
            h = (h ^ (v >> 8)) * 1099511628211ull;
        }
        return h;
    };
    Image a, b;
    REQUIRE(erd::synth(erd::SynthParams(), &a).ok());
    erd::SynthParams p16;
    p16.width = 97;
    p16.height = 61;
    p16.bits = 16;
    p16.seed = 12345;
    REQUIRE(erd::synth(p16, &b).ok());
    CHECK(fnv(a) == 0x8ac530988289e9bull);
    CHECK(fnv(b) == 0xecdfa0d6dbab2467ull);
}

TEST_CASE("writing over an input is refused through the real commands, and the input survives", "[cli][io]") {
    if (!need_binary()) return;
    TempDir dir;
    std::string img = dir.file("a.pgm");
    REQUIRE(run_erd("synth -q -W 16 -H 12 -o " + sh_quote(img)).status == 0);
    const std::string before = slurp(img);
    // The same file under another name: ./, .., a hard link.
    REQUIRE(::link(img.c_str(), dir.file("b.pgm").c_str()) == 0);
    const std::string aliases[] = {img, dir.path + "/./a.pgm", dir.path + "/x/../a.pgm", dir.file("b.pgm")};
    for (const auto& out : aliases) {
        INFO(out);
        RunResult g = run_erd("generate --method gpi -n 8 -i " + sh_quote(img) + " -o " + sh_quote(out));
        CHECK(g.status == 2);
        CHECK_THAT(g.err, Catch::Contains("output would overwrite the input"));
        CHECK(slurp(img) == before);
    }
    REQUIRE(run_erd("generate -q --method gpi -n 8 -i " + sh_quote(img) + " -o " + sh_quote(dir.file("m.model"))).status == 0);
    const std::string model = slurp(dir.file("m.model"));
    RunResult r = run_erd("reconstruct " + sh_quote(dir.file("m.model")) + " -o " + sh_quote(dir.file("m.model")));
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("output would overwrite the input"));
    CHECK(slurp(dir.file("m.model")) == model);
}
