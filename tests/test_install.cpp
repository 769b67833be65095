// Installing: `make install DESTDIR=...` puts the public headers only (api/erd.h and what it
// includes) and no generic program names (`make install-aliases` adds them), a program and
// docs/examples/embedded.cpp build against the installed copy with pkg-config; the man page
// names every subcommand and option; `make help` lists every target.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

// The source tree (for make): $ERD_SRC, else the current folder when it is one.
std::string source_tree() {
    const char* s = std::getenv("ERD_SRC");
    std::string root = s && *s ? s : ".";
    if (!exists(root + "/Makefile") || !exists(root + "/cli/thesis_alias.cpp") || !exists(root + "/docs/erd.1")) return "";
    return absolute(root);
}

// The lines of text, sorted bytewise, each ending in '\n'.
std::string sorted_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    std::sort(lines.begin(), lines.end());
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

std::string dirname_of(const std::string& p) {
    std::string::size_type slash = p.rfind('/');
    return slash == std::string::npos ? "." : p.substr(0, slash);
}

const char* const kInstalledProgram = R"(// Built against the installed copy only.
#include <erd/erd.h>
#include <cstdio>
#include <vector>
int main() {
    const int w = 40, h = 30;
    std::vector<std::uint16_t> px(w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) px[y * w + x] = std::uint16_t((x - 20) * (x - 20) + (y - 12) * (y - 12) < 64 ? 220 : 30 + x + y);
    erd::api::ImageView view{w, h, 255, px.data(), 0};
    erd::api::Options opt;
    opt.generate.points = 60;
    opt.exact = erd::api::ExactMode::ignore;
    erd::Model model;
    erd::api::GenerateInfo info;
    erd::Status st = erd::api::generate(erd::api::Method::erdgpi, view, opt, &model, &info);
    if (!st) { std::printf("generate: %s\n", st.message.c_str()); return 1; }
    if (info.achieved != model.vertices.size() || info.requested != 60) return 1;
    erd::Image rec;
    if (!erd::api::reconstruct(model, true, &rec)) return 1;
    double db = 0;
    if (!erd::api::psnr(view, erd::api::view_of(rec), &db)) return 1;
    erd::Cdt cdt;   // the kernel on its own
    if (!cdt.reset(10, 10)) return 1;
    erd::VertInd v = 0;
    if (!cdt.insert_point(erd::LatticePoint{5, 5}, &v) || !cdt.insert_point(erd::LatticePoint{2, 7}, &v)) return 1;
    std::string why;
    std::printf("vertices %zu psnr %.1f cdt faces %zu verify %d\n", model.vertices.size(), db, cdt.face_count(), int(cdt.verify(&why)));
    return 0;
}
)";

}  // namespace

