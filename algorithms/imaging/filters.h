// Filters: 1-D taps and separable 2-D convolution, the building blocks of MMSODD and Canny.
//
// Conventions (../shared/spec/NOTES.md "Filters"):
//   * A tap vector h of odd length 2c+1 stores h[n] for n = -c..c and is applied as a convolution,
//     y[i] = sum_n h[n] * x[i - n]. So the first-derivative filter with transfer function
//     (1/2)z - (1/2)z^-1 is stored {1/2, 0, -1/2} and gives y[i] = (x[i+1] - x[i-1]) / 2: positive
//     where the signal increases (x to the right, y down).
//   * The n-th order binomial filter has n taps (n odd): order 3 = [1 2 1]/4, order 5 = [1 4 6 4 1]/16.
//     Order 1 is the identity.
//   * "Derivative composed with smoothing" is one filter, compose_taps(derivative, binomial), applied
//     to the extended signal once. With zero extension this differs near the border from filtering
//     twice with truncation in between; the composed form is the thesis's wording (3.4.1).
//   * Border: zero extension (the thesis, 3.2.1) unless the caller asks for replication of the
//     nearest sample (used by edge detection, docs/DECISIONS.md "Filters and MMSODD").
#pragma once
#include <vector>

#include "algorithms/imaging/image.h"

namespace erd {

enum class Border { zero, replicate };

// Binomial taps of the given odd order >= 1 (normalised row order-1 of Pascal's triangle; they sum
// to 1 exactly for orders up to 53, where the integer coefficients are exact in a double).
// Returns an empty vector for an even or non-positive order.
std::vector<double> binomial_taps(int order);

// {1/2, 0, -1/2}: transfer function (1/2)z - (1/2)z^-1.
std::vector<double> derivative1_taps();

// {1, -2, 1}: transfer function z - 2 + z^-1.
std::vector<double> derivative2_taps();

// Full convolution of two tap vectors (odd lengths give an odd length: |a| + |b| - 1); the filter
// equal to applying a then b to an infinitely extended signal.
std::vector<double> compose_taps(const std::vector<double>& a, const std::vector<double>& b);

// One output row of a column filter: out[x] = sum over k = 0..m-1 (ascending, from +0) of
// t[k] * rows[k][x], x in [0, w). convolve_cols sums the same products in the same order through
// it, so callers that stream rows (MMSODD) get bit-identical results.
void weighted_rows(const double* const* rows, const double* t, int m, double* out, int w);

// 1-D convolution of each row (x direction) / each column (y direction). taps must have odd length.
Grid<double> convolve_rows(const Grid<double>& in, const std::vector<double>& taps, Border border = Border::zero);
Grid<double> convolve_cols(const Grid<double>& in, const std::vector<double>& taps, Border border = Border::zero);

}  // namespace erd
