// GPR and GPRFS-ED (Adams; the greedy point removal of Demaret and Iske's adaptive thinning) on
// the basic model, with the removal loop of removal.h.
//
//   gpr    every pixel is a vertex at the start (the Delaunay triangulation of the whole lattice);
//          vertices are removed by least significance until N remain.
//   gprfs  the start is ED's selection (ed_select.h) of K*N points (K = --oversample, default
//          kGprfsOversample) plus the corners, then removal to N: the cost of GPR on a much
//          smaller mesh. With K*N >= W*H it is GPR.
//   id     incremental/decremental (after Adams, Signal Processing 93 (2013), ID1/ID2; the paper's
//          exact schedule is not public): the mesh grows from the four corners to N by GPI's rule
//          (the pixel of largest error in the face of largest squared error), then C cycles
//          (--id-cycles, the quality-for-time knob) each insert A*N more points by the same rule
//          and remove the A*N least significant (--id-share A).
// Choices the papers leave open are decided in docs/DECISIONS.md "Point removal": errors against
// the rounded approximation (as GPI's), ties by (y, x), lazy significance updates, K.
#pragma once
#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

constexpr double kGprfsOversample = 8.0;

// Registry entries "gpr" and "gprfs" (algorithms/methods/methods.h contract).
Status generate_gpr(const Image& image, const GenerateOptions& options, GenerateResult* result);
Status generate_gprfs(const Image& image, const GenerateOptions& options, GenerateResult* result);
Status generate_id(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
