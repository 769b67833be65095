// Thinning of binary edge maps to one-pixel-wide 8-connected curves.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/point_rings.h"

namespace erd {

// Zhang-Suen thinning (two sub-iterations per pass until nothing changes), then one sweep that
// deletes staircase corners: a point with two 4-neighbours at a right angle whose removal keeps
// the 8-connectivity of its neighbourhood (Yokoi 8-connectivity number 1). After it, no 2x2 block
// is fully set and a point inside a curve has exactly two 8-neighbours. Nonzero = set; the result
// holds 0/1. Returns the number of set points left. Works on a list of the set points (found by
// skipping zero bytes eight at a time), so the cost follows the edge count more than the area.
std::size_t thin_edges(Grid<std::uint8_t>* map);

// The same thinning on a sparse set of points (point_rings.h: plane indices in row-major order,
// which the corner sweep depends on): alive[i] != 0 marks point i as set; deleted points get 0,
// survivors 1. Edge detection thins its main points this way, without a plane.
void thin_points(const SortedPoints& pts, std::vector<std::uint8_t>* alive);

}  // namespace erd
