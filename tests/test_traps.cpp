// The last input traps (issue 49), each as a new user meets it:
//   - a small image followed by a gigabyte (a sparse file) is read as far as its header says and
//     a bounded look after it, in every format, from a file as from a stream (cli/framing.h);
//   - an output whose folder is missing or not writable is refused before the input is read, in
//     every subcommand and for every file of a batch, and nothing is created (cli/output_names.h);
//   - Apple's CgBI "PNG" is refused by name (imageio/png.cpp).
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/image_io.h"
#include "cli/model_file.h"
#include "tests/decode_util.h"
#include "tests/erd_run.h"
#include "tests/png_util.h"
#include "tests/synth_util.h"

using namespace erd_test;

namespace {

constexpr std::uint64_t kGiB = std::uint64_t(1) << 30;

// `bytes` in `path`, then the file made `size` bytes long with a hole (no disk used).
void write_with_tail(const std::string& path, const std::string& bytes, std::uint64_t size) {
    spit(path, bytes);
    REQUIRE(::truncate(path.c_str(), off_t(size)) == 0);
}

std::string pnm(const erd::Image& im, bool plain) {
    std::string b;
    REQUIRE(erd::imageio::encode_image(im, plain ? erd::imageio::ImageFormat::pgm_plain : erd::imageio::ImageFormat::pgm_raw, &b).ok());
    return b;
}

// A 2 x 2 RGBA image as Apple's CgBI variant: a CgBI chunk before IHDR, BGRA samples, the IDAT
// stream a raw deflate (stored blocks, no zlib header or Adler-32), which stb decodes.
std::string cgbi_png() {
    std::string rows;
    for (int y = 0; y < 2; ++y) {
        rows += '\0';
        for (int x = 0; x < 2; ++x) rows += std::string{char(20 * x), char(40 * y), char(200), char(255)};
    }
    std::string raw = "\x01";
    raw += char(rows.size() & 0xff);
    raw += char(rows.size() >> 8);
    raw += char(~rows.size() & 0xff);
    raw += char((~rows.size() >> 8) & 0xff);
    raw += rows;
    const std::string ihdr = be32(2) + be32(2) + std::string("\x08\x06\x00\x00\x00", 5);
    return "\x89PNG\r\n\x1a\n" + chunk("CgBI", std::string("\x50\x00\x20\x06", 4)) + chunk("IHDR", ihdr) + chunk("IDAT", raw) +
           chunk("IEND", "");
}

}  // namespace

TEST_CASE("a small image followed by 1 GiB: the image and 4 KiB read, every format, file or stream", "[io][traps]") {
    TempDir t;
    const erd::Image gray = synth_image(64, 64);
    erd::Image colour(5, 4, 255, 3);
    for (std::size_t i = 0; i < colour.samples.size(); ++i) colour.samples[i] = std::uint16_t(i * 7 % 256);
    std::string png;
    REQUIRE(erd::imageio::encode_image(gray, erd::imageio::ImageFormat::png, &png).ok());
    std::string ppm;
    REQUIRE(erd::imageio::encode_image(colour, erd::imageio::ImageFormat::ppm_raw, &ppm).ok());
    const std::string pam = "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\nTUPLTYPE GRAYSCALE\nENDHDR\n" + std::string("\x01\x02\x03\x04", 4);
    struct Case {
        const char* name;
        std::string bytes;
    };
    std::vector<Case> cases = {{"p5.pgm", pnm(gray, false)}, {"p2.pgm", pnm(gray, true)}, {"p6.ppm", ppm},
                               {"p7.pam", pam},              {"gray.png", png}};
    for (const char* j : {"gray_8x8.jpg", "rgb_12x10_444.jpg", "progressive_1x7.jpg"}) {
        const std::string jpeg = slurp(std::string("fuzz/corpus/fuzz_jpeg/") + j);
        if (!have_input(!jpeg.empty(), std::string("fuzz/corpus/fuzz_jpeg/") + j + " (run from the source tree)")) return;
        cases.push_back({j, jpeg});
    }
    for (const Case& c : cases) {
        INFO(c.name);
        erd::Image want, got;
        REQUIRE(decode(c.bytes, &want).ok());
        const std::string path = t.file(c.name);
        write_with_tail(path, c.bytes, kGiB);
        // The file: the content (the framer's end; a plain PGM's ends at its last sample) and no
        // more; the size of the tail reported, never read.
        std::string bytes;
        bool more = false;
        std::uint64_t unread = 0;
        REQUIRE(erd::cli::read_file(path, &bytes, erd::cli::kMaxInputBytes, erd::cli::image_framer({}), &more, &unread).ok());
        CHECK(bytes.size() <= c.bytes.size());
        CHECK(c.bytes.compare(0, bytes.size(), bytes) == 0);
        CHECK(unread == kGiB - bytes.size());
        std::string warning;
        REQUIRE(erd::cli::read_image(path, &got, &warning).ok());
        CHECK(got.samples == want.samples);
        CHECK_THAT(warning, Catch::Contains("ignored " + std::to_string(kGiB - bytes.size()) + " bytes after the image"));
        // A short tail (at most 4 KiB): the whole file, as every file was read before.
        write_with_tail(path, c.bytes, c.bytes.size() + 100);
        REQUIRE(erd::cli::read_file(path, &bytes, erd::cli::kMaxInputBytes, erd::cli::image_framer({}), &more, &unread).ok());
        CHECK(bytes.size() == c.bytes.size() + 100);
        CHECK(unread == 0);
    }
}

