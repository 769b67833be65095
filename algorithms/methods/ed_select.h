// ED's sample selection (thesis 3.2.1 steps 1-3), shared by ED and GPRFS-ED (gpr.h): the density
// sigma = d / d_max with d the MMSODD after 3rd-order binomial smoothing (gamma = 1), then
// Floyd-Steinberg error diffusion choosing `count` non-corner pixels, the threshold searched so
// that exactly that many result whenever some threshold gives it. The four corners are forbidden
// to the diffusion (their density still diffuses); the caller adds them.
#pragma once
#include <cstddef>

#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// Step 1: the density (colour: the channels' MMSODDs combined as options.colour.density says).
Grid<double> ed_sigma(const Image& image, const GenerateOptions& options);

// The pixels the diffusion must not choose: the four corners (1), the rest 0.
Grid<std::uint8_t> ed_corners(int width, int height);

// Steps 2-3: `count` points into *chosen, none where `forbidden` is nonzero; *adjusted = the
// points the threshold adjustment moved (0 when the search hit count).
Status ed_choose(const Grid<double>& sigma, std::size_t count, const GenerateOptions& options,
                 const Grid<std::uint8_t>& forbidden, DiffusionResult* chosen, std::size_t* adjusted);

}  // namespace erd
