// The valid region of an image with nodata (issue 47), and its outline as constraints.
//
// The region R is the marching-squares region of the valid mask at level 1/2 on the pixel centres,
// valid diagonals joined: in each cell of four pixel centres, a valid corner alone keeps the
// triangle within half a pixel (L1) of it, a nodata corner alone is cut off by the triangle within
// half a pixel of it, two valid corners on a side keep the half cell on their side, two on a
// diagonal keep the cell less the two nodata corners' triangles. Its outline runs through the
// midpoints between a valid and a nodata pixel (odd doubled coordinates, never a pixel centre), so
// every valid pixel lies strictly inside R and every nodata pixel strictly outside. Outside the
// image counts as valid: the outline ends on the image's border, which closes R.
//
// The methods insert the outline as constrained edges before anything else, so that no face
// crosses it: each face then lies wholly inside or wholly outside R, and inside_valid_region of
// a point inside the face says which. Faces outside R are dropped from the model; every valid
// pixel keeps a face that owns it, and no nodata pixel has one.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/polylines.h"

namespace erd {

// The outline of R for the valid mask of a w x h image (valid[y*w + x] != 0: data), as polylines in
// doubled coordinates: open ones from border to border, closed ones repeating their first point;
// collinear points merged. Empty when every pixel is valid.
std::vector<Polyline> valid_outline(const std::vector<std::uint8_t>& valid, int w, int h);

// True when the point (x6 / 6, y6 / 6) in pixels (six times the pixel coordinate: a face's centroid
// is the sum of its three corners' doubled coordinates) lies in R; a point exactly on the outline
// counts as inside. The point must lie in the image's domain [0, w-1] x [0, h-1].
bool inside_valid_region(const std::vector<std::uint8_t>& valid, int w, int h, std::int64_t x6, std::int64_t y6);

// Pixels within `radius` (Chebyshev) of a nodata pixel: 1. The ERD methods keep detected edges
// away from the holes with it.
std::vector<std::uint8_t> near_nodata(const std::vector<std::uint8_t>& valid, int w, int h, int radius);

// The polylines cut where a point lies near nodata (near_nodata of its nearest pixel): the runs of
// at least two points between such points are kept, each as its own polyline.
std::vector<Polyline> clip_polylines(const std::vector<Polyline>& lines, const std::vector<std::uint8_t>& near, int w);

}  // namespace erd
