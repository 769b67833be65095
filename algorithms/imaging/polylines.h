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

// Polylines in one array: noise traces millions of short lines, and a vector each would cost a
// heap block and a header per line. Line k is points[first[k]] .. points[first[k + 1] - 1].
struct PolylineList {
    std::vector<LatticePoint> points;
    std::vector<std::size_t> first{0};

    std::size_t size() const { return first.size() - 1; }
    std::size_t size(std::size_t k) const { return first[k + 1] - first[k]; }
    const LatticePoint* line(std::size_t k) const { return points.data() + first[k]; }
    Polyline operator[](std::size_t k) const { return Polyline(line(k), line(k) + size(k)); }
    void add(const Polyline& l) {
        points.insert(points.end(), l.begin(), l.end());
        first.push_back(points.size());
    }
    void clear() {
        std::vector<LatticePoint>().swap(points);
        std::vector<std::size_t>(1, 0).swap(first);
    }
};

// Traces the set points of a thinned edge map (nonzero = edge) into polylines. Links join
// 8-neighbours, except a diagonal pair that also shares a set 4-neighbour (the corner of a
// staircase or of a T), so one junction is one point, not a cluster of mutual junctions. Points
// with 1 or >= 3 links are nodes: every polyline runs from a node to a node through points with
// exactly 2 links, so polylines meet only at their ends (split at junctions and
// self-intersections). A closed curve without nodes becomes one polyline whose last point repeats
// its first; so does a run that returns to its start node (a loop on a junction). Isolated points
// give one-point polylines. Deterministic: nodes in row-major order, links in a fixed order
// (E, SE, S, SW, W, NW, N, NE), loops after all node runs. Each link is used by one polyline.
PolylineList trace_polylines(const Grid<std::uint8_t>& edges);
// The same for edge points as EdgeDetector::detect gives them, after pts.link_rows().
PolylineList trace_polylines(const SortedPoints& pts);

}  // namespace erd
