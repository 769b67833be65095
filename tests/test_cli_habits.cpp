// What a new user expects of a command line (issue 20): help and version everywhere, bundled
// short flags, unique prefixes of long options, "did you mean", generate from stdin, a one-line
// summary with the details behind -v, the extension trap, and JSON that stays JSON whatever the
// file names hold.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "cli/json.h"
#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// A small synthetic image through the real binary.
std::string synth_image(const TempDir& dir, const std::string& name = "in.pgm") {
    RunResult r = run_erd("synth -W 48 -H 40 -q -o " + sh_quote(dir.file(name)));
    REQUIRE(r.status == 0);
    return dir.file(name);
}

// python3 reads `path` as JSON and prints repr() of field `key` (ASCII only): the test that our
// JSON is JSON to a strict reader, not to our own.
RunResult python_field(const std::string& path, const std::string& key) {
    return run_shell("python3 -c 'import json,sys; d=json.loads(open(sys.argv[1],\"rb\").read()); print(ascii(d[sys.argv[2]]))' " +
                     sh_quote(path) + " " + sh_quote(key));
}

}  // namespace

TEST_CASE("help --help, SUB --version, help --version", "[cli][habits]") {
    if (!need_binary()) return;
    const RunResult list = run_erd("help");
    RunResult h = run_erd("help --help");
    CHECK(h.status == 0);
    CHECK(h.out == list.out);
    CHECK(run_erd("help -h").out == list.out);
    const std::string version = run_erd("--version").out;
    REQUIRE_THAT(version, Catch::StartsWith("erd "));
    for (const char* sub : {"generate", "reconstruct", "psnr", "edges", "render", "export", "info", "synth", "help"}) {
        INFO(sub);
        RunResult v = run_erd(std::string(sub) + " --version");
        CHECK(v.status == 0);
        CHECK(v.out == version);
        CHECK(v.err.empty());
    }
    CHECK_THAT(run_erd("info --help").out, Catch::Contains("--version"));
}

TEST_CASE("bundled short flags and unique prefixes of long options", "[cli][habits]") {
    if (!need_binary()) return;
    TempDir dir;
    // -qW8: -q then -W 8; the value may follow in the same word or the next.
    RunResult b = run_erd("synth -qW8 -H 6 -o " + sh_quote(dir.file("a.pgm")));
    INFO(b.err);
    CHECK(b.status == 0);
    CHECK(b.err.empty());  // -q was taken
    RunResult l = run_erd("synth --width 8 --height 6 -q -o " + sh_quote(dir.file("b.pgm")));
    REQUIRE(l.status == 0);
    CHECK(slurp(dir.file("a.pgm")) == slurp(dir.file("b.pgm")));
    // Prefixes: --wid is --width, --no is --no-noise.
    RunResult p = run_erd("synth --wid 8 --hei=6 --qui -o " + sh_quote(dir.file("c.pgm")));
    CHECK(p.status == 0);
    CHECK(slurp(dir.file("c.pgm")) == slurp(dir.file("a.pgm")));
    CHECK(run_erd("synth --wid 8 --hei 6 --no -q -o " + sh_quote(dir.file("d.pgm"))).status == 0);
    CHECK(slurp(dir.file("d.pgm")) != slurp(dir.file("a.pgm")));

    const std::string img = synth_image(dir);
    RunResult g = run_erd("generate --meth gpi --poi 30 -qx2 -i " + sh_quote(img) + " -o " + sh_quote(dir.file("m.model")));
    INFO(g.err);
    CHECK(g.status == 0);
    CHECK(exists(dir.file("m.model")));

    struct Bad { const char* args; const char* line; };
    const Bad bad[] = {
        // --p: points, polylines, psnr, ...: ambiguous, and the candidates are named.
        {"generate --p 3", "erd generate: option --p is ambiguous (--points, --polylines, --psnr, --psnr-report, --progress)"},
        {"generate --methd gpi", "erd generate: unknown option --methd. Did you mean '--method'?"},
        {"synth --widht 8 -o x.pgm", "erd synth: unknown option --widht. Did you mean '--width'?"},
        {"synth --zzzzzzzz -o x.pgm", "erd synth: unknown option --zzzzzzzz"},
        {"synth -qZ -o x.pgm", "erd synth: unknown option -Z (in -qZ)"},
        {"synth -qW", "erd synth: option --width needs a value (N)"},
        {"synth --quiet=1 -o x.pgm", "erd synth: option --quiet takes no value"},
    };
    for (const Bad& c : bad) {
        INFO(c.args);
        RunResult r = run_erd(c.args);
        CHECK(r.status == 2);
        CHECK(r.err.substr(0, r.err.find('\n')) == c.line);
    }
}

