// check_model: an ERD model is what the kernel makes of its points and constraints (verify()
// passes, the same faces) and every face corner carries the value of the wedge it lies in.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "algorithms/model/model.h"
#include "kernel/cdt.h"

namespace erd::test {

inline std::uint64_t key(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

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


}  // namespace erd::test
