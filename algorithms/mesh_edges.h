// Edges and wedges of a Model, recovered from its face list alone.
//
// Pictures and exports need two things the Model does not store directly: the list of edges (each
// once, with a "constrained" flag) and, for an ERD model, which face corners around a vertex form
// one wedge. A model made by a method lists its constrained edges; a model read from an .erd file
// does not (the format has no such list), so an interior edge also counts as constrained when the
// two faces beside it give a different value to one of its endpoints: that is exactly where the
// approximating function is discontinuous. Hull edges are never constrained (nothing lies beyond).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "algorithms/model.h"
#include "kernel/status.h"

namespace erd {

constexpr std::uint32_t kNoMeshFace = 0xffffffffu;

// One undirected edge, a < b, with the faces on its two sides (right = kNoMeshFace on the hull).
struct MeshEdge {
    std::uint32_t a = 0, b = 0;
    std::uint32_t left = kNoMeshFace, right = kNoMeshFace;
    bool constrained = false;
};

// Every edge of the model once, sorted by (a, b). Fails (Code::input) when a face has an
// out-of-range or repeated vertex index, or when an edge has more than two faces.
Status mesh_edges(const Model& m, std::vector<MeshEdge>* out);

// Wedge labels: wedge[f][i] is the wedge of corner i of face f; corners of one vertex share a label
// exactly when they are joined by a chain of faces around it crossing no constrained edge. Labels
// are 0..*count-1, numbered by vertex, then by the first face (in face order) of each wedge.
// *first_vertex_wedge (size vertices+1) gives the labels of vertex v as [first[v], first[v+1]);
// a vertex without faces gets no label.
void corner_wedges(const Model& m, const std::vector<MeshEdge>& edges,
                   std::vector<std::array<std::uint32_t, 3>>* wedge, std::vector<std::uint32_t>* first_vertex_wedge,
                   std::uint32_t* count);

// Value of corner i of face f: the corner value for an ERD model, else the vertex value.
inline double face_corner_value(const Model& m, std::size_t f, int i) {
    if (m.kind == ModelKind::erd && f < m.corner_values.size()) return m.corner_values[f][std::size_t(i)];
    return m.values[m.faces[f][std::size_t(i)]];
}

}  // namespace erd
