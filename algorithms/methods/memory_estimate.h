// The peak memory of one run of a method, for the memory cap (api/erd.h memory_estimate,
// `erd generate --max-memory`). Two estimates:
//   - from the size alone, before the image is read: an upper bound, the edge-richest images
//     measured (the registry's factors, methods.cpp);
//   - from the image: the ERD methods' peak is inside step 1's edge linking and grows with the
//     points their widest detection keeps, which the detector's own row sample estimates
//     (canny.h estimated_kept_points, about 3% of a pass); a hard-edged image's crack detector
//     grows with the pixels alone. ED and GPI grow with the pixels and the target.
// docs/DECISIONS.md "Memory" has the measurements and the fit.
#pragma once
#include <cstddef>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/options.h"

namespace erd {

// The fixed part of the bound: the fits' fixed costs beyond the process's own 2 MiB are 0.8-1.6 MB.
constexpr std::size_t kMemoryBoundFixed = std::size_t(2) << 20;

// Heap bytes at the peak of a run on a width x height image (channels as given), an upper bound
// whatever the content: the registry's factors per pixel and per vertex + kMemoryBoundFixed.
// 0 for an empty size.
std::size_t memory_bound(const MethodInfo& method, int width, int height, int channels, const GenerateOptions& options);

// Heap bytes at the peak of a run on this image: within 25% of the measured peak on photos,
// synthetic and hard-edged images and heightmaps (DECISIONS "Memory"). Costs a few percent of
// step 1 for the ERD methods (the edge kind and the row sample), nothing for ED and GPI.
std::size_t memory_estimate(const MethodInfo& method, const Image& image, const GenerateOptions& options);

// What memory_estimate bases an ERD estimate on, for tests and the bench.
struct ErdMemoryBasis {
    bool hard = false;         // the crack detector (no kept points)
    bool stepped = false;      // --edges auto on a stepped image: the soft and hard treatments both run
    double beta = 0, r = 0;    // the widest detection the parameter selection makes
    std::size_t kept = 0;      // points its pass is expected to keep
};
ErdMemoryBasis erd_memory_basis(const Image& gray, const GenerateOptions& options, std::size_t target, bool erded);

}  // namespace erd
