// What a user of the erd program sees on long and many-file runs (issue 20) and the all-or-nothing
// commit of several outputs (issue 19): progress lines on a non-terminal, batches with a bad file,
// their summaries, and a commit whose second move fails. Small images: about a second in all.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/outputs.h"
#include "tests/erd_run.h"

namespace {

using erd_test::exists;
using erd_test::slurp;
using erd_test::spit;
using erd_test::TempDir;

erd_test::RunResult run_in(const TempDir& dir, const std::string& args) {
    return erd_test::run_erd(args, "cd " + erd_test::sh_quote(dir.path) + " && ");
}

// Every progress line of `err` ("erd SUB: STAGE P%..."), by stage (passes apart), in order.
std::map<std::string, std::vector<int>> progress_lines(const std::string& err, const std::string& sub) {
    std::map<std::string, std::vector<int>> out;
    std::istringstream in(err);
    std::string line;
    const std::string head = "erd " + sub + ": ";
    while (std::getline(in, line)) {
        REQUIRE(line.find('\r') == std::string::npos);  // no redraws off a terminal
        if (line.rfind(head, 0) != 0) continue;
        const std::string rest = line.substr(head.size());
        const std::size_t pct = rest.find('%');
        if (pct == std::string::npos) continue;
        std::size_t num = rest.rfind(' ', pct);
        if (num == std::string::npos) continue;
        out[rest.substr(0, num)].push_back(std::atoi(rest.c_str() + num + 1));
    }
    return out;
}

void require_increasing(const std::map<std::string, std::vector<int>>& stages, const std::string& stage) {
    INFO("stage " << stage);
    REQUIRE(stages.count(stage) == 1);
    const std::vector<int>& p = stages.at(stage);
    REQUIRE(p.size() >= 2);
    for (std::size_t i = 1; i < p.size(); ++i) REQUIRE(p[i] > p[i - 1]);
}

}  // namespace

TEST_CASE("--progress off a terminal: lines with increasing percentages for every long stage", "[cli][progress]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    REQUIRE(run_in(t, "synth -q -W 160 -H 120 -o in.pgm").status == 0);
    auto r = run_in(t, "generate -m erdgpi -i in.pgm -o m.erd --progress");
    REQUIRE(r.status == 0);
    auto s = progress_lines(r.err, "generate");
    for (const char* stage : {"initial mesh", "greedy insertion", "wedge refit"}) require_increasing(s, stage);
    const std::pair<const char*, const char*> runs[] = {{"reconstruct", "reconstruct m.erd -o rec.pgm"},
                                                         {"render", "render m.erd -o pic.png"},
                                                         {"export", "export m.erd -o m.obj"},
                                                         {"edges", "edges in.pgm -o e.pgm"}};
    for (const auto& [sub, args] : runs) {
        r = run_in(t, std::string(args) + " --progress");
        REQUIRE(r.status == 0);
        require_increasing(progress_lines(r.err, sub), sub);
    }
    // Without --progress off a terminal, and under -q: none.
    r = run_in(t, "reconstruct m.erd -o rec.pgm");
    CHECK(progress_lines(r.err, "reconstruct").empty());
    r = run_in(t, "generate -q -m gpi -i in.pgm -o m.model --progress");
    CHECK(r.err.empty());
}

