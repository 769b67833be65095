// Reconstruction: the image a mesh model stands for (the thesis's imgsyn and imgsyn_aa).
//
// The approximating function (thesis 3.3, ../shared/spec/NOTES.md): inside a face, the plane through the face's
// three corner values (basic model: the vertex values; ERD model: the face's wedge values); on a
// discontinuity edge (not at an endpoint) the mean of the planes of its two faces; at a vertex
// the mean of its wedge values (one wedge: its value). Discontinuities are the edges across which
// corner values jump (algorithms/model/model_topology.h), so a model read from a file and the model
// in memory give the same image.
//
// Point evaluation samples that function at every pixel (lattice Lambda); 4x4 supersampling
// averages it over 16 sub-samples per pixel at offsets -0.375 -0.125 0.125 0.375 in x and y,
// sub-samples outside Gamma = [0, W-1] x [0, H-1] moved onto its border (clamped). Each lattice
// point is evaluated on the one face that owns it (kernel/raster.h), planes incrementally along
// spans. Results are rounded to nearest (halves up) and clamped to [0, maxval].
//
// A model of C channels (Model::channels, 1 or 3) gives an image of C channels: every channel is
// the function above of its own values, on the one triangulation and the one set of
// discontinuities the channels share (an edge jumps when any channel jumps). Each face is scanned
// once for all channels; a gray model's arithmetic is the same whatever C-handling is around it.
#pragma once
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

// Checks that m is a triangulation of its image domain [0, 2W-2] x [0, 2H-2] (doubled): sizes
// and indices consistent, finite values, positive faces inside the domain whose areas add up to
// the rectangle, every interior edge shared by exactly two faces and every other edge on the
// border, every pixel owned by exactly one face. Otherwise Code::input with a message starting
// "not a triangulation of the image domain" (or naming the inconsistent field).
Status check_triangulation(const Model& m);

// Renders m into *out (W x H, m.channels, m.maxval): supersample ? 4x4 supersampling : point evaluation.
// Runs the checks of check_triangulation first (all but the pixel count, which they imply), so
// it never fails in any other way on any model.
// progress: "reconstruct" with the fraction of faces (point evaluation) or row bands done, called
// from the calling thread only. threads: faces or bands of rows side by side
// (kernel/row_parallel.h; 0 = the machine's processors), the same image for every count.
Status reconstruct(const Model& m, bool supersample, Image* out, ProgressHook progress = {}, int threads = 1);

// The same with m's adjacency already built (topo = build_topology(m), e.g. from read_model()),
// which saves building it again; a topo whose sizes do not fit m is rebuilt.
Status reconstruct(const Model& m, const ModelTopology& topo, bool supersample, Image* out, ProgressHook progress = {},
                   int threads = 1);

}  // namespace erd
