// Colour helpers of the methods (issue 17): the luma plane the edge detector and the edge-kind
// measure read, and the MMSODD of a colour image combined over its channels (ED's and ERDED's
// density). A gray image (channels == 1) passes through unchanged: luma_of copies it and
// colour_mmsodd is mmsodd(im, order), so the gray path's arithmetic is the same.
#pragma once
#include "algorithms/imaging/image.h"

namespace erd {

// BT.601 luma of an RGB image, rounded half up: (299 R + 587 G + 114 B + 500) / 1000, the
// weights of the CLI's PNG conversion. A gray image is returned as is.
Image luma_of(const Image& im);

// The gradient of edge detection's step 1 on a colour image (canny.h EdgeDetector; docs/
// DECISIONS.md "Colour methods"): that of the luma plane (the caller passes the luma image), Di
// Zenzo's (the structure tensor's largest eigenvalue and its eigenvector over the three channels'
// gradients), or the largest channel's gradient.
enum class ColourGradient { luma, dizenzo, max };

// How colour_mmsodd combines the channels' MMSODDs (docs/DECISIONS.md "Colour methods").
enum class ColourDensity {
    sum,   // d = d_R + d_G + d_B
    max,   // d = max(d_R, d_G, d_B)
    luma,  // d = MMSODD of the luma plane
};

// The MMSODD (algorithms/imaging/mmsodd.h, zero borders) of every channel of im, combined.
Grid<double> colour_mmsodd(const Image& im, int smoothing_order, ColourDensity how, int threads = 1);

}  // namespace erd
