// Binary STL export (issue 18): a heightmap's mesh parsed back: facet count, unit normals that
// agree with the corners' order, and with --base a watertight solid (every edge in exactly two
// facets, once in each direction).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "algorithms/imaging/synth.h"
#include "algorithms/methods/methods.h"
#include "algorithms/output/export.h"
#include "tests/output_util.h"

using namespace erd;

namespace {

using Vec3 = std::array<float, 3>;
struct Facet { Vec3 n, v[3]; };

float f32(const std::string& s, std::size_t at) {
    std::uint32_t u = 0;
    for (int k = 0; k < 4; ++k) u |= std::uint32_t(std::uint8_t(s[at + std::size_t(k)])) << (8 * k);
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

// Parses binary STL; fails the test on a wrong size.
std::vector<Facet> parse_stl(const std::string& s) {
    REQUIRE(s.size() >= 84);
    CHECK(s.compare(0, 5, "solid") != 0);  // readers take "solid" for ASCII STL
    std::uint32_t n = 0;
    for (int k = 0; k < 4; ++k) n |= std::uint32_t(std::uint8_t(s[80 + std::size_t(k)])) << (8 * k);
    REQUIRE(s.size() == 84 + 50 * std::size_t(n));
    std::vector<Facet> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t at = 84 + 50 * i;
        for (int k = 0; k < 3; ++k) out[i].n[std::size_t(k)] = f32(s, at + 4 * std::size_t(k));
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) out[i].v[c][std::size_t(k)] = f32(s, at + 12 + 12 * std::size_t(c) + 4 * std::size_t(k));
    }
    return out;
}

// Every normal has unit length and points along (v1 - v0) x (v2 - v0).
void check_normals(const std::vector<Facet>& facets) {
    for (const Facet& f : facets) {
        const float len = std::sqrt(f.n[0] * f.n[0] + f.n[1] * f.n[1] + f.n[2] * f.n[2]);
        CHECK(len == Approx(1.0f).margin(1e-5));
        const float ux = f.v[1][0] - f.v[0][0], uy = f.v[1][1] - f.v[0][1], uz = f.v[1][2] - f.v[0][2];
        const float vx = f.v[2][0] - f.v[0][0], vy = f.v[2][1] - f.v[0][1], vz = f.v[2][2] - f.v[0][2];
        const double dot = double(f.n[0]) * (uy * vz - uz * vy) + double(f.n[1]) * (uz * vx - ux * vz) +
                           double(f.n[2]) * (ux * vy - uy * vx);
        CHECK(dot > 0);
    }
}

// Watertight and consistently oriented: each directed edge once, and its reverse once.
bool watertight(const std::vector<Facet>& facets) {
    std::map<std::pair<Vec3, Vec3>, int> directed;
    for (const Facet& f : facets)
        for (int k = 0; k < 3; ++k) ++directed[{f.v[k], f.v[(k + 1) % 3]}];
    for (const auto& e : directed) {
        if (e.second != 1) return false;
        const auto r = directed.find({e.first.second, e.first.first});
        if (r == directed.end() || r->second != 1) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("STL of the diagonal: 2 facets up, 12 closed with a base", "[output][stl]") {
    ExportOptions o;
    o.format = MeshFormat::stl;
    o.zscale = 0.5;
    std::string stl;
    ExportCounts c;
    REQUIRE(export_mesh(output_test::diagonal_basic(), o, &stl, &c).ok());
    std::vector<Facet> f = parse_stl(stl);
    REQUIRE(f.size() == 2);
    CHECK(c.facets == 2);
    check_normals(f);
    for (const Facet& t : f) CHECK(t.n[2] > 0);  // the surface faces up
    CHECK(!watertight(f));

    o.base = 3;
    REQUIRE(export_mesh(output_test::diagonal_basic(), o, &stl, &c).ok());
    f = parse_stl(stl);
    REQUIRE(f.size() == 2 * 2 + 2 * 4);  // top, bottom, two per boundary edge
    check_normals(f);
    CHECK(watertight(f));
    CHECK(f[0].v[0][2] == Approx(127 * 0.5 + 3));  // lifted by the base

    // An ERD surface is open along its constrained edges: no solid from it.
    CHECK(export_mesh(output_test::diagonal_erd(), o, &stl, &c).code == Code::input);
    o.base = 0;
    REQUIRE(export_mesh(output_test::diagonal_erd(), o, &stl, &c).ok());
    CHECK(parse_stl(stl).size() == 2);
}

TEST_CASE("STL of a GPI heightmap mesh: facet count, normals, watertight with a base", "[output][stl]") {
    const MethodInfo* gpi = find_method("gpi");
    REQUIRE(gpi);
    SynthParams sp;
    sp.width = 40;
    sp.height = 30;
    sp.bits = 16;
    sp.noise = false;
    Image im;
    REQUIRE(synth(sp, &im).ok());
    GenerateOptions opt;
    opt.points = 120;
    GenerateResult res;
    REQUIRE(gpi->run(im, opt, &res).ok());
    ExportOptions o;
    o.format = MeshFormat::stl;
    o.base = 10;
    std::string stl;
    ExportCounts c;
    REQUIRE(export_mesh(res.model, o, &stl, &c).ok());
    const std::vector<Facet> f = parse_stl(stl);
    // Euler for a triangulated disc: F = 2V - 2 - B with B boundary vertices (= boundary edges).
    const std::size_t v = res.model.vertices.size(), faces = res.model.faces.size(), b = 2 * v - 2 - faces;
    CHECK(f.size() == 2 * faces + 2 * b);
    CHECK(c.facets == f.size());
    check_normals(f);
    CHECK(watertight(f));
}
