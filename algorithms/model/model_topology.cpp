// Adjacency of a Model from its face list (see model_topology.h).
#include "algorithms/model/model_topology.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

namespace erd {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

// Model::constraints as sorted (smaller, larger) vertex pairs, for lookups by edge.
using EdgeKeys = std::vector<std::array<std::uint32_t, 2>>;
EdgeKeys listed_constraints(const Model& m) {
    EdgeKeys listed = m.constraints;
    for (auto& c : listed)
        if (c[0] > c[1]) std::swap(c[0], c[1]);
    std::sort(listed.begin(), listed.end());
    return listed;
}

std::array<std::uint32_t, 2> edge_key(const Model& m, std::uint32_t h) {
    const std::uint32_t u = m.faces[h / 3][h % 3], w = m.faces[h / 3][(h + 1) % 3];
    return {std::min(u, w), std::max(u, w)};
}

// The edge of half-edge h is listed as a constraint or is a discontinuity.
bool constrained(const Model& m, const ModelTopology& t, const EdgeKeys& listed, std::uint32_t h) {
    return std::binary_search(listed.begin(), listed.end(), edge_key(m, h)) || is_discontinuity(m, t, h);
}

}  // namespace

Status build_topology(const Model& m, ModelTopology* t) {
    const std::size_t nv = m.vertices.size(), nf = m.faces.size();
    if (nf > (std::size_t(kNoHalfEdge) - 3) / 3) return Status::bad_input("too many faces");
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& c = m.faces[f];
        for (std::uint32_t v : c)
            if (v >= nv)
                return Status::bad_input("face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                                         " out of range");
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
            return Status::bad_input("face " + std::to_string(f) + " repeats a vertex");
    }
    t->corner_begin.assign(nv + 1, 0);
    for (const auto& f : m.faces)
        for (std::uint32_t v : f) ++t->corner_begin[v + 1];
    for (std::size_t v = 0; v < nv; ++v) t->corner_begin[v + 1] += t->corner_begin[v];
    t->corners.assign(3 * nf, 0);
    std::vector<std::uint32_t> fill(t->corner_begin.begin(), t->corner_begin.end() - 1);
    for (std::size_t h = 0; h < 3 * nf; ++h) t->corners[fill[m.faces[h / 3][h % 3]]++] = std::uint32_t(h);
    // Outgoing half-edges of each vertex as (destination, half-edge), sorted per vertex: a
    // repeated destination is a directed edge in two faces; the twin of u->w is found among w's.
    const auto dest = [&](std::uint32_t h) { return m.faces[h / 3][(h + 1) % 3]; };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out(3 * nf);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {dest(t->corners[i]), t->corners[i]};
    for (std::size_t v = 0; v < nv; ++v) {
        const auto b = out.begin() + t->corner_begin[v], e = out.begin() + t->corner_begin[v + 1];
        std::sort(b, e);
        for (auto it = b; it + 1 < e; ++it)
            if (it->first == (it + 1)->first)
                return Status::bad_input("faces " + std::to_string(it->second / 3) + " and " + std::to_string((it + 1)->second / 3) +
                                         " overlap (both contain the edge " + std::to_string(v) + "->" +
                                         std::to_string(it->first) + ")");
    }
    t->twin.assign(3 * nf, kNoHalfEdge);
    for (std::size_t h = 0; h < 3 * nf; ++h) {
        const std::uint32_t u = m.faces[h / 3][h % 3], w = dest(std::uint32_t(h));
        const auto b = out.begin() + t->corner_begin[w], e = out.begin() + t->corner_begin[w + 1];
        const auto it = std::lower_bound(b, e, std::make_pair(u, std::uint32_t(0)));
        if (it != e && it->first == u) t->twin[h] = it->second;
    }
    return Status::success();
}

bool is_discontinuity(const Model& m, const ModelTopology& t, std::uint32_t h) {
    if (m.kind != ModelKind::erd) return false;
    const std::uint32_t o = t.twin[h];
    if (o == kNoHalfEdge) return false;
    // h runs u->w in one face, o runs w->u in the other; a jump in any channel counts.
    if (m.channels == 1)
        return corner_value(m, h) != corner_value(m, ModelTopology::next(o)) ||
               corner_value(m, ModelTopology::next(h)) != corner_value(m, o);
    for (int c = 0; c < m.channels; ++c)
        if (corner_value(m, h, c) != corner_value(m, ModelTopology::next(o), c) ||
            corner_value(m, ModelTopology::next(h), c) != corner_value(m, o, c))
            return true;
    return false;
}

