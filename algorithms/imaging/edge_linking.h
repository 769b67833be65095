// Steps 4 and 5 of edge detection (algorithms/imaging/canny.h) on one detection's strong points:
// hysteresis from the strong maxima, and the junction repair of Ding and Goshtasby (2001).
// Internal to canny_track.cpp; the points come from the streaming pass (canny_pass.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/cell_list.h"
#include "algorithms/imaging/point_rings.h"

namespace erd {

namespace edge_flags {
// One byte per kept point holds all its flags:
// - bits 0-2, one detection's: kCandidate and kSecondary (step 3's, for a point with g >= tau_low;
//   none below it) and kMain (steps 4 and 5);
// - bits 3-4, the pass's: step 3's kCandidate and kSecondary shifted by kPassShift, whatever the
//   thresholds (the pass serves several detections);
// - bits 5-7, the link field of step 5: at a point the search reached, the direction (point_rings.h
//   order) back to the point it was reached from; at a main point, how many main neighbours it
//   has, counted up to 2.
enum : std::uint8_t { kNone = 0, kCandidate = 1, kSecondary = 2, kMain = 4 };
constexpr int kPassShift = 3;
constexpr std::uint8_t kPassFlags = std::uint8_t((kCandidate | kSecondary) << kPassShift);
constexpr int kLinkShift = 5;
constexpr std::uint8_t kLinkField = std::uint8_t(7u << kLinkShift);
}  // namespace edge_flags

// One detection's view of the pass's kept points (a superset of the points with g >= tau_low),
// so steps 4 and 5 touch small arrays instead of grid planes; a kept point below tau_low has no
// detection flags, which makes it absent for both steps. Arrays are indexed by a point's list
// position (PointBits::index); lists of points hold their plane cells.
struct StrongPoints {
    explicit StrongPoints(const PointBits& kept) : points(&kept), mains(kept.stride()) {}
    const PointBits* points;            // the kept points' cells and rings
    const float* mag = nullptr;         // their g
    std::uint8_t* flag = nullptr;       // their flag bytes (edge_flags)
    std::vector<std::uint32_t> seeds;   // cells of the candidates with g >= tau_high, row-major
    CellList mains;                     // cells of the points step 4 marks kMain, in the order marked
    std::vector<std::uint32_t> grown;   // where each component of step 4 starts in `mains`
    std::size_t size() const { return points->size(); }
};

// Step 4: grows from the seeds through 8-connected candidates; returns the number of main points.
// Each growth is one 8-connected component of the main points (a candidate next to it would have
// joined it), its points one run of sp->mains. Frees the seeds.
std::size_t hysteresis(StrongPoints* sp);

// Step 5, Ding-Goshtasby: joins different main components through short secondary paths (at most
// max_link points), and lets each end of a main curve climb the magnitude (strictly increasing,
// >= tl) to a different component (canny.h, step 5). Returns the number of points added. Needs
// hysteresis(sp): its components, and its mains, whose order starts the search.
std::size_t join_components(StrongPoints* sp, int max_link, float tl);

}  // namespace erd