TEST_CASE("make install DESTDIR=..., a program built with pkg-config against it, make uninstall", "[packaging]") {
    if (!need_binary()) return;
    const std::string root = source_tree();
    if (!have_input(!root.empty(), "source tree not found (run from the repository or set ERD_SRC)")) return;
    // BUILD spelled as the Makefile spells it after normalising (relative to the tree when inside
    // it), so the -o names below match its targets and nothing is rebuilt with other flags.
    std::string build = absolute(dirname_of(erd_bin()));
    if (build.compare(0, root.size() + 1, root + "/") == 0) build = build.substr(root.size() + 1);
    // (a build dir that is the tree itself stays absolute, as the Makefile leaves it)
    if (!have_input(exists((build[0] == '/' ? build : root + "/" + build) + "/liberd.a"), build + "/liberd.a missing")) return;
    TempDir dest;
    const std::string prefix = "/opt/erd";
    // -o: install what the build dir holds; never rebuild someone's objects from here.
    const std::string make = "make -s -C " + sh_quote(root) + " BUILD=" + sh_quote(build) + " PREFIX=" + prefix +
                             " DESTDIR=" + sh_quote(dest.path) + " -o " + sh_quote(build + "/erd") + " -o " +
                             sh_quote(build + "/liberd.a");
    const std::string lib_path = (build[0] == '/' ? build : root + "/" + build) + "/liberd.a";
    struct stat before {};
    ::stat(lib_path.c_str(), &before);
    RunResult inst = run_in(dest.path, make + " install");
    INFO(inst.err);
    REQUIRE(inst.status == 0);
    struct stat after {};
    ::stat(lib_path.c_str(), &after);
    CHECK(after.st_mtime == before.st_mtime);  // installed as built, nothing rebuilt
    CHECK(exists(erd_bin()));
    const std::string top = dest.path + prefix;
    for (const char* f : {"bin/erd", "lib/liberd.a", "lib/pkgconfig/erd.pc", "share/man/man1/erd.1", "include/erd/erd.h",
                          "include/erd/api/erd.h", "include/erd/algorithms/model/model.h", "include/erd/kernel/cdt.h",
                          "include/erd/kernel/status.h"}) {
        INFO(f);
        CHECK(exists(top + "/" + f));
    }
    // Only the public headers: api/erd.h and what it includes (make public-headers, the compiler's
    // list), not every internal header; no generic program names without install-aliases.
    RunResult pub = run_in(root, "make -s public-headers");
    REQUIRE(pub.status == 0);
    RunResult headers = run_in(top + "/include/erd", "find . -type f | sed 's|^\\./||' | LC_ALL=C sort");
    CHECK(headers.out == sorted_lines("erd.h\n" + pub.out));
    CHECK(pub.out.find("api/erd.h\n") != std::string::npos);
    CHECK(pub.out.find("algorithms/methods/methods.h") == std::string::npos);  // internal: not installed
    // docs/manual.md lists them (one per line, indented, in its "Installing" section).
    const std::string manual = slurp(root + "/docs/manual.md");
    std::istringstream pub_lines(pub.out);
    for (std::string h; std::getline(pub_lines, h);) {
        INFO("docs/manual.md lists the public header " << h);
        const bool listed = manual.find("\n    " + h + "\n") != std::string::npos ||
                            manual.find("\n    " + h + " ") != std::string::npos;
        CHECK(listed);
    }
    for (const char* a : kAliases) {
        INFO(a);
        CHECK_FALSE(exists(top + "/bin/" + a));
        CHECK_FALSE(exists(top + "/share/man/man1/" + std::string(a) + ".1"));
    }
    RunResult aliases = run_in(dest.path, make + " install-aliases");
    INFO(aliases.err);
    REQUIRE(aliases.status == 0);
    CHECK(exists(top + "/share/man/man1/ywb.1"));
    CHECK(exists(top + "/share/man/man1/Cal_PSNR.1"));
    for (const char* a : kAliases) {
        INFO(a);
        char target[64] = {};
        ssize_t n = ::readlink((top + "/bin/" + a).c_str(), target, sizeof target - 1);
        CHECK(n == 3);
        CHECK(std::string(target) == "erd");
    }
    std::string pc = slurp(top + "/lib/pkgconfig/erd.pc");
    CHECK_THAT(pc, Catch::Contains("prefix=/opt/erd"));
    CHECK_THAT(pc, Catch::Contains("-lerd"));
    // The installed alias runs as the thesis's program.
    RunResult cal = run_in(dest.path, sh_quote(top + "/bin/Cal_PSNR") + " " + sh_quote(root + "/docs/erd.1") + " x");
    CHECK(cal.status == 2);  // not images: the error comes from erd psnr, reached through the link

    // The headers are installed from the tree, the library from the build dir: when a header was
    // edited after the library was built (helpers share one tree) the two disagree and a program
    // built against them is meaningless. After `make` they always agree.
    RunResult newer = run_in(root, "find kernel algorithms api -name '*.h' -newer " + sh_quote(build + "/liberd.a"));
    if (std::getenv("ERD_SANITIZED")) {
        WARN("sanitized build: liberd.a needs the sanitizer runtime, the pkg-config program is not linked");
    } else if (!newer.out.empty()) {
        WARN("headers newer than " + build + "/liberd.a (rebuild first); the pkg-config program is not built: " + newer.out);
    } else {
        spit(dest.file("prog.cpp"), kInstalledProgram);
        const std::string env = "PKG_CONFIG_PATH=" + sh_quote(top + "/lib/pkgconfig") + " PKG_CONFIG_SYSROOT_DIR=" + sh_quote(dest.path);
        RunResult flags = run_in(dest.path, env + " pkg-config --cflags --libs erd");
        INFO(flags.out + flags.err);
        REQUIRE(flags.status == 0);
        CHECK_THAT(flags.out, Catch::Contains(top + "/include/erd"));
        // Compiled in the DESTDIR, away from the source tree: only the installed headers are seen.
        RunResult cc = run_in(dest.path, "c++ -std=c++17 -O1 prog.cpp $(" + env + " pkg-config --cflags --libs erd) -o prog");
        INFO(cc.err);
        REQUIRE(cc.status == 0);
        RunResult prog = run_in(dest.path, "./prog");
        INFO(prog.out);
        CHECK(prog.status == 0);
        CHECK_THAT(prog.out, Catch::StartsWith("vertices "));
        CHECK_THAT(prog.out, Catch::Contains(" psnr "));
        CHECK_THAT(prog.out, Catch::EndsWith("cdt faces 6 verify 1\n"));
        // The shipped example too, copied out of the tree.
        spit(dest.file("embedded.cpp"), slurp(root + "/docs/examples/embedded.cpp"));
        RunResult ecc = run_in(dest.path, "c++ -std=c++17 -O1 embedded.cpp $(" + env + " pkg-config --cflags --libs erd) -o embedded");
        INFO(ecc.err);
        REQUIRE(ecc.status == 0);
        RunResult ex = run_in(dest.path, "./embedded");
        INFO(ex.out + ex.err);
        CHECK(ex.status == 0);
        CHECK_THAT(ex.out, Catch::Contains("erdgpi: "));
    }

    RunResult un = run_in(dest.path, make + " uninstall");
    INFO(un.err);
    CHECK(un.status == 0);
    RunResult left = run_in(dest.path, "find " + sh_quote(top) + " ! -type d");
    CHECK(left.out.empty());
}

