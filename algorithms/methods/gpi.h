// GPI: greedy point insertion on the basic model (thesis 3.2.2; Adams's variant of
// Garland-Heckbert: the face with the largest squared error gives up its worst point).
//
// Starts from the Delaunay triangulation of the four image corners and refines it with the shared
// loop of algorithms/greedy.h; the approximation on a face is the plane through the image samples
// at its three vertices.
#pragma once
#include "algorithms/methods/greedy_models.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// Registry entry "gpi" (algorithms/methods/methods.h contract). Stops at N vertices, or earlier by
// --max-error / --psnr, or when no point has nonzero error (achieved < requested then).
Status generate_gpi(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
