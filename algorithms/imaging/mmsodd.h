// MMSODD: maximum magnitude second-order directional derivative (thesis eq. 3.1-3.3).
//
//   d = max(|l1 + l2|, |l1 - l2|),  l1 = (fxx + fyy) / 2,  l2 = sqrt((fxx - fyy)^2 / 4 + fxy^2)
//
// with each second derivative estimated by one separable filter: smoothing composed with the
// derivative taps of filters.h, the binomial of order smoothing_order in both directions:
//   fxx: x taps = [1 -2 1] * b_n, y taps = b_n
//   fyy: x taps = b_n,            y taps = [1 -2 1] * b_n
//   fxy: x taps = [1/2 0 -1/2] * b_n, y taps = [1/2 0 -1/2] * b_n   (first derivative in x, then in y)
// ED uses order 3 (thesis 3.2.1), ERDED and the wedge-value line search order 5 (3.4.1, 3.4.2).
// Borders: zero extension, as the thesis says; the MMSODD is therefore large along the image frame.
#pragma once
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/image.h"

namespace erd {

// MMSODD at every sample of im. smoothing_order must be odd and >= 1 (1 = no smoothing);
// an invalid order is treated as 1.
Grid<double> mmsodd(const Grid<double>& im, int smoothing_order, Border border = Border::zero);

// The same with zero extension, straight from an image's samples: equal to
// mmsodd(to_grid(im), smoothing_order) without the image-sized copy in doubles.
Grid<double> mmsodd(const Image& im, int smoothing_order);

// The MMSODD by its definition: the three separable filter pairs above, any border, three
// image-sized temporaries. mmsodd() serves Border::replicate with it; tests use it as the
// reference for the one-smoothing form of the zero border.
Grid<double> mmsodd_separable(const Grid<double>& im, int smoothing_order, Border border);

// The formula alone, from the three second derivatives at one point.
double mmsodd_value(double fxx, double fyy, double fxy);

}  // namespace erd
