// check_model: an ERD model is what the kernel makes of its points and constraints (verify()
// passes, the same faces, or a triangulation of them that flips made: check_flipped_model) and
// every face corner carries the value of the wedge it lies in. check_same_step1: two ways to the
// framework's step 1 agree.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "algorithms/methods/erd_mesh.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/cdt.h"

namespace erd::test {

inline std::uint64_t key(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

// The model's faces are the CDT's (as point sets).
inline bool same_faces(const Cdt& cdt, const Model& m) {
    return canonical_faces(cdt) == canonical_faces(m.vertices, m.faces);
}

// A model whose faces are not the CDT's (data-dependent flips, algorithms/methods/flips.h):
// its faces are positive, tile the rectangle and form one fan around every vertex, every
// constraint piece of the CDT is one of its edges, and around every vertex consecutive faces
// not separated by a constrained edge carry the same corner value (one value per wedge).
inline void check_flipped_model(const Cdt& cdt, const std::vector<VertInd>& ids, const Model& m) {
    std::int64_t area = 0;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& f : m.faces) {
        const LatticePoint a = m.vertices[f[0]], b = m.vertices[f[1]], c = m.vertices[f[2]];
        const std::int64_t o = std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(c.x - a.x) * (b.y - a.y);
        REQUIRE(o > 0);
        area += o;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = f[std::size_t(k)], w = f[std::size_t((k + 1) % 3)];
            edges.insert({std::min(u, w), std::max(u, w)});
        }
    }
    REQUIRE(area == 2 * std::int64_t(cdt.max_x()) * cdt.max_y());
    std::vector<std::uint32_t> model_index(cdt.vertex_count(), 0);
    for (std::size_t i = 0; i < ids.size(); ++i) model_index[ids[i]] = std::uint32_t(i);
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    std::set<std::pair<std::uint32_t, std::uint32_t>> constrained;
    for (const auto& c : cons) {
        const std::uint32_t u = model_index[c[0]], w = model_index[c[1]];
        constrained.insert({std::min(u, w), std::max(u, w)});
        REQUIRE(edges.count({std::min(u, w), std::max(u, w)}) == 1);
    }
    ModelTopology t;
    REQUIRE(build_topology(m, &t).ok());
    std::vector<std::uint32_t> fan;
    for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
        bool closed = false;
        REQUIRE(vertex_fan(t, v, &fan, &closed).ok());
        for (std::size_t i = 0; i + 1 < fan.size() + (closed ? 1 : 0); ++i) {
            const std::uint32_t h = fan[i], g = fan[(i + 1) % fan.size()];
            const std::uint32_t w = m.faces[h / 3][(h % 3 + 1) % 3];  // the edge v-w between them
            if (constrained.count({std::min(v, w), std::max(v, w)})) continue;
            CHECK(corner_value(m, h) == corner_value(m, g));
        }
    }
}

// Rebuilds the CDT of an ERD model from its points and constraints, checks it with verify(),
// checks that its faces are the model's faces, and that every face corner carries the value of
// the wedge it lies in (faces of one wedge agree; the vertex value is the mean of its wedges), in
// every channel of a colour model.
inline void check_model(const Model& m) {
    REQUIRE(m.kind == ModelKind::erd);
    const std::size_t C = std::size_t(m.channels);
    REQUIRE((C == 1 || C == 3));
    REQUIRE(m.values.size() == m.vertices.size() * C);
    REQUIRE(m.corner_values.size() == m.faces.size() * C);
    Cdt cdt;
    REQUIRE(cdt.reset(2 * m.width - 2, 2 * m.height - 2).ok());
    std::vector<VertInd> ids;
    REQUIRE(cdt.insert_points(m.vertices, &ids).ok());
    REQUIRE(cdt.vertex_count() == m.vertices.size());  // no duplicates
    for (const auto& c : m.constraints) {
        ConstraintReport rep;
        REQUIRE(cdt.insert_constraint(ids[c[0]], ids[c[1]], &rep).ok());
        CHECK(rep.dropped_crossing == 0);
    }
    std::string why;
    INFO(why);
    REQUIRE(cdt.verify(&why));
    REQUIRE(cdt.face_count() == m.faces.size());
    if (!same_faces(cdt, m)) {
        check_flipped_model(cdt, ids, m);
        return;
    }

    // Model faces by their point triple (rotated to start at the smallest key).
    std::map<std::array<std::uint64_t, 3>, std::size_t> face_of_points;
    auto triple = [](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
        std::array<std::uint64_t, 3> t{a, b, c};
        while (!(t[0] < t[1] && t[0] < t[2])) t = {t[1], t[2], t[0]};
        return t;
    };
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const LatticePoint a = m.vertices[m.faces[f][0]], b = m.vertices[m.faces[f][1]], c = m.vertices[m.faces[f][2]];
        const std::int64_t area = std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(c.x - a.x) * (b.y - a.y);
        REQUIRE(area > 0);
        face_of_points[triple(key(a), key(b), key(c))] = f;
    }
    // Corner value in channel c of model face f at its vertex with point p.
    auto corner = [&](FaceInd cf, VertInd v, std::size_t c) {
        const EdgeInd e = 3 * cf;
        const auto t = triple(key(cdt.point(cdt.org(e))), key(cdt.point(cdt.org(e + 1))), key(cdt.point(cdt.org(e + 2))));
        auto it = face_of_points.find(t);
        REQUIRE(it != face_of_points.end());
        const std::size_t f = it->second;
        for (int i = 0; i < 3; ++i)
            if (m.vertices[m.faces[f][std::size_t(i)]] == cdt.point(v)) return m.corner_values[f * C + c][std::size_t(i)];
        FAIL("vertex not in face");
        return 0.0;
    };
    std::vector<std::size_t> model_index(cdt.vertex_count(), 0);
    for (std::size_t i = 0; i < ids.size(); ++i) model_index[ids[i]] = i;
    std::vector<Wedge> wedges;
    for (VertInd v = 0; v < cdt.vertex_count(); ++v) {
        cdt.wedges(v, &wedges);
        REQUIRE(!wedges.empty());
        for (std::size_t c = 0; c < C; ++c) {
            double sum = 0;
            for (const Wedge& w : wedges) {
                EdgeInd e = w.first;
                const double z = corner(face_of(e), v, c);
                for (std::uint32_t i = 0; i < w.count; ++i) {
                    CHECK(corner(face_of(e), v, c) == z);
                    e = cdt.rot_next(e);
                }
                sum += z;
            }
            CHECK(m.values[model_index[v] * C + c] == Approx(sum / double(wedges.size())));
        }
    }
}


// Two ways to step 1 (algorithms/methods/erd_mesh.h) that must give the same initial mesh: the
// same parameters chosen and the same simplified polylines.
inline void check_same_step1(const InitialMesh& a, const InitialMesh& b) {
    CHECK(a.params.simple == b.params.simple);
    CHECK(a.params.beta == b.params.beta);
    CHECK(a.params.r == b.params.r);
    CHECK(a.params.l == b.params.l);
    CHECK(a.params.eps == b.params.eps);
    CHECK(a.params.constrained_points == b.params.constrained_points);
    CHECK(a.polylines == b.polylines);
}

}  // namespace erd::test