TEST_CASE("json_string: valid UTF-8 out of any bytes", "[cli][habits][json]") {
    using erd::cli::json_string;
    CHECK(json_string("plain") == "\"plain\"");
    CHECK(json_string("q\"b\\n\nt\t\x01\x1f\x7f") == "\"q\\\"b\\\\n\\nt\\t\\u0001\\u001f\\u007f\"");
    CHECK(json_string("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80") == "\"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\"");
    CHECK(json_string("\xff") == "\"\\ufffd\"");
    CHECK(json_string("a\x80" "b") == "\"a\\ufffdb\"");                       // stray continuation
    CHECK(json_string("\xc0\xaf") == "\"\\ufffd\\ufffd\"");                   // overlong '/'
    CHECK(json_string("\xe0\x80\xaf") == "\"\\ufffd\\ufffd\\ufffd\"");        // overlong, 3 bytes
    CHECK(json_string("\xed\xa0\x80") == "\"\\ufffd\\ufffd\\ufffd\"");        // surrogate D800
    CHECK(json_string("\xf4\x90\x80\x80") == "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");  // above U+10FFFF
    CHECK(json_string("\xe2\x82") == "\"\\ufffd\\ufffd\"");                   // cut short at the end
    CHECK(json_string("\xe2\x82z") == "\"\\ufffd\\ufffdz\"");
    CHECK(json_string(std::string("a\0b", 3)) == "\"a\\u0000b\"");
}

TEST_CASE("info --json and generate --stats stay JSON with hostile names (python3 reads them)", "[cli][habits][json]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = synth_image(dir);
    const std::string hostile = "x\xff\x01\"q\n\tend\xc3\xa9.pgm";
    REQUIRE(run_shell("cp " + sh_quote(img) + " " + sh_quote(dir.file(hostile))).status == 0);
    RunResult info = run_erd("info --json " + sh_quote(dir.file(hostile)));
    REQUIRE(info.status == 0);
    spit(dir.file("info.json"), info.out);
    RunResult py = python_field(dir.file("info.json"), "file");
    INFO(info.out << py.err);
    REQUIRE(py.status == 0);
    CHECK(py.out == "'" + dir.path + "/x\\ufffd\\x01\"q\\n\\tend\\xe9.pgm'\n");

    // --stats read from a hostile name (stdin here), written to one, parsed back.
    const std::string stats = dir.file("s\xfe\n.json");
    RunResult g = run_erd("generate -m erdgpi -n 40 -q -o " + sh_quote(dir.file("m.erd")) + " --stats " + sh_quote(stats) +
                          " < " + sh_quote(dir.file(hostile)));
    INFO(g.err);
    REQUIRE(g.status == 0);
    spit(dir.file("stats.json"), slurp(stats));
    RunResult m = python_field(dir.file("stats.json"), "method");
    CHECK(m.status == 0);
    CHECK(m.out == "'erdgpi'\n");
}