TEST_CASE("a model, triangulation or .erdz followed by 1 GiB: refused after a few KB", "[io][traps]") {
    if (!need_binary()) return;
    TempDir t;
    REQUIRE(run_in(t.path, sh_quote(erd_bin()) + " synth -q -W 40 -H 30 -o in.pgm && " + sh_quote(erd_bin()) +
                               " generate -q -m erdgpi -i in.pgm -n 40 -o m.erd -t m.tri -p m.poly && " + sh_quote(erd_bin()) +
                               " convert m.erd m.erdz").status == 0);
    for (const char* name : {"m.erd", "m.tri", "m.erdz", "m.poly"}) {
        INFO(name);
        const std::string path = t.file(std::string("tail_") + name);
        const std::string content = slurp(t.file(name));
        REQUIRE(!content.empty());
        write_with_tail(path, content, kGiB);
        std::string bytes;
        std::uint64_t unread = 0;
        const bool tri = std::string(name) == "m.tri";
        const erd::cli::Framer framer = std::string(name) == "m.poly" ? erd::cli::polylines_framer() : erd::cli::model_framer(tri);
        REQUIRE(erd::cli::read_file(path, &bytes, erd::cli::kMaxInputBytes, framer, nullptr, &unread).ok());
        CHECK(bytes.size() <= content.size() + 65536);
        CHECK(unread == kGiB - bytes.size());
        if (std::string(name) == "m.poly") continue;
        erd::Model m;
        std::string warning;
        const erd::Status s = erd::cli::load_model_file(path, &m, &warning);
        CHECK(s.code == erd::Code::input);
        CHECK(s.message.find('\n') == std::string::npos);
        CHECK_THAT(s.message, Catch::Contains(std::string(name) == "m.erdz" ? "bytes after the last section" : "\\x00"));
    }
}

TEST_CASE("erd generate on a 64 x 64 PGM followed by 1 GiB: the model of the image, one warning, small memory", "[cli][traps]") {
    if (!need_binary()) return;
    TempDir t;
    REQUIRE(run_in(t.path, sh_quote(erd_bin()) + " synth -q -W 64 -H 64 -o small.pgm").status == 0);
    write_with_tail(t.file("big.pgm"), slurp(t.file("small.pgm")), kGiB);
    // 128 MB of address space: reading the file whole took 1025 MB (a sanitized binary reserves
    // terabytes of shadow memory, which no limit allows: it runs without one).
    const std::string limit = std::getenv("ERD_SANITIZED") ? "" : "ulimit -v 131072 && ";
    RunResult r = run_in(t.path, limit + sh_quote(erd_bin()) + " generate -m gpi -d 3 -i big.pgm -o big.model");
    CHECK(r.status == 0);
    // The warning, then the summary line.
    CHECK_THAT(r.err, Catch::StartsWith("erd generate: warning: big.pgm: ignored " +
                                        std::to_string(kGiB - slurp(t.file("small.pgm")).size()) +
                                        " bytes after the image (only the first image of a file is read)\nerd generate: gpi: "));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2);
    REQUIRE(run_in(t.path, sh_quote(erd_bin()) + " generate -q -m gpi -d 3 -i small.pgm -o small.model").status == 0);
    CHECK(slurp(t.file("big.model")) == slurp(t.file("small.model")));
    // The same bytes from a pipe: the stream's warning.
    r = run_in(t.path, "head -c 1000000 big.pgm | { " + limit + sh_quote(erd_bin()) + " generate -m gpi -d 3 -o pipe.model; }");
    CHECK(r.status == 0);
    CHECK_THAT(r.err, Catch::Contains("stdin: ignored the data after the image"));
    CHECK(slurp(t.file("pipe.model")) == slurp(t.file("small.model")));
}

