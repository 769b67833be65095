// ED: the error-diffusion mesh generator of Yang, Wernick and Brankov (thesis 3.2.1; the
// thesis's ywb command) on the basic model.
//
// Density sigma = d / d_max with d the MMSODD of the image after 3rd-order binomial smoothing
// (gamma = 1); Floyd-Steinberg error diffusion in serpentine order selects the sample points,
// the threshold found by search so that, with the four image corners always included, exactly N
// points result when any threshold gives that; the Delaunay triangulation of the points (kernel)
// with each vertex valued by the image sample at it.
#pragma once
#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// Registry entry "ed" (algorithms/methods/methods.h contract).
Status generate_ed(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
