// Bilinear interpolation phi_bar of a sampled image (thesis 2.4.2), and the half-pixel resampling
// on which edges are located (thesis 3.4.1, Figure 3.4).
#pragma once
#include "algorithms/imaging/image.h"

namespace erd {

// phi_bar at real pixel coordinates (x right, y down). Points outside Gamma = [0,W-1]x[0,H-1] are
// clamped onto it first, so callers that step slightly outside (wedge line search) get the border
// value. At integer coordinates the result equals the sample exactly. An empty grid gives 0.
double bilinear(const Grid<double>& im, double x, double y);
// The same on the integer samples (converted exactly, so the result is bit for bit that of the
// Grid<double> copy of the image, without making the copy); on a real image, on its real plane.
double bilinear(const Image& im, double x, double y);

// phi_bar at the lattice point (X, Y) in doubled coordinates (X = 2x), computed without rounding
// issues: the mean of 1, 2 or 4 samples.
double bilinear_doubled(const Grid<double>& im, int X, int Y);
double bilinear_doubled(const Image& im, int X, int Y);

// phi_bar sampled on the (2W-1) x (2H-1) half-pixel grid: entry (X, Y) is the lattice point (X, Y)
// in doubled coordinates, i.e. pixel coordinates (X/2, Y/2). Even entries equal the samples; odd
// ones are means of 2 or 4 neighbours. An empty input gives an empty grid.
Grid<double> half_pixel(const Grid<double>& im);

}  // namespace erd
