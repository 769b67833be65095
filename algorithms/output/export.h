// Meshes for 3-D tools: Wavefront OBJ, ASCII PLY, binary STL and glTF 2.0 binary (.glb) of a Model
// seen as a height field.
//
// Frame: x = X/2 and y = (H-1) - Y/2 in pixels (the image's y axis flipped so the picture is upright
// when seen from +z with y up), z = value * zscale. Faces are written counter-clockwise seen from
// +z, so their normals point up. The default zscale, max(W, H) / (10 * maxval), makes the whole
// value range one tenth of the larger image side high (a real model: its range hi - lo).
//
// World coordinates (issue 47): a model of a georeferenced raster (GeoTIFF) is written in its
// world units instead: x, y the pixel centre's world coordinates (algorithms/imaging/georef.h), the
// default zscale 1 in a projected CRS (heights in the units of x and y) and one tenth of the larger
// extent over the range otherwise (degrees). OBJ and PLY hold them as they are (9 significant
// digits or more); STL and glTF store 32-bit floats, which would lose the centimetres of a UTM
// coordinate, so they hold x - x0, y - y0 from the mesh's centre (x0, y0): STL names the origin in
// its header, glTF puts it in its node's translation (JSON numbers, kept exactly).
//
// glTF: y up (glTF x = x, y = z, z = -y), one mesh of one indexed triangle list (32-bit indices),
// POSITION with its bounds, COLOR_0 (unsigned bytes, normalized) for a colour model, a matte
// material; no normals (viewers shade the faces flat, as the ERD surface is cut along its
// discontinuities anyway).
//
// An ERD model is discontinuous across its constrained edges, so each wedge gets its own vertex
// copy (a vertex with k wedges is written k times, at the same x and y, with the wedge's value) and
// every face uses the copies of its corners' wedges: the discontinuities stay open as cracks.
//
// A colour model (3 channels) is one surface with a colour per vertex copy: z is the BT.601 luma
// 0.299 R + 0.587 G + 0.114 B of the copy's values times zscale; PLY adds uchar red, green, blue
// properties (value * 255 / maxval, rounded, clamped), OBJ writes "v x y z r g b" with r g b in
// [0, 1] (value / maxval, clamped) as MeshLab reads it; STL has no colour and keeps the luma
// surface alone.
//
// Binary STL (as fogleman/hmm writes for heightmaps): an 80-byte header, the facet count, then per
// facet the unit normal and three corners as little-endian floats. With base H > 0 (basic models
// only: an ERD surface is open along its constrained edges) the surface is lifted by H and closed
// into a solid: a vertical wall under every boundary edge down to z = 0 and a bottom that repeats
// the top's triangulation facing down, so every edge is shared by exactly two facets.
#pragma once
#include <string>

#include "algorithms/model/model.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

enum class MeshFormat { obj, ply, stl, glb };

struct ExportOptions {
    MeshFormat format = MeshFormat::obj;
    double zscale = 0;  // <= 0: the default max(W, H) / (10 * maxval)
    double base = 0;    // STL only: > 0 makes a solid of this base height (see above)
    ProgressHook progress;  // "export", the fraction of vertices and faces written (OBJ, PLY)
};

// Counts of what export_mesh writes (for tests and messages).
struct ExportCounts {
    std::size_t vertices = 0;  // copies written: one per vertex (basic) or per wedge (erd)
    std::size_t faces = 0;     // faces of the model's surface
    std::size_t facets = 0;    // STL: facets written (faces, plus walls and bottom with a base)
};

// The default zscale for a model: max(W, H) / (10 * maxval) (see above for real and georeferenced
// models).
double default_zscale(const Model& m);

// Writes the model as OBJ or PLY text, binary STL or glTF 2.0 binary into *out. Fails (Code::input) on an
// inconsistent model (index out of range, a repeated vertex, overlapping faces: build_topology).
Status export_mesh(const Model& m, const ExportOptions& options, std::string* out, ExportCounts* counts = nullptr);

}  // namespace erd