// The input is not an image: reading it first would fail on it (exit 2); the output's folder,
// checked first, fails with exit 1 and names the output.
TEST_CASE("an output in a missing folder: refused before the input is read, every subcommand, batches too", "[cli][traps]") {
    if (!need_binary()) return;
    TempDir t;
    REQUIRE(run_in(t.path, sh_quote(erd_bin()) + " synth -q -W 16 -H 12 -o a.pgm && " + sh_quote(erd_bin()) +
                               " generate -q -m gpi -i a.pgm -n 10 -o good.model").status == 0);
    spit(t.file("bad.pgm"), "not an image");
    spit(t.file("bad.model"), "not a model");
    spit(t.file("afile"), "a file");
    struct Case {
        std::string args, output;
    };
    const std::vector<Case> cases = {
        {"generate -m erdgpi -i bad.pgm -d 1 -o missing/dir/x.erd", "missing/dir/x.erd"},
        {"generate -m gpi -i bad.pgm -d 1 -o good2.model -t missing/x.tri", "missing/x.tri"},
        {"generate -m erdgpi -i bad.pgm -d 1 -o x.erd -p afile/x.poly", "afile/x.poly"},
        {"generate -m gpi -i bad.pgm -d 1 -o x.model --stats missing/s.json", "missing/s.json"},
        {"edges bad.pgm -o missing/e.pgm", "missing/e.pgm"},
        {"reconstruct bad.model -o missing/r.pgm", "missing/r.pgm"},
        {"render bad.model -o missing/r.svg", "missing/r.svg"},
        {"export bad.model -o missing/r.obj", "missing/r.obj"},
        {"convert bad.model missing/r.erdz", "missing/r.erdz"},
        {"synth -W 64 -H 64 -o missing/s.pgm", "missing/s.pgm"},
        // A batch: every expanded output up front (the first names the problem), so no job runs.
        {"generate -m gpi -d 1 -i a.pgm -i bad.pgm -o missing/{name}.model", "missing/a.model"},
        {"generate -m gpi -d 1 -i a.pgm -i bad.pgm -o {name}_x.model -t missing/{name}.tri", "missing/a.tri"},
        {"generate -m gpi -d 1 -i a.pgm -o out_{name}.model --summary missing/s.csv", "missing/s.csv"},
        {"reconstruct good.model bad.model -o missing/{name}.pgm", "missing/good.pgm"},
    };
    const std::string before = t.listing();
    for (const Case& c : cases) {
        INFO("erd " << c.args);
        RunResult r = run_in(t.path, sh_quote(erd_bin()) + " " + c.args);
        CHECK(r.status == 1);
        const std::string why = c.output.rfind("afile/", 0) == 0 ? "Not a directory" : "No such file or directory";
        CHECK(r.err == "erd " + c.args.substr(0, c.args.find(' ')) + ": " + c.output + ": " + why + "\n");
        CHECK(t.listing() == before);  // nothing made: no output, no temporary, no folder
    }
}

// Root writes anywhere: as root the folder cases run as nobody (setpriv), as in test_outputs.cpp.
TEST_CASE("an output in a folder we may not write: refused before the input is read, nothing made", "[cli][traps]") {
    if (!need_binary()) return;
    TempDir t;
    const std::string home = t.file("home");
    REQUIRE(::mkdir(home.c_str(), 0755) == 0);
    REQUIRE(::mkdir((home + "/ro").c_str(), 0755) == 0);
    spit(home + "/ro/old.model", "old");
    spit(home + "/bad.pgm", "not an image");
    std::string as_user;
    if (::geteuid() == 0) {
        if (run_shell("command -v setpriv").status != 0) {
            WARN("skipped: running as root without setpriv to drop to nobody");
            return;
        }
        REQUIRE(::chmod(t.path.c_str(), 0755) == 0);
        REQUIRE(run_shell("chown -R 65534:65534 " + sh_quote(home)).status == 0);
        as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
    }
    REQUIRE(::chmod((home + "/ro").c_str(), 0555) == 0);
    for (const char* out : {"ro/new.model", "ro/old.model"}) {
        INFO(out);
        RunResult r = run_shell("cd " + sh_quote(home) + " && " + as_user + sh_quote(erd_bin()) + " generate -m gpi -d 3 -i bad.pgm -o " + out);
        CHECK(r.status == 1);
        CHECK(r.err == std::string("erd generate: ") + out + ": Permission denied (erd cannot create files in ro)\n");
    }
    CHECK(slurp(home + "/ro/old.model") == "old");
    CHECK_FALSE(exists(home + "/ro/new.model"));
    REQUIRE(::chmod((home + "/ro").c_str(), 0755) == 0);
}

TEST_CASE("Apple's CgBI PNG: refused by name, file or stdin, before stb decodes it", "[io][traps]") {
    const std::string apple = cgbi_png();
    erd::Image im;
    check_refused(decode(apple, &im), "an Apple CgBI file");
    // The same bytes without the CgBI chunk and with a zlib stream: a PNG stb decodes, so the
    // refusal is the chunk's.
    std::string rows;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) rows += std::string{char(200), char(40 * y), char(20 * x), char(255)};
    CHECK(decode(make_png(2, 2, 8, 6, rows), &im).ok());
    if (!need_binary()) return;
    TempDir t;
    spit(t.file("icon.png"), apple);
    RunResult r = run_in(t.path, sh_quote(erd_bin()) + " generate -m erdgpi -d 50 -i icon.png -o icon.erd");
    CHECK(r.status == 2);
    CHECK(r.err == "erd generate: icon.png: an Apple CgBI file (Xcode's iPhone-optimised PNG: byte-swapped BGRA, raw deflate), "
                   "not a standard PNG; convert it first (xcrun pngcrush -revert-iphone-optimizations)\n");
    CHECK_FALSE(exists(t.file("icon.erd")));
    r = run_in(t.path, sh_quote(erd_bin()) + " info - < icon.png");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::StartsWith("erd info: stdin: an Apple CgBI file"));
}
