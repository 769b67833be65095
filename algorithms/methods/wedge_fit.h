// Least-squares refit of all wedge values of an ERD model (ours, beyond the thesis).
//
// The thesis fixes each wedge value from the image near its vertex (3.4.1 step 2). Once the mesh
// is final, the approximating function is linear in the wedge values, so the values that minimise
// the squared error at the pixels can be found directly: conjugate gradients on the normal
// equations, starting from the thesis's values. A face's pixels enter those equations only
// through a 3x3 Gram matrix and a 3-vector, so one pass over the pixels assembles them and the
// iterations cost O(faces). Each pixel is evaluated with the plane of the face that owns it
// (kernel/raster.h ownership), as during ERDGPI refinement.
// A value no pixel depends on keeps its thesis value. Results are clamped to [0, maxval].
#pragma once
#include <cstddef>

#include "algorithms/model/erd_model.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/result.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"

namespace erd {

// Refits every wedge value of model on cdt against image by at most `iterations` CGLS steps.
// progress: "wedge refit", half for the pass over the pixels, half for the iterations.
void fit_wedge_values(const Cdt& cdt, const Image& image, int iterations, ErdModel* model, WedgeFitStats* stats,
                      ProgressHook progress = {});

}  // namespace erd
