// Douglas-Peucker polyline simplification (thesis 2.3.2, 3.4.1 step 1.3).
//
// Units: epsilon is measured in doubled-coordinate units, i.e. half-pixel grid steps, the units the
// polylines are traced in (epsilon = 2 is one pixel). The distance of a point to a piece is its
// Euclidean distance to the segment between the piece's kept end points (to the point itself when
// they coincide, as for a closed loop), and a point is kept when that distance is > epsilon.
// Iterative with an explicit stack: no recursion depth limit on long polylines.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "algorithms/imaging/polylines.h"

namespace erd {

// The kept points of line, in order; the end points are always kept (a closed loop keeps its
// repeated first point). Lines of 0, 1 or 2 points are returned unchanged. epsilon < 0 acts as 0.
Polyline douglas_peucker(const Polyline& line, double epsilon);
// The same with an extra condition: a piece line[first..last] whose points are all within epsilon
// is kept as one segment only when accept(first, last) holds; otherwise it is split at its
// farthest point like any other.
using PieceTest = std::function<bool(std::size_t first, std::size_t last)>;
Polyline douglas_peucker(const Polyline& line, double epsilon, const PieceTest& accept);

// When the minimum length l is counted: on the traced polyline (default; the thesis's flag text
// "any polyline generated with fewer points than minLength is discarded") or after simplification
// (the wording of thesis 3.4.1 step 1.3).
enum class LengthRule { before_simplification, after_simplification };

// Simplifies each line and drops those with fewer than min_points points (counted per rule).
PolylineList simplify_polylines(const PolylineList& lines, double epsilon, int min_points,
                                LengthRule rule = LengthRule::before_simplification);

}  // namespace erd
