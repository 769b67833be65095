// Steps 4 and 5 of edge detection (algorithms/imaging/canny.h) on one detection's strong points:
// hysteresis from the strong maxima, and the junction repair of Ding and Goshtasby (2001).
// Internal to canny.cpp; the points come from its streaming pass.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/point_rings.h"

namespace erd {

namespace edge_flags {
// Point flags: kCandidate and kSecondary from step 3 (suppress), kMain from steps 4 and 5.
enum : std::uint8_t { kNone = 0, kCandidate = 1, kMain = 2, kSecondary = 4 };
}  // namespace edge_flags

// One detection's view of the pass's kept points (a superset of the points with g >= tau_low),
// so steps 4 and 5 touch small arrays instead of grid planes; a kept point below tau_low has no
// flags, which makes it absent for both steps.
struct StrongPoints {
    const SortedPoints* points = nullptr;  // plane indices and rings of the kept points
    const float* mag = nullptr;            // their g
    std::vector<std::uint8_t> flag;        // kCandidate, kSecondary, kMain; none below tau_low
    std::vector<std::uint32_t> seeds;      // candidates with g >= tau_high, in row-major order
    std::vector<std::uint32_t> mains;      // every point marked kMain, in the order marked
    std::vector<std::uint32_t> label;      // main component (steps 4, 5), 0 = none
    std::size_t size() const { return points->size(); }
    void ring(std::uint32_t i, std::uint32_t nb[8]) const { points->ring(i, nb); }
};

// Step 4: grows from the seeds through 8-connected candidates; returns the number of main points.
// Each growth is one 8-connected component of the main points (a candidate next to it would have
// joined it); with `labels`, sp->label receives its number, 1, 2, ... in the order grown.
std::size_t hysteresis(StrongPoints* sp, bool labels);

// Step 5, Ding-Goshtasby: joins different main components through short secondary paths (at most
// max_link points), and lets each end of a main curve climb the magnitude (strictly increasing,
// >= tl) to a different component (canny.h, step 5). Returns the number of points added. Needs
// hysteresis(sp, true): its labels, and its mains, whose order starts the search.
std::size_t join_components(StrongPoints* sp, int max_link, float tl);

}  // namespace erd
