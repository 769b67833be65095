// Thinning of binary edge maps to one-pixel-wide 8-connected curves.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/image.h"

namespace erd {

// Zhang-Suen thinning (two sub-iterations per pass until nothing changes), then one sweep that
// deletes staircase corners: a point with two 4-neighbours at a right angle whose removal keeps
// the 8-connectivity of its neighbourhood (Yokoi 8-connectivity number 1). After it, no 2x2 block
// is fully set and a point inside a curve has exactly two 8-neighbours. Nonzero = set; the result
// holds 0/1. Returns the number of set points left. Works on a list of the set points (found by
// skipping zero bytes eight at a time), so the cost follows the edge count more than the area.
std::size_t thin_edges(Grid<std::uint8_t>* map);

// The same thinning in place on a byte plane whose set points (nonzero) all have a zero frame of
// one point around them (rows `stride` bytes apart). live lists every set point in increasing
// index order (row-major, which the corner sweep depends on) and is left holding the survivors,
// still in order; deleted points are zeroed in the plane. Lets edge detection thin in a plane it
// already has instead of a copy.
void thin_plane(std::uint8_t* plane, std::ptrdiff_t stride, std::vector<std::ptrdiff_t>* live);

}  // namespace erd
