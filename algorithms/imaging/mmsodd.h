// MMSODD: maximum magnitude second-order directional derivative (thesis eq. 3.1-3.3).
//
//   d = max(|l1 + l2|, |l1 - l2|),  l1 = (fxx + fyy) / 2,  l2 = sqrt((fxx - fyy)^2 / 4 + fxy^2)
//
// with the second derivatives estimated in two filtering passes, as the thesis describes them
// (3.2.1: a binomial filter "for noise removal", then derivative filters): first the image is
// smoothed by the binomial of order smoothing_order in x and y, S = b_n b_n f; then
//   fxx = [1 -2 1] in x on S,  fyy = [1 -2 1] in y on S,  fxy = [1/2 0 -1/2] in x, then in y, on S.
// Each pass extends its input by zeros (the thesis's border rule), so S is zero outside the image
// (not the smoothed zero-extended image, which is what one composed filter would see): the frame
// is then the MMSODD's maximum, not the sample next to it (docs/DECISIONS.md "ERD reproduction").
// ED uses order 3 (thesis 3.2.1), ERDED and the wedge-value line search order 5 (3.4.1, 3.4.2).
#pragma once
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/image.h"

namespace erd {

// MMSODD at every sample of im. smoothing_order must be odd and >= 1 (1 = no smoothing);
// an invalid order is treated as 1. threads: bands of rows side by side (kernel/row_parallel.h;
// 0 = the machine's processors), the same bits for every count; the separable form ignores it.
Grid<double> mmsodd(const Grid<double>& im, int smoothing_order, Border border = Border::zero, int threads = 1);

// The same with zero extension, straight from an image's samples: equal to
// mmsodd(to_grid(im), smoothing_order) without the image-sized copy in doubles.
Grid<double> mmsodd(const Image& im, int smoothing_order, int threads = 1);

// The same on channel `channel` of a colour image: mmsodd(channel_plane(im, channel), order)
// without the plane's copy.
Grid<double> mmsodd_channel(const Image& im, int channel, int smoothing_order, int threads = 1);

// How mmsodd_channel_into combines a channel's value v with *out's (of the image's size): out = v,
// out + v, or max(out, v), pixel by pixel. The channels of a colour density are combined into
// one plane so, without a second image-sized plane.
enum class MmsoddInto { store, add, max };
void mmsodd_channel_into(const Image& im, int channel, int smoothing_order, MmsoddInto into, Grid<double>* out,
                         int threads = 1);

// The MMSODD by its definition: the passes above with whole-image filters, any border, four
// image-sized temporaries. mmsodd() serves Border::replicate with it; tests use it as the
// reference for the one-sweep form of the zero border.
Grid<double> mmsodd_separable(const Grid<double>& im, int smoothing_order, Border border);

// The formula alone, from the three second derivatives at one point.
double mmsodd_value(double fxx, double fyy, double fxy);

}  // namespace erd