VertexWedges vertex_wedges(const Model& m, const ModelTopology& t, std::uint32_t v, int channel) {
    const std::uint32_t b = t.corner_begin[v], e = t.corner_begin[v + 1];
    if (b == e) return {0, m.values[std::size_t(v) * std::size_t(m.channels) + std::size_t(channel)]};
    bool uniform = true;
    for (int c = 0; c < m.channels && uniform; ++c) {  // every channel: the wedges are those of all of them
        const double first = corner_value(m, t.corners[b], c);
        for (std::uint32_t i = b + 1; i < e && uniform; ++i) uniform = corner_value(m, t.corners[i], c) == first;
    }
    if (uniform) return {1, corner_value(m, t.corners[b], channel)};
    // Runs of faces joined across edges that are not discontinuities (corners are sorted, so
    // the neighbour's local index is found by binary search).
    const std::uint32_t n = e - b;
    std::vector<std::uint32_t> parent(n);
    for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
    const auto first_c = t.corners.begin() + b, last_c = t.corners.begin() + e;
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t c = t.corners[b + i];
        if (t.twin[c] == kNoHalfEdge || is_discontinuity(m, t, c)) continue;
        const std::uint32_t nb = ModelTopology::next(t.twin[c]);
        const auto it = std::lower_bound(first_c, last_c, nb);
        if (it == last_c || *it != nb) continue;
        const std::uint32_t a = find_root(parent, i), r = find_root(parent, std::uint32_t(it - first_c));
        if (a != r) parent[a] = r;
    }
    VertexWedges w;
    double sum = 0.0;
    for (std::uint32_t i = 0; i < n; ++i)
        if (find_root(parent, i) == i) {
            ++w.count;
            sum += corner_value(m, t.corners[b + i], channel);
        }
    w.mean = sum / w.count;
    return w;
}

std::vector<ModelEdge> model_edges(const Model& m, const ModelTopology& t) {
    const EdgeKeys listed = listed_constraints(m);
    std::vector<ModelEdge> edges;
    edges.reserve(t.twin.size() / 2 + 2);
    for (std::uint32_t h = 0; h < t.twin.size(); ++h) {
        if (t.twin[h] != kNoHalfEdge && t.twin[h] < h) continue;  // each edge once
        const auto key = edge_key(m, h);
        edges.push_back({key[0], key[1], constrained(m, t, listed, h)});
    }
    std::sort(edges.begin(), edges.end(),
              [](const ModelEdge& x, const ModelEdge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    return edges;
}

CornerWedges corner_wedges(const Model& m, const ModelTopology& t) {
    const std::size_t nh = t.twin.size(), nv = t.corner_begin.size() - 1;
    const EdgeKeys listed = listed_constraints(m);
    // Union of the corners on both sides of every unconstrained interior edge, at both ends; the
    // smaller root wins, so each wedge's root is its first corner whatever the order of unions.
    std::vector<std::uint32_t> parent(nh);
    for (std::uint32_t i = 0; i < nh; ++i) parent[i] = i;
    const auto join = [&](std::uint32_t x, std::uint32_t y) {
        x = find_root(parent, x);
        y = find_root(parent, y);
        if (x != y) parent[std::max(x, y)] = std::min(x, y);
    };
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint32_t o = t.twin[h];
        if (o == kNoHalfEdge || o < h || constrained(m, t, listed, h)) continue;
        join(h, ModelTopology::next(o));  // corners at u
        join(ModelTopology::next(h), o);  // corners at w
    }
    CornerWedges cw;
    cw.label.assign(nh, 0);
    cw.first.assign(nv + 1, 0);
    const std::uint32_t none = kNoHalfEdge;
    std::vector<std::uint32_t> label_of_root(nh, none);
    for (std::size_t v = 0; v < nv; ++v) {
        cw.first[v] = cw.count;
        for (std::uint32_t i = t.corner_begin[v]; i < t.corner_begin[v + 1]; ++i) {
            const std::uint32_t c = t.corners[i], r = find_root(parent, c);
            if (label_of_root[r] == none) label_of_root[r] = cw.count++;
            cw.label[c] = label_of_root[r];
        }
    }
    cw.first[nv] = cw.count;
    return cw;
}

Status vertex_fan(const ModelTopology& t, std::uint32_t v, std::vector<std::uint32_t>* fan, bool* closed) {
    fan->clear();
    const std::uint32_t b = t.corner_begin[v], e = t.corner_begin[v + 1], n = e - b;
    *closed = false;
    if (n == 0) return Status::success();
    const auto back = [&](std::uint32_t c) { return t.twin[ModelTopology::prev(c)]; };
    const auto fwd = [&](std::uint32_t c) {
        return t.twin[c] == kNoHalfEdge ? kNoHalfEdge : ModelTopology::next(t.twin[c]);
    };
    const std::uint32_t start = t.corners[b];
    std::uint32_t first = start;
    for (std::uint32_t steps = 0; steps <= n; ++steps) {
        const std::uint32_t p = back(first);
        if (p == kNoHalfEdge) break;
        if (p == start) {
            *closed = true;
            break;
        }
        first = p;
    }
    std::uint32_t c = first;
    for (std::uint32_t steps = 0; steps < n && c != kNoHalfEdge; ++steps) {
        fan->push_back(c);
        c = fwd(c);
        if (c == first) break;
    }
    if (fan->size() != n || (*closed) != (c == first))
        return Status::bad_input("the faces around vertex " + std::to_string(v) + " do not form a single fan");
    return Status::success();
}

}  // namespace erd
