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

#include "algorithms/imaging/image.h"
#include "kernel/lattice.h"

namespace erd {

enum class ModelKind { basic, erd };

// Which kind of edge an ERD model's discontinuities stand for, and so how it is reconstructed:
//   soft  the thesis's: edges the camera has blurred; the image is the mean of 4x4 sub-samples
//         per pixel (imgsyn_aa). Files without a header block are soft.
//   hard  steps between two pixels (drawings, screenshots, aliased renderings): each pixel is
//         the function at its centre (point evaluation), so a pixel lies wholly on one side.
// Written to an .erd as the header line "edges hard" (algorithms/model/model_io.h). Per edge
// (issue 44): Model::kind_exceptions lists the discontinuity edges of the other kind, which
// decide the pixels near them (algorithms/model/edge_kinds.h).
enum class EdgeKind { soft, hard };

struct Model {
    ModelKind kind = ModelKind::basic;
    int width = 0;   // image size in pixels; the domain is [0, W-1] x [0, H-1]
    int height = 0;
    std::uint32_t maxval = 255;
    EdgeKind edges = EdgeKind::soft;  // erd only; a basic model is always point-evaluated

    int channels = 1;  // 1 (gray) or 3 (RGB): values per vertex and per corner

    // A model of a real-valued image (issue 47): values in the data's units, maxval 0 (unused),
    // lo..hi the range of the image's valid samples (the PSNR peak is hi - lo). Always point
    // evaluated, soft edges or not, so its pixel values are those its method measured.
    bool real = false;
    double lo = 0.0, hi = 0.0;
    // The raster's sample type, nodata value and georeferencing (algorithms/imaging/image.h).
    RasterMeta meta;
    // The faces cover only the image's valid region (an image with nodata: those over it were
    // dropped), so the four corners need not be vertices and reconstruction leaves the pixels no
    // face owns as nodata.
    bool holes = false;

    std::vector<LatticePoint> vertices;
    std::vector<double> values;                        // per vertex and channel, values[v*channels + c]
                                                       // (for erd: its single-wedge value, or the
                                                       // mean of its wedge values)
    std::vector<std::array<std::uint32_t, 3>> faces;   // vertex indices, positive orientation
    std::vector<std::array<double, 3>> corner_values;  // erd only: wedge values at the corners of
                                                       // face f in channel c: [f*channels + c]
    std::vector<std::array<std::uint32_t, 2>> constraints;  // erd only: constrained edges (i < j)
    // erd only: the discontinuity edges (i < j, sorted, no repeats) whose kind is the other one
    // than `edges` (algorithms/model/edge_kinds.h); empty: every edge is of kind `edges`.
    std::vector<std::array<std::uint32_t, 2>> kind_exceptions;

    std::size_t size() const { return vertices.size(); }
};

// True when m is reconstructed by 4x4 supersampling: an ERD model with soft edges of an integer image.
inline bool supersampled(const Model& m) { return m.kind == ModelKind::erd && m.edges == EdgeKind::soft && !m.real; }

// The faces may leave holes: the model of an image with nodata.
inline bool has_holes(const Model& m) { return m.holes; }

}  // namespace erd
