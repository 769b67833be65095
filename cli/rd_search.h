// --choose-density (issue 24): the point count traded against the value step. For a size target
// (--bpp B) the density whose .erdz within B bits per pixel reconstructs best; for a quality
// target (--step-psnr P) the density whose .erdz reaching P dB is smallest. Each density tried is
// a whole run of the method and a step search (algorithms/codec/erdz_rate.h).
#pragma once
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/methods.h"
#include "cli/codec_output.h"
#include "kernel/status.h"

namespace erd::cli {

// The densities (percent) tried: 2^(k/2) for k = -8 .. 6, 0.0625% to 8%, with at least 8 points.
constexpr double kChoiceMinDensity = 0.0625, kChoiceMaxDensity = 8.0;

struct DensityTrial {
    double density = 0.0;
    RateResult rate;  // met false: no step meets the target at this density
};

struct DensityChoice {
    double density = 0.0;
    RateResult rate;
    std::vector<DensityTrial> trials;  // in the order tried
};

// Meshes `image` with `method` at densities from the lowest up and keeps the best file for
// codec.target: the scan goes up while the result improves (it stops two densities past the
// best, or where a size target can no longer be met), then tries the two quarter-octave
// neighbours of the best. *result and *bytes are the chosen run's; the target must be a bpp
// or psnr one. Fails when no density meets it (the message says the nearest).
Status choose_density(const MethodInfo& method, const Image& image, GenerateOptions options, const CodecChoice& codec,
                      GenerateResult* result, std::string* bytes, DensityChoice* choice);

}  // namespace erd::cli
