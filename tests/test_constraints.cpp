// User constraints (issue 18, --constraints / --no-detect): every user segment is a chain of
// constrained edges of the ERD model, whatever the order of the polylines and of their points;
// crossing user segments and points outside the image are refused, duplicates merge.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "algorithms/imaging/synth.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/model_io.h"
#include "tests/erd_run.h"
#include "tests/synth_util.h"

using namespace erd;

namespace {

Image small_synth() { return erd_test::synth_image(48, 40); }

using Lines = std::vector<std::vector<LatticePoint>>;

// (0,0)..(94,78) is the doubled domain of 48 x 40. A bent line, a closed triangle, a lone point.
Lines user_lines() {
    return {{{4, 6}, {30, 20}, {60, 20}}, {{70, 40}, {90, 70}, {50, 70}, {70, 40}}, {{10, 70}}};
}

GenerateResult run(const char* method, const Lines& lines, bool detect) {
    const MethodInfo* m = find_method(method);
    REQUIRE(m);
    GenerateOptions opt;
    opt.points = 120;
    opt.constraints = lines;
    opt.detect = detect;
    GenerateResult res;
    REQUIRE(m->run(small_synth(), opt, &res).ok());
    return res;
}

bool on_segment(LatticePoint p, LatticePoint a, LatticePoint b) {
    const std::int64_t cross = std::int64_t(b.x - a.x) * (p.y - a.y) - std::int64_t(b.y - a.y) * (p.x - a.x);
    return cross == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Segment a-b is a chain of the model's constrained edges through vertices on it.
bool has_segment(const Model& m, LatticePoint a, LatticePoint b) {
    auto vertex = [&](LatticePoint p) {
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
            if (m.vertices[i] == p) return std::int64_t(i);
        return std::int64_t(-1);
    };
    std::int64_t cur = vertex(a);
    const std::int64_t end = vertex(b);
    if (cur < 0 || end < 0) return false;
    std::set<std::int64_t> seen{cur};
    while (cur != end) {
        std::int64_t next = -1;
        for (const auto& e : m.constraints)
            for (int s = 0; s < 2; ++s)
                if (std::int64_t(e[s]) == cur && !seen.count(e[1 - s]) && on_segment(m.vertices[e[1 - s]], a, b))
                    next = e[1 - s];
        if (next < 0) return false;
        seen.insert(next);
        cur = next;
    }
    return true;
}

void check_all_present(const Model& m, const Lines& lines) {
    for (const auto& pl : lines) {
        for (const LatticePoint p : pl)
            CHECK(std::find(m.vertices.begin(), m.vertices.end(), p) != m.vertices.end());
        for (std::size_t k = 0; k + 1 < pl.size(); ++k) CHECK(has_segment(m, pl[k], pl[k + 1]));
    }
}

}  // namespace

TEST_CASE("user constraints are constrained edges of both ERD methods, in any order", "[erd][constraints]") {
    Lines reordered = user_lines();
    std::reverse(reordered.begin(), reordered.end());
    for (auto& pl : reordered) std::reverse(pl.begin(), pl.end());
    for (const char* method : {"erdgpi", "erded"}) {
        INFO(method);
        for (bool detect : {true, false}) {
            INFO("detect " << detect);
            const GenerateResult a = run(method, user_lines(), detect);
            const GenerateResult b = run(method, reordered, detect);
            CHECK(a.achieved == 120);
            check_all_present(a.model, user_lines());
            check_all_present(b.model, user_lines());
            if (!detect) {
                // Without detection the user's segments are the only constrained edges: 2 + 3 pieces,
                // more only where a vertex landed on one.
                CHECK(a.model.constraints.size() >= 5);
                for (const auto& e : a.model.constraints) {
                    bool on = false;
                    for (const auto& pl : user_lines())
                        for (std::size_t k = 0; k + 1 < pl.size(); ++k)
                            on = on || (on_segment(a.model.vertices[e[0]], pl[k], pl[k + 1]) &&
                                        on_segment(a.model.vertices[e[1]], pl[k], pl[k + 1]));
                    CHECK(on);
                }
            }
        }
    }
}

TEST_CASE("user constraints: duplicates merge, crossings and outside points are refused", "[erd][constraints]") {
    const MethodInfo* m = find_method("erdgpi");
    REQUIRE(m);
    const Image im = small_synth();
    auto status = [&](const Lines& lines) {
        GenerateOptions opt;
        opt.points = 120;
        opt.constraints = lines;
        GenerateResult res;
        return m->run(im, opt, &res);
    };
    // The same polyline twice, one overlapping it, and a reversed copy: one set of segments.
    const Lines dup = {{{4, 6}, {30, 20}}, {{4, 6}, {30, 20}}, {{30, 20}, {4, 6}}, {{4, 6}, {56, 34}}};
    CHECK(status(dup).ok());
    // Two segments crossing between lattice points of neither.
    const Status cross = status({{{0, 0}, {40, 40}}, {{0, 40}, {40, 0}}});
    CHECK(cross.code == Code::input);
    CHECK(cross.message.find("crosses") != std::string::npos);
    // Meeting at a shared end point is not a crossing.
    CHECK(status({{{0, 0}, {20, 20}}, {{20, 20}, {40, 0}}}).ok());
    CHECK(status({{{0, 0}, {95, 10}}}).code == Code::input);   // x beyond 2W - 2 = 94
    CHECK(status({{{0, 0}, {10, -1}}}).code == Code::input);
    // More points than N - 4.
    Lines many;
    for (int y : {10, 30, 50}) {  // 3 x 48 = 144 distinct points > 116
        many.emplace_back();
        for (int x = 0; x <= 94; x += 2) many.back().push_back({x, y});
    }
    CHECK(status(many).code == Code::input);
}

TEST_CASE("generate --constraints: in the .tri; bad files and other methods refused in one line", "[erd][constraints][cli]") {
    using namespace erd_test;
    if (!need_binary()) return;
    TempDir dir;
    // A 24 x 18 gray ramp (P5).
    std::string pgm = "P5\n24 18\n255\n";
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 24; ++x) pgm += char(x * 10 + (x > 12 ? 60 : 0));
    spit(dir.file("in.pgm"), pgm);
    spit(dir.file("c.poly"), "erd-polylines 1\n1\n3 4 4 20 30 40 30\n");
    const std::string base = "generate -i " + sh_quote(dir.file("in.pgm")) + " -n 40 -q -x 2 ";
    RunResult r = run_erd(base + "--method erdgpi --no-detect --constraints " + sh_quote(dir.file("c.poly")) +
                          " -o " + sh_quote(dir.file("m.erd")) + " -t " + sh_quote(dir.file("m.tri")));
    INFO(r.err);
    REQUIRE(r.status == 0);
    Model tri;
    REQUIRE(read_triangulation(slurp(dir.file("m.tri")), &tri).ok());
    CHECK(has_segment(tri, {4, 4}, {20, 30}));
    CHECK(has_segment(tri, {20, 30}, {40, 30}));
    // Each bad case: exit 2 and one line on stderr.
    spit(dir.file("bad.poly"), "erd-polylines 1\n1\n2 4 4 20\n");
    spit(dir.file("out.poly"), "erd-polylines 1\n1\n2 4 4 60 4\n");
    for (const std::string& args :
         {"--method erdgpi --constraints " + sh_quote(dir.file("bad.poly")),
          "--method erded --constraints " + sh_quote(dir.file("out.poly")),
          "--method erdgpi --constraints " + sh_quote(dir.file("missing.poly")),
          "--method gpi --constraints " + sh_quote(dir.file("c.poly"))}) {
        const std::string out = dir.file(args.rfind("--method gpi", 0) == 0 ? "x.model" : "x.erd");
        RunResult b = run_erd(base + args + " -o " + sh_quote(out));
        INFO(args << ": " << b.err);
        CHECK(b.status == 2);
        CHECK((b.err.find(".poly") != std::string::npos || b.err.find("--constraints") != std::string::npos));
        CHECK(!exists(out));
    }
}