TEST_CASE("many files: one bad among them, the others done, exit 1, a summary row for each", "[cli][batch]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    REQUIRE(::mkdir(t.file("in").c_str(), 0755) == 0);
    REQUIRE(::mkdir(t.file("out").c_str(), 0755) == 0);
    REQUIRE(run_in(t, "synth -q -W 40 -H 30 -o a.pgm").status == 0);
    REQUIRE(run_in(t, "synth -q -W 50 -H 20 -o in/c.pgm").status == 0);
    spit(t.file("b.pgm"), "P5 junk\n");
    auto r = run_in(t, "generate -m gpi -i a.pgm -i b.pgm -i in -o 'out/{name}.model' -j 2 --summary s.csv");
    INFO(r.err);
    REQUIRE(r.status == 1);
    CHECK(exists(t.file("out/a.model")));
    CHECK(exists(t.file("out/c.model")));
    CHECK_FALSE(exists(t.file("out/b.model")));
    CHECK(r.err.find("erd generate: b.pgm: ") != std::string::npos);
    CHECK(r.err.find("1 of 3 files failed") != std::string::npos);
    const std::string csv = slurp(t.file("s.csv"));
    INFO(csv);
    REQUIRE(csv.rfind("file,method,points,psnr,seconds,status,error\n", 0) == 0);
    CHECK(csv.find("\na.pgm,gpi,36,") != std::string::npos);
    CHECK(csv.find("\nb.pgm,,,,") != std::string::npos);
    CHECK(csv.find("\nin/c.pgm,gpi,30,") != std::string::npos);
    CHECK(csv.find(",2,b.pgm: ") != std::string::npos);  // the bad file's exit status and message
    // The same as JSON, and reconstruct over the models made.
    r = run_in(t, "generate -q -m ed -i a.pgm -i in -o 'out/{name}.model' --summary s.json");
    REQUIRE(r.status == 0);
    const std::string json = slurp(t.file("s.json"));
    CHECK(json.find("{\"file\":\"a.pgm\",\"method\":\"ed\",\"points\":36,\"psnr\":") != std::string::npos);
    CHECK(json.find("\"status\":0,\"error\":\"\"}") != std::string::npos);
    r = run_in(t, "reconstruct out -o 'out/{name}.pgm' -j 0 --summary r.csv");
    REQUIRE(r.status == 0);
    CHECK(exists(t.file("out/a.pgm")));
    CHECK(exists(t.file("out/c.pgm")));
    // psnr over the reconstructions, originals by a {name} pattern; b.pgm has no original.
    spit(t.file("out/b.pgm"), "P5 junk\n");
    REQUIRE(::rename(t.file("in/c.pgm").c_str(), t.file("c.pgm").c_str()) == 0);
    r = run_in(t, "psnr '{name}.pgm' out -j 2 --summary p.csv");
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.find("out/a.pgm ") != std::string::npos);
    CHECK(r.out.find("out/c.pgm ") != std::string::npos);
    CHECK(r.err.find("1 of 3 files failed") != std::string::npos);
    const std::string pcsv = slurp(t.file("p.csv"));
    INFO(pcsv);
    CHECK(pcsv.find("\nout/a.pgm,") != std::string::npos);
    CHECK(pcsv.find("\nout/b.pgm,,,,") != std::string::npos);
    CHECK(run_in(t, "psnr a.pgm out").status == 2);  // many images need a {name} pattern
    // Usage errors before any work: one output file for several inputs, two inputs to one name.
    CHECK(run_in(t, "generate -m gpi -i a.pgm -i in -o one.model").status == 2);
    CHECK(run_in(t, "generate -m gpi -i a.pgm -i a.pgm -o 'out/{name}.model'").status == 2);
    CHECK(run_in(t, "generate -m gpi -i a.pgm -i in -o 'out/{name}.model' -j x").status == 2);
    CHECK(run_in(t, "generate -m gpi -i a.pgm -i in -o 'out/{name}.model' -d 200").status == 2);
}

TEST_CASE("a commit whose second move fails puts the first old file back", "[outputs][commit]") {
    for (const bool named : {false, true}) {
        INFO((named ? "named temporaries" : "O_TMPFILE"));
        if (named) ::setenv("ERD_NO_TMPFILE", "1", 1);
        TempDir t;
        const std::string a = t.file("a.model"), b = t.file("b.tri");
        spit(a, "old a\n");
        erd::Status st;
        {
            erd::cli::Outputs outs;
            REQUIRE(outs.check({a, b}, {}).ok());
            REQUIRE(outs.stage(a, "new a\n").ok());
            REQUIRE(outs.stage(b, "new b\n").ok());
            REQUIRE(::mkdir(b.c_str(), 0755) == 0);  // b's move now fails (a folder in its place)
            st = outs.commit();
        }
        ::unsetenv("ERD_NO_TMPFILE");
        REQUIRE_FALSE(st.ok());
        INFO(st.message);
        CHECK(st.message.find("b.tri") != std::string::npos);
        CHECK(st.message.find("every file is as it was") != std::string::npos);
        CHECK(slurp(a) == "old a\n");
        const auto r = erd_test::run_shell("ls -A " + erd_test::sh_quote(t.path));
        CHECK(r.out == "a.model\nb.tri\n");  // no temporary, no second name left
        // And when nothing fails, both are new.
        ::rmdir(b.c_str());
        erd::cli::Outputs outs;
        REQUIRE(outs.stage(a, "new a\n").ok());
        REQUIRE(outs.stage(b, "new b\n").ok());
        REQUIRE(outs.commit().ok());
        CHECK(slurp(a) == "new a\n");
        CHECK(slurp(b) == "new b\n");
    }
}

TEST_CASE("a P5 with CR LF after maxval and data after the raster reads the same from a pipe", "[cli][framing]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    // Found by fuzz_framing: the file's rule (one byte more than the raster: the LF is the
    // separator's pair) needs to see whether the stream ends there.
    using namespace std::string_literals;
    for (const std::string& body : {"P5\r\n2 1\r\n255\r\n\x02\xb0" "4#trailing"s, "P5\r\n2 1\r\n255\r\n\x02\xb0"s,
                                    "P5\n2 1\n255\r\n\x02\xb0\x07"s}) {
        spit(t.file("f.pgm"), body);
        const auto r = erd_test::run_shell("cat " + erd_test::sh_quote(t.file("f.pgm")) + " | " + erd_test::sh_quote(erd_test::erd_bin()) +
                                           " psnr " + erd_test::sh_quote(t.file("f.pgm")) + " -");
        INFO(r.err);
        CHECK(r.status == 0);
        CHECK(r.out == "inf\n");
    }
}
