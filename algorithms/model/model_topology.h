// Adjacency of a Model's faces (half-edges, twins, vertex fans) and the wedges it implies.
//
// The model files list faces only, so the readers, the writer and reconstruction rebuild the
// adjacency here instead of asking the kernel. Half-edge h = 3f + k runs from faces[f][k] to
// faces[f][(k+1) % 3]; it is also "corner" h of face f, at vertex faces[f][k]. Faces must have
// positive orientation (Model's contract), so twins run in opposite directions.
//
// Wedges without constraint lists. A wedge of v is a maximal run of faces around v not separated
// by a discontinuity. For an ERD model the discontinuities are derived from the corner values: an
// edge is a discontinuity when its two faces' corner values differ at either endpoint (files do
// not list constraints; docs/DECISIONS.md, "Model files"). Faces of one wedge then
// always agree at v, so each wedge has one value.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

constexpr std::uint32_t kNoHalfEdge = 0xffffffffu;

struct ModelTopology {
    std::vector<std::uint32_t> twin;          // per half-edge; kNoHalfEdge on the border of the mesh
    std::vector<std::uint32_t> corner_begin;  // per vertex + 1: corners of vertex v are
    std::vector<std::uint32_t> corners;       // corners[corner_begin[v] .. corner_begin[v+1])

    static std::uint32_t next(std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
    static std::uint32_t prev(std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
};

// Builds the adjacency. Fails (input error, message naming the faces) when a face index is out of
// range, a face repeats a vertex, or two faces contain the same directed edge (overlapping or inconsistently oriented
// faces); a third face on an undirected edge is caught the same way.
Status build_topology(const Model& m, ModelTopology* t);

// Value in channel c of face h/3 at the vertex where half-edge (corner) h starts: values for a
// basic model, corner_values for an ERD model.
inline double corner_value(const Model& m, std::uint32_t h, int c = 0) {
    const std::size_t f = h / 3, k = h % 3, C = std::size_t(m.channels);
    if (m.kind == ModelKind::erd && f * C < m.corner_values.size()) return m.corner_values[f * C + std::size_t(c)][k];
    return m.values[std::size_t(m.faces[f][k]) * C + std::size_t(c)];
}

// True when half-edge h and its twin separate different values in some channel (ERD models
// only; false on the border and for basic models). All channels share the discontinuities.
bool is_discontinuity(const Model& m, const ModelTopology& t, std::uint32_t h);

// The wedges of vertex v: their number and the mean of their values in `channel` (the value of
// the approximating function at v, thesis 3.3 case 2). Basic model: one wedge, its value.
struct VertexWedges {
    int count = 0;
    double mean = 0.0;
};
VertexWedges vertex_wedges(const Model& m, const ModelTopology& t, std::uint32_t v, int channel = 0);

// One undirected edge of the mesh, a < b. Constrained when Model::constraints lists it or it is
// a discontinuity: pictures draw these thick, exports cut the surface open along them.
struct ModelEdge {
    std::uint32_t a = 0, b = 0;
    bool constrained = false;
};

// Every edge once, sorted by (a, b) (a fixed drawing order).
std::vector<ModelEdge> model_edges(const Model& m, const ModelTopology& t);

// Wedge labels of all corners, for exports that give every wedge its own vertex copy: corners of
// one vertex share a label exactly when a chain of faces around it joins them without crossing a
// constrained edge (as model_edges flags them). Labels run 0..count-1, by vertex, then by the
// first face (in face order) of each wedge; vertex v has labels [first[v], first[v+1]).
struct CornerWedges {
    std::vector<std::uint32_t> label;  // per corner (half-edge) h = 3f + k
    std::vector<std::uint32_t> first;  // per vertex + 1
    std::uint32_t count = 0;
};
CornerWedges corner_wedges(const Model& m, const ModelTopology& t);

// The corners of v in rotational order (crossing the edge v->next of each face in turn), starting
// at the first face of an open fan. *closed tells whether the fan closes. Fails when the faces
// around v do not form a single fan (then wedges cannot be told from the order of faces).
Status vertex_fan(const ModelTopology& t, std::uint32_t v, std::vector<std::uint32_t>* fan, bool* closed);

}  // namespace erd