TEST_CASE("erd(1) names every subcommand, every generate option and all seven thesis programs", "[packaging]") {
    if (!need_binary()) return;
    const std::string root = source_tree();
    if (!have_input(!root.empty(), "source tree not found (run from the repository or set ERD_SRC)")) return;
    // roff writes "-" as "\-"; undo that to search the text.
    std::string man = slurp(root + "/docs/erd.1");
    std::string text;
    for (std::size_t i = 0; i < man.size(); ++i) {
        if (man[i] == '\\' && i + 1 < man.size() && man[i + 1] == '-') continue;
        text += man[i];
    }
    RunResult help = run_erd("help");
    REQUIRE(help.status == 0);
    std::size_t pos = help.out.find("Subcommands:");
    REQUIRE(pos != std::string::npos);
    std::istringstream lines(help.out.substr(pos));
    std::string line;
    std::getline(lines, line);
    int subs = 0;
    while (std::getline(lines, line) && line.size() > 2 && line[0] == ' ') {
        std::string name = line.substr(2, line.find(' ', 2) - 2);
        INFO(name);
        CHECK(text.find("erd " + name) != std::string::npos);
        ++subs;
    }
    CHECK(subs >= 8);
    RunResult gen = run_erd("generate --help");
    REQUIRE(gen.status == 0);
    int opts = 0;
    for (std::size_t p = gen.out.find("--"); p != std::string::npos; p = gen.out.find("--", p + 2)) {
        std::size_t e = p + 2;
        while (e < gen.out.size() && (std::isalnum(static_cast<unsigned char>(gen.out[e])) || gen.out[e] == '-')) ++e;
        std::string opt = gen.out.substr(p, e - p);
        if (opt.size() < 4) continue;
        INFO(opt);
        CHECK(text.find(opt) != std::string::npos);
        ++opts;
    }
    CHECK(opts >= 20);
    for (const char* a : kAliases) CHECK(text.find(std::string(".B ") + a) != std::string::npos);
    CHECK(text.find(".SH EXIT STATUS") != std::string::npos);
}

TEST_CASE("make help lists every target of the Makefile", "[packaging]") {
    const std::string root = source_tree();
    if (!have_input(!root.empty(), "source tree not found (run from the repository or set ERD_SRC)")) return;
    RunResult help = run_in(root, "make -s help");
    REQUIRE(help.status == 0);
    // The .PHONY lists name every target that is not a file.
    std::istringstream mk(slurp(root + "/Makefile"));
    int targets = 0;
    for (std::string line; std::getline(mk, line);) {
        if (line.rfind(".PHONY:", 0) != 0) continue;
        std::istringstream names(line.substr(7));
        for (std::string t; names >> t;) {
            INFO(t);
            CHECK_THAT(help.out, Catch::Contains("make " + t + " ") || Catch::Contains("make, make " + t + " ") ||
                                     Catch::Contains("make " + t + "\n"));
            ++targets;
        }
    }
    CHECK(targets >= 18);
}
