// ERDGPI (thesis 3.4.3): the initial ERD mesh of step 1 with its wedge values (step 2), refined by
// greedy point insertion on the ERD model's approximation (algorithms/greedy.h, the loop GPI
// uses too).
//
// The face evaluator is the plane through the face's three wedge values. Errors are measured at
// the pixels a face owns by point evaluation of that plane; a pixel lying exactly on a constrained
// edge is measured against the plane of the face that owns it (not the mean of both sides), which
// keeps the per-face sums additive. A candidate on a constrained edge splits it (kernel) and the
// new vertex's two wedges get values by the line search; other vertices keep theirs.
#pragma once
#include "algorithms/methods/greedy_models.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// Registry entry "erdgpi" (algorithms/methods/methods.h contract). Stops at N vertices, or earlier by
// --max-error / --psnr, or when no pixel has nonzero error.
Status generate_erdgpi(const Image& image, const GenerateOptions& options, GenerateResult* result);

// Registry entry "erdgpr" (erd_removal.h): ERDGPI to K*N vertices (K = --oversample, default
// kErdgprOversample), then greedy point removal to N by the ERD model's error, then ERDGPI's end.
Status generate_erdgpr(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
