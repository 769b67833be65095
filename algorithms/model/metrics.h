// Image quality: mean squared error and PSNR (the thesis's Cal_PSNR).
//
// The PSNR peak is 2^p - 1 with p = ceil(log2(maxval + 1)) of the ORIGINAL (../shared/spec/NOTES.md): a 12-bit
// image with maxval 4095 gets peak 4095, an 8-bit image 255, one with maxval 200 also 255.
#pragma once
#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd {

// Peak value for PSNR of an image with this maxval: 2^bits - 1.
double psnr_peak(std::uint32_t maxval);

// Mean squared error over all samples. Fails (Code::input) when sizes differ, when the images
// are empty, or when the maxvals differ (comparing 8-bit to 16-bit samples is meaningless).
Status mse(const Image& orig, const Image& approx, double* out);

// PSNR in dB = 10 log10(peak^2 / mse); +infinity when the images are identical. Same failures as mse.
Status psnr(const Image& orig, const Image& approx, double* out);

// Convenience forms for callers that have already checked the images match: NaN on mismatch.
double mse(const Image& orig, const Image& approx);
double psnr(const Image& orig, const Image& approx);

}  // namespace erd
