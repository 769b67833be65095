// erd info on every kind of model file (.model, .erd gray and colour, soft and hard edges, a -t
// triangulation .tri, an .erdz), as text and as JSON, by name and by content; and erd help's
// closing examples, run as printed. Hand-written 3 x 3 models, so every count is known; one small
// generated .erdz (well under a second).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// Five vertices (the four corners and the centre), four faces round the centre. In the .erd files
// the centre has two wedges (faces 0, 1 and faces 2, 3), so the edges centre-corner 3 and
// centre-corner 0 are constrained: 2 constrained edges.
const char* const kModel = "255\n5\n0 0 10\n2 0 20\n0 2 30\n2 2 40\n1 1 25\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n";
const char* const kColourErd =
    "erd-header 1\nchannels 3\nend\n255\n5\n0 0 10 11 12\n4 0 20 21 22\n0 4 30 31 32\n4 4 40 41 42\n2 2 25 26 25\n"
    "4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n4\n4 0 25 26 10\n4 1 25 26 10\n4 2 25 26 40\n4 3 25 26 40\n";
const char* const kHardErd =
    "erd-header 1\nedges hard\nend\n255\n5\n0 0 10\n4 0 20\n0 4 30\n4 4 40\n2 2 25\n"
    "4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n4\n4 0 10\n4 1 10\n4 2 40\n4 3 40\n";
const char* const kTri = "erd-triangulation 1\n3 3\n5\n0 0\n4 0\n0 4\n4 4\n2 2\n4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n1\n0 4\n";

struct Case {
    const char* name;
    const char* text;
    std::vector<std::string> lines;  // the text output after "file:"
    std::string json;                // the JSON after "file"
};

}  // namespace

TEST_CASE("erd info on a text model: kind, size, mesh, edge kinds, file size and bpp; text and JSON", "[cli][info]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::vector<Case> cases = {
        {"a.model", kModel,
         {"format:    .model text, basic model", "size:      3 x 3 (9 pixels), maxval 255, 1 channel",
          "mesh:      5 vertices, 4 faces, 0 constrained edges", "file size: 67 bytes, 59.55556 bpp"},
         R"("format":"model","kind":"basic","edges":null,"width":3,"height":3,"maxval":255,"channels":1,"vertices":5,)"
         R"("faces":4,"constraints":0,"edge_kinds":{},"bytes":67,"bpp":59.55555555555556})"},
        {"c.erd", kColourErd,
         {"format:    .erd text, erd model", "size:      3 x 3 (9 pixels), maxval 255, 3 channels",
          "mesh:      5 vertices, 4 faces, 2 constrained edges (2 soft)", "file size: 179 bytes, 159.11111 bpp"},
         R"("format":"erd","kind":"erd","edges":"soft","width":3,"height":3,"maxval":255,"channels":3,"vertices":5,)"
         R"("faces":4,"constraints":2,"edge_kinds":{"soft":2},"bytes":179,"bpp":159.11111111111111})"},
        {"h.erd", kHardErd,
         {"format:    .erd text, erd (hard edges) model", "size:      3 x 3 (9 pixels), maxval 255, 1 channel",
          "mesh:      5 vertices, 4 faces, 2 constrained edges (2 hard)", "file size: 125 bytes, 111.11111 bpp"},
         R"("format":"erd","kind":"erd","edges":"hard","width":3,"height":3,"maxval":255,"channels":1,"vertices":5,)"
         R"("faces":4,"constraints":2,"edge_kinds":{"hard":2},"bytes":125,"bpp":111.11111111111111})"},
        {"t.tri", kTri,
         {"format:    .tri text, triangulation (no values: erd render draws it, nothing reconstructs it)",
          "size:      3 x 3 (9 pixels)", "mesh:      5 vertices, 4 faces, 1 constrained edge (a triangulation stores no edge kinds)",
          "file size: 78 bytes, 69.33333 bpp"},
         R"("format":"tri","kind":"triangulation","edges":null,"width":3,"height":3,"maxval":null,"channels":null,)"
         R"("vertices":5,"faces":4,"constraints":1,"edge_kinds":null,"bytes":78,"bpp":69.33333333333333})"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string path = dir.file(c.name);
        spit(path, c.text);
        RunResult t = run_erd("info " + sh_quote(path));
        INFO(t.err);
        REQUIRE(t.status == 0);
        CHECK(t.err.empty());
        std::string want = "file:      " + path + "\n";
        for (const std::string& l : c.lines) want += l + "\n";
        CHECK(t.out == want);
        RunResult j = run_erd("info --json " + sh_quote(path));
        REQUIRE(j.status == 0);
        CHECK(j.out == "{\"file\":\"" + path + "\"," + c.json + "\n");
    }
    // By content, whatever the name: the hard .erd under a name without an extension reads the same.
    spit(dir.file("noext"), kHardErd);
    RunResult n = run_erd("info " + sh_quote(dir.file("noext")));
    CHECK(n.status == 0);
    CHECK_THAT(n.out, Catch::Contains("mesh:      5 vertices, 4 faces, 2 constrained edges (2 hard)"));
    // A broken model: one line naming the file and the place, exit 2, nothing on stdout.
    spit(dir.file("cut.erd"), std::string(kHardErd).substr(0, 60));
    RunResult b = run_erd("info " + sh_quote(dir.file("cut.erd")));
    CHECK(b.status == 2);
    CHECK(b.out.empty());
    CHECK_THAT(b.err, Catch::StartsWith("erd info: " + dir.file("cut.erd") + ": "));
    CHECK(b.err.find('\n') == b.err.size() - 1);
}

