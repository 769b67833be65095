#include "algorithms/mesh_edges.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace erd {

namespace {

struct HalfEdge {
    std::uint32_t a, b;    // a < b
    std::uint32_t face;
    bool operator<(const HalfEdge& o) const {
        if (a != o.a) return a < o.a;
        if (b != o.b) return b < o.b;
        return face < o.face;
    }
};

int corner_of(const Model& m, std::uint32_t f, std::uint32_t v) {
    for (int i = 0; i < 3; ++i)
        if (m.faces[f][std::size_t(i)] == v) return i;
    return 0;  // unreachable for edges built from f
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];  // path halving keeps chains short without recursion
        x = parent[x];
    }
    return x;
}

}  // namespace

Status mesh_edges(const Model& m, std::vector<MeshEdge>* out) {
    out->clear();
    const std::size_t nv = m.vertices.size();
    std::vector<HalfEdge> hs;
    hs.reserve(m.faces.size() * 3);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& t = m.faces[f];
        for (int i = 0; i < 3; ++i) {
            if (t[std::size_t(i)] >= nv)
                return Status::bad_input("face " + std::to_string(f) + " names vertex " +
                                         std::to_string(t[std::size_t(i)]) + " of " + std::to_string(nv));
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            return Status::bad_input("face " + std::to_string(f) + " repeats a vertex");
        for (int i = 0; i < 3; ++i) {
            std::uint32_t u = t[std::size_t(i)], w = t[std::size_t((i + 1) % 3)];
            hs.push_back({std::min(u, w), std::max(u, w), std::uint32_t(f)});
        }
    }
    std::sort(hs.begin(), hs.end());

    std::vector<std::array<std::uint32_t, 2>> cons = m.constraints;
    for (auto& c : cons)
        if (c[0] > c[1]) std::swap(c[0], c[1]);
    std::sort(cons.begin(), cons.end());

    for (std::size_t i = 0; i < hs.size();) {
        std::size_t j = i;
        while (j < hs.size() && hs[j].a == hs[i].a && hs[j].b == hs[i].b) ++j;
        if (j - i > 2)
            return Status::bad_input("edge " + std::to_string(hs[i].a) + "-" + std::to_string(hs[i].b) +
                                     " belongs to more than two faces");
        MeshEdge e;
        e.a = hs[i].a;
        e.b = hs[i].b;
        e.left = hs[i].face;
        if (j - i == 2) e.right = hs[i + 1].face;
        e.constrained = std::binary_search(cons.begin(), cons.end(), std::array<std::uint32_t, 2>{e.a, e.b});
        if (!e.constrained && e.right != kNoMeshFace && m.kind == ModelKind::erd && m.corner_values.size() == m.faces.size()) {
            for (std::uint32_t v : {e.a, e.b}) {
                double l = face_corner_value(m, e.left, corner_of(m, e.left, v));
                double r = face_corner_value(m, e.right, corner_of(m, e.right, v));
                if (l != r) e.constrained = true;
            }
        }
        out->push_back(e);
        i = j;
    }
    return Status::success();
}

void corner_wedges(const Model& m, const std::vector<MeshEdge>& edges,
                   std::vector<std::array<std::uint32_t, 3>>* wedge, std::vector<std::uint32_t>* first_vertex_wedge,
                   std::uint32_t* count) {
    const std::size_t nf = m.faces.size(), nv = m.vertices.size();
    std::vector<std::uint32_t> parent(nf * 3);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const MeshEdge& e : edges) {
        if (e.constrained || e.right == kNoMeshFace) continue;
        for (std::uint32_t v : {e.a, e.b}) {
            std::uint32_t x = find_root(parent, e.left * 3 + std::uint32_t(corner_of(m, e.left, v)));
            std::uint32_t y = find_root(parent, e.right * 3 + std::uint32_t(corner_of(m, e.right, v)));
            if (x != y) parent[std::max(x, y)] = std::min(x, y);
        }
    }
    // Corners grouped by vertex (counting sort keeps face order inside a vertex).
    std::vector<std::uint32_t> start(nv + 1, 0), order(nf * 3);
    for (const auto& t : m.faces)
        for (std::uint32_t v : t) ++start[v + 1];
    for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < nf * 3; ++c) order[fill[m.faces[c / 3][c % 3]]++] = std::uint32_t(c);

    const std::uint32_t none = 0xffffffffu;
    std::vector<std::uint32_t> label_of_root(nf * 3, none);
    wedge->assign(nf, {0, 0, 0});
    first_vertex_wedge->assign(nv + 1, 0);
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        (*first_vertex_wedge)[v] = next;
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
            std::uint32_t c = order[k];
            std::uint32_t r = find_root(parent, c);
            if (label_of_root[r] == none) label_of_root[r] = next++;
            (*wedge)[c / 3][c % 3] = label_of_root[r];
        }
    }
    (*first_vertex_wedge)[nv] = next;
    *count = next;
}

}  // namespace erd
