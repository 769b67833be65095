// Polylines from an edge map (thesis 3.4.1 step 1.2); the whole step 1.1-1.3 chain is in
// algorithms/imaging/edge_polylines.h.
//
// Coordinates are LatticePoints in doubled coordinates, which are exactly the indices of the
// half-pixel grid of canny.h: entry (X, Y) of the edge map is LatticePoint{X, Y}.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/image.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

using Polyline = std::vector<LatticePoint>;

// The capacity a Polyline of n points gets (the power of two at or above n, as push_back from empty
// gives): step 1 makes and frees hundreds of thousands of short polylines per detection, and
// blocks of a few sizes are reused across the parameter loop's detections (exact sizes raised
// peak RSS by 8 MB on a noisy 1024^2 image).
inline std::size_t polyline_capacity(std::size_t n) {
    std::size_t c = 1;
    while (c < n) c *= 2;
    return c;
}

// Traces the set points of a thinned edge map (nonzero = edge) into polylines. Links join
// 8-neighbours, except a diagonal pair that also shares a set 4-neighbour (the corner of a
// staircase or of a T), so one junction is one point, not a cluster of mutual junctions. Points
// with 1 or >= 3 links are nodes: every polyline runs from a node to a node through points with
// exactly 2 links, so polylines meet only at their ends (split at junctions and
// self-intersections). A closed curve without nodes becomes one polyline whose last point repeats
// its first; so does a run that returns to its start node (a loop on a junction). Isolated points
// give one-point polylines. Deterministic: nodes in row-major order, links in a fixed order
// (E, SE, S, SW, W, NW, N, NE), loops after all node runs. Each link is used by one polyline.
std::vector<Polyline> trace_polylines(const Grid<std::uint8_t>& edges);
// The same for edge points as EdgeDetector::detect gives them, after pts.link_rows().
std::vector<Polyline> trace_polylines(const SortedPoints& pts);

}  // namespace erd
