// Model: a mesh model of an image, as the methods produce it and the files store it.
//
// Both models of the thesis share one type:
//   basic (ED, GPI; .model files): vertices on the integer lattice, one value per vertex,
//       a Delaunay triangulation; the approximating function is continuous.
//   erd (ERDED, ERDGPI; .erd files): vertices on the half-integer lattice, a constrained
//       Delaunay triangulation, and one value per face corner (the wedge value of the wedge
//       of that vertex in which the face lies); discontinuous across constrained edges.
//
// Coordinates are doubled integers in both kinds (X = 2x in [0, 2W-2], Y = 2y in [0, 2H-2]);
// a basic model has even coordinates only. Faces are listed with positive signed area
// (X1-X0)(Y2-Y0) - (X2-X0)(Y1-Y0) > 0, i.e. counter-clockwise with y up.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "kernel/lattice.h"

namespace erd {

enum class ModelKind { basic, erd };

struct Model {
    ModelKind kind = ModelKind::basic;
    int width = 0;   // image size in pixels; the domain is [0, W-1] x [0, H-1]
    int height = 0;
    std::uint32_t maxval = 255;

    std::vector<LatticePoint> vertices;
    std::vector<double> values;                        // per vertex (for erd: its single-wedge value,
                                                       // or the mean of its wedge values)
    std::vector<std::array<std::uint32_t, 3>> faces;   // vertex indices, positive orientation
    std::vector<std::array<double, 3>> corner_values;  // erd only: wedge value at each face corner
    std::vector<std::array<std::uint32_t, 2>> constraints;  // erd only: constrained edges (i < j)

    std::size_t size() const { return vertices.size(); }
};

}  // namespace erd
