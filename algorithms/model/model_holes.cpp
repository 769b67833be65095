#include "algorithms/model/model_holes.h"

#include <algorithm>
#include <utility>

#include "algorithms/imaging/valid_region.h"
#include "algorithms/model/model_topology.h"

namespace erd {

DroppedFaces drop_faces_over_nodata(const std::vector<std::uint8_t>& valid, Model* m) {
    DroppedFaces out;
    if (valid.empty()) return out;
    const std::size_t C = std::size_t(m->channels), nf = m->faces.size();
    const bool erd = m->kind == ModelKind::erd;
    std::size_t k = 0;
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m->faces[f];
        const LatticePoint a = m->vertices[fc[0]], b = m->vertices[fc[1]], c = m->vertices[fc[2]];
        // The centroid (a face lies wholly on one side of the outline, which is made of its edges).
        const std::int64_t x6 = std::int64_t(a.x) + b.x + c.x, y6 = std::int64_t(a.y) + b.y + c.y;
        if (!inside_valid_region(valid, m->width, m->height, x6, y6)) continue;
        m->faces[k] = fc;
        if (erd)
            for (std::size_t ch = 0; ch < C; ++ch) m->corner_values[k * C + ch] = m->corner_values[f * C + ch];
        ++k;
    }
    out.faces = nf - k;
    m->faces.resize(k);
    if (erd) m->corner_values.resize(k * C);
    // Vertices no kept face uses, and the renumbering of the others.
    std::vector<std::uint32_t> index(m->vertices.size(), 0xffffffffu);
    for (const auto& fc : m->faces)
        for (std::uint32_t v : fc) index[v] = 0;
    std::uint32_t n = 0;
    for (std::size_t v = 0; v < index.size(); ++v) {
        if (index[v] != 0) continue;
        index[v] = n;
        m->vertices[n] = m->vertices[v];
        for (std::size_t ch = 0; ch < C; ++ch) m->values[std::size_t(n) * C + ch] = m->values[v * C + ch];
        ++n;
    }
    out.vertices = m->vertices.size() - n;
    m->vertices.resize(n);
    m->values.resize(std::size_t(n) * C);
    for (auto& fc : m->faces)
        for (std::uint32_t& v : fc) v = index[v];
    // Constraints between two kept faces only (one along the outline has a face on one side).
    std::vector<std::uint64_t> shared;
    {
        std::vector<std::uint64_t> edges;
        edges.reserve(3 * m->faces.size());
        for (const auto& fc : m->faces)
            for (int i = 0; i < 3; ++i) {
                const std::uint64_t p = fc[std::size_t(i)], q = fc[std::size_t((i + 1) % 3)];
                edges.push_back((std::min(p, q) << 32) | std::max(p, q));
            }
        std::sort(edges.begin(), edges.end());
        for (std::size_t i = 0; i + 1 < edges.size(); ++i)
            if (edges[i] == edges[i + 1]) shared.push_back(edges[i]);
    }
    // The same for the edges of the other kind (issue 44), which must stay discontinuities.
    for (auto* edges : {&m->constraints, &m->kind_exceptions}) {
        std::size_t c = 0;
        for (const auto& e : *edges) {
            if (index[e[0]] == 0xffffffffu || index[e[1]] == 0xffffffffu) continue;
            std::uint32_t p = index[e[0]], q = index[e[1]];
            if (p > q) std::swap(p, q);
            if (!std::binary_search(shared.begin(), shared.end(), (std::uint64_t(p) << 32) | q)) continue;
            (*edges)[c++] = {p, q};
        }
        edges->resize(c);
        std::sort(edges->begin(), edges->end());
    }
    if (erd) {
        ModelTopology topo;
        if (build_topology(*m, &topo).ok())
            for (std::uint32_t v = 0; v < n; ++v)
                for (std::size_t ch = 0; ch < C; ++ch) m->values[std::size_t(v) * C + ch] = vertex_wedges(*m, topo, v, int(ch)).mean;
    }
    return out;
}

}  // namespace erd