TEST_CASE("erd info on an .erdz: the mesh line with edge kinds, the file's bytes in the JSON", "[cli][info][erdz]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("s.pgm"), z = dir.file("m.erdz");
    REQUIRE(run_erd("synth --kind cartoon -W 64 -H 48 -o " + sh_quote(img)).status == 0);
    REQUIRE(run_erd("generate -q -m erdgpi -i " + sh_quote(img) + " -d 3 -o " + sh_quote(z)).status == 0);
    RunResult t = run_erd("info " + sh_quote(z));
    REQUIRE(t.status == 0);
    CHECK_THAT(t.out, Catch::Contains("format:    erdz 3, erd (hard edges) model, method erdgpi"));
    // As many hard edges as constrained edges: "mesh: V vertices, F faces, N constrained edges (N hard)".
    const std::size_t m = t.out.find("mesh:");
    REQUIRE(m != std::string::npos);
    const std::string mesh = t.out.substr(m, t.out.find('\n', m) - m);
    const std::size_t f = mesh.find("faces, ");
    REQUIRE(f != std::string::npos);
    const std::string n = mesh.substr(f + 7, mesh.find(' ', f + 7) - (f + 7));
    CHECK(std::stoi(n) > 0);
    CHECK_THAT(mesh, Catch::EndsWith("constrained edges (" + n + " hard)"));
    RunResult j = run_erd("info --json " + sh_quote(z));
    REQUIRE(j.status == 0);
    CHECK_THAT(j.out, Catch::Contains("\"edge_kinds\":{\"hard\":" + n + "}"));
    CHECK_THAT(j.out, Catch::Contains("\"bytes\":" + std::to_string(slurp(z).size()) + ","));
}

TEST_CASE("erd info - tells a model from an image on standard input, from a pipe or a file", "[cli][info]") {
    if (!need_binary()) return;
    TempDir dir;
    const std::string img = dir.file("s.pgm");
    REQUIRE(run_erd("synth --kind cartoon -W 64 -H 48 -o " + sh_quote(img)).status == 0);
    for (const char* name : {"m.model", "m.erd", "m.erdz"}) {
        const std::string path = dir.file(name);
        REQUIRE(run_erd(std::string("generate -q -m ") + (name[2] == 'm' ? "gpi" : "erdgpi") + " -i " + sh_quote(img) +
                        " -d 3 -o " + sh_quote(path)).status == 0);
        const RunResult named = run_erd("info --json " + sh_quote(path));
        REQUIRE(named.status == 0);
        // The same facts as by its name, but the file's name.
        std::string expected = named.out;
        const std::string field = "\"file\":\"" + path + "\"";
        REQUIRE(expected.find(field) != std::string::npos);
        expected.replace(expected.find(field), field.size(), "\"file\":\"-\"");
        for (const RunResult& r : {run_erd("info --json - < " + sh_quote(path)),       // a file
                                   run_erd("info --json -", "cat " + sh_quote(path) + " |")}) {  // a pipe
            INFO(name);
            CHECK(r.status == 0);
            CHECK(r.err.empty());
            CHECK(r.out == expected);
        }
    }
    const RunResult image = run_erd("info -", "cat " + sh_quote(img) + " |");
    CHECK(image.status == 0);
    CHECK_THAT(image.out, Catch::Contains("PGM (P5, raw)"));
}

TEST_CASE("erd help ends with the three commands most people need, and they run as printed", "[cli][info]") {
    if (!need_binary()) return;
    RunResult h = run_erd("help");
    REQUIRE(h.status == 0);
    const std::size_t e = h.out.rfind("\nExamples:\n");
    REQUIRE(e != std::string::npos);
    std::vector<std::string> commands;
    for (std::size_t i = e + 11; i < h.out.size();) {
        const std::size_t j = h.out.find('\n', i);
        const std::string line = h.out.substr(i, j - i);
        i = j == std::string::npos ? h.out.size() : j + 1;
        REQUIRE(line.compare(0, 6, "  erd ") == 0);
        commands.push_back(line.substr(6, line.find("   ") - 6));  // the command, without its comment
    }
    REQUIRE(commands.size() == 3);
    CHECK(commands[0].compare(0, 9, "generate ") == 0);
    CHECK(commands[1].compare(0, 12, "reconstruct ") == 0);
    CHECK(commands[2].compare(0, 5, "psnr ") == 0);
    // Run them in a folder holding photo.png: the last prints a PSNR.
    TempDir dir;
    REQUIRE(run_erd("synth -W 96 -H 64 -o " + sh_quote(dir.file("photo.png"))).status == 0);
    RunResult r;
    for (const std::string& c : commands) {
        INFO(c);
        r = run_in(dir.path, sh_quote(erd_bin()) + " " + c);
        INFO(r.err);
        REQUIRE(r.status == 0);
    }
    CHECK(std::stod(r.out) > 25.0);
}
