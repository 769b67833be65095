// The wedge values of an ERD model of a real image fitted towards the smallest LARGEST error over
// the valid pixels (issue 47: --max-error on terrain), on a fixed mesh.
//
// Greedy insertion (hmm's rule, and GPI's) puts a vertex on a pixel and gives it the pixel's
// value, so on a convex or concave stretch every face's plane lies on one side of the data and its
// largest error is twice what a plane shifted half way would have. The ERD model's values are
// free (its wedge values are fitted, beyond the thesis: wedge_fit.h), so the fit here moves them
// to balance the errors: iteratively reweighted least squares for ever higher norms of the errors
// (weights (|e| / e_max)^2, ^4, ^8, ... at least 0.1, in the refit's face systems), the values of
// the round with the smallest largest error kept. The methods then insert points where the
// error is still above the bound (scaffold.h), so the bound holds whatever the fit reached.
#pragma once
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/erd_model.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"

namespace erd {

// Refits model's values on cdt against the real image (valid pixels) for `rounds` rounds; returns
// the largest error over the valid pixels of the values kept (those of the best round, or the
// values it was given when none was better).
// owners: pixel_owners(cdt, image) when the caller has it (else it is made here).
double fit_minimax(const Cdt& cdt, const Image& image, ErdModel* model, int rounds, ProgressHook progress = {},
                   const std::vector<FaceInd>* owners = nullptr);

// The face of cdt that owns each pixel of image (W x H, row by row; kernel/raster.h's rule).
std::vector<FaceInd> pixel_owners(const Cdt& cdt, const Image& image);

// The largest error over the valid pixels of the real image of model on cdt, each pixel evaluated
// on the face that owns it (as reconstruct evaluates a real model's pixels); -1 for an integer image.
// owners: pixel_owners(cdt, image) when the caller has it.
double largest_error(const Cdt& cdt, const Image& image, const ErdModel& model,
                     const std::vector<FaceInd>* owners = nullptr);

}  // namespace erd
