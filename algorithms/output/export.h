// Meshes for 3-D tools: Wavefront OBJ and ASCII PLY text of a Model seen as a height field.
//
// Frame: x = X/2 and y = (H-1) - Y/2 in pixels (the image's y axis flipped so the picture is upright
// when seen from +z with y up), z = value * zscale. Faces are written counter-clockwise seen from
// +z, so their normals point up. The default zscale, max(W, H) / (10 * maxval), makes the whole
// value range one tenth of the larger image side high.
//
// An ERD model is discontinuous across its constrained edges, so each wedge gets its own vertex
// copy (a vertex with k wedges is written k times, at the same x and y, with the wedge's value) and
// every face uses the copies of its corners' wedges: the discontinuities stay open as cracks.
#pragma once
#include <string>

#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

enum class MeshFormat { obj, ply };

struct ExportOptions {
    MeshFormat format = MeshFormat::obj;
    double zscale = 0;  // <= 0: the default max(W, H) / (10 * maxval)
};

// Counts of what export_mesh writes (for tests and messages).
struct ExportCounts {
    std::size_t vertices = 0;  // copies written: one per vertex (basic) or per wedge (erd)
    std::size_t faces = 0;
};

// The default zscale for a model: max(W, H) / (10 * maxval).
double default_zscale(const Model& m);

// Writes the model as OBJ or PLY text into *out. Fails (Code::input) on an inconsistent model
// (index out of range, a repeated vertex, overlapping faces: build_topology).
Status export_mesh(const Model& m, const ExportOptions& options, std::string* out, ExportCounts* counts = nullptr);

}  // namespace erd