TEST_CASE("the extension trap: generate refuses a name of the other kind; readers go by content", "[cli][habits]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = synth_image(dir);
    // Both ways: a basic model named .erd, an ERD model named .model; refused before any work.
    struct Case { const char* method; const char* wrong; const char* line; };
    const Case cases[] = {
        {"gpi", "w.erd", "gpi makes a basic model, which is a .model file; name the output .model"},
        {"erdgpi", "w.model", "erdgpi makes an ERD model, which is a .erd file; name the output .erd"},
    };
    for (const Case& c : cases) {
        INFO(c.method);
        RunResult r = run_erd(std::string("generate -m ") + c.method + " -n 40 -i " + sh_quote(img) + " -o " + sh_quote(dir.file(c.wrong)));
        CHECK(r.status == 2);
        CHECK(r.err == "erd generate: " + dir.file(c.wrong) + ": " + c.line + "\n");
        CHECK_FALSE(exists(dir.file(c.wrong)));
    }
    // Names that say nothing are fine.
    REQUIRE(run_erd("generate -m gpi -n 40 -q -i " + sh_quote(img) + " -o " + sh_quote(dir.file("b.txt"))).status == 0);
    REQUIRE(run_erd("generate -m erdgpi -n 40 -q -i " + sh_quote(img) + " -o " + sh_quote(dir.file("e.txt"))).status == 0);

    // A file whose name lies (renamed by hand) is read by its content, with a warning; the image
    // is that of the rightly named file.
    struct Lie { const char* from; const char* right; const char* wrong; const char* says; };
    const Lie lies[] = {
        {"b.txt", "b.model", "b.erd", "the content is a .model file, not a .erd as the name says; read as .model"},
        {"e.txt", "e.erd", "e.model", "the content is a .erd file, not a .model as the name says; read as .erd"},
    };
    for (const Lie& l : lies) {
        INFO(l.wrong);
        spit(dir.file(l.right), slurp(dir.file(l.from)));
        spit(dir.file(l.wrong), slurp(dir.file(l.from)));
        RunResult good = run_erd("reconstruct " + sh_quote(dir.file(l.right)) + " -o " + sh_quote(dir.file("good.pgm")));
        REQUIRE(good.status == 0);
        CHECK(good.err.empty());
        RunResult bad = run_erd("reconstruct " + sh_quote(dir.file(l.wrong)) + " -o " + sh_quote(dir.file("bad.pgm")));
        CHECK(bad.status == 0);
        CHECK(bad.err == "erd reconstruct: warning: " + dir.file(l.wrong) + ": " + l.says + "\n");
        CHECK(slurp(dir.file("bad.pgm")) == slurp(dir.file("good.pgm")));
        CHECK(run_erd("export -q " + sh_quote(dir.file(l.wrong)) + " -o " + sh_quote(dir.file("m.obj"))).status == 0);
    }
}

TEST_CASE("generate reads stdin without -i; a run prints one summary line, details under -v", "[cli][habits]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = synth_image(dir);
    RunResult a = run_erd("generate -m erdgpi -n 60 -q -i " + sh_quote(img) + " -o " + sh_quote(dir.file("a.erd")));
    REQUIRE(a.status == 0);
    RunResult s = run_erd("generate -m erdgpi -n 60 -o " + sh_quote(dir.file("s.erd")) + " < " + sh_quote(img));
    INFO(s.err);
    REQUIRE(s.status == 0);
    CHECK(slurp(dir.file("s.erd")) == slurp(dir.file("a.erd")));
    // Without -q or -v: one line, what was made and where.
    CHECK(std::count(s.err.begin(), s.err.end(), '\n') == 1);
    CHECK_THAT(s.err, Catch::StartsWith("erd generate: erdgpi: 60 points, "));
    CHECK_THAT(s.err, Catch::Contains(" faces from 48 x 40 in "));
    CHECK_THAT(s.err, Catch::EndsWith(" s -> " + dir.file("s.erd") + "\n"));
    // -v: the stage timings and the method's statistics as well, then the same summary.
    RunResult v = run_erd("generate -v -m erdgpi -n 60 -i " + sh_quote(img) + " -o " + sh_quote(dir.file("v.erd")));
    REQUIRE(v.status == 0);
    CHECK(std::count(v.err.begin(), v.err.end(), '\n') > 5);
    CHECK_THAT(v.err, Catch::Contains("erd generate: greedy insertion "));
    CHECK_THAT(v.err, Catch::Contains(" ms\n"));
    CHECK_THAT(v.err, Catch::Contains("erd generate: stop: target\n"));
    CHECK_THAT(v.err, Catch::Contains("erd generate: erdgpi: 60 points, "));
    CHECK(run_erd("generate -q -m erdgpi -n 60 -i " + sh_quote(img) + " -o " + sh_quote(dir.file("q.erd"))).err.empty());
}
