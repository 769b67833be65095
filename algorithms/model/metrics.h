// Image quality: mean squared error and PSNR (the thesis's Cal_PSNR).
//
// The PSNR peak is 2^p - 1 with p = ceil(log2(maxval + 1)) of the ORIGINAL (../shared/spec/NOTES.md): a 12-bit
// image with maxval 4095 gets peak 4095, an 8-bit image 255, one with maxval 200 also 255.
// Colour (channels 3): the MSE is averaged over the three channels and all pixels, one number,
// with the same peak (the convention of Kodak results).
#pragma once
#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd {

// Peak value for PSNR of an image with this maxval: 2^bits - 1.
double psnr_peak(std::uint32_t maxval);

// Real images (issue 47): errors in the data's units over the pixels the original has data at;
// the peak is the original's valid range hi - lo (1 when it is one value). When either image is
// real the functions below compare Image::reals (an integer image's samples as they are); sums of
// doubles then, each row in order and the rows in order, the same for every thread count.
double psnr_peak(const Image& orig);

// The largest absolute difference over the original's valid pixels and all channels. Fails as
// mse, and when the approximation has no data where the original has.
Status max_abs_error(const Image& orig, const Image& approx, double* out, int threads = 1);

// Mean squared error over all samples (every channel of every pixel). Fails (Code::input) when
// sizes or channel counts differ, when the images are empty, or when the maxvals differ
// (comparing 8-bit to 16-bit samples is meaningless). threads: bands of rows side by side
// (kernel/row_parallel.h); the sums are exact integers, so every count gives the same result.
Status mse(const Image& orig, const Image& approx, double* out, int threads = 1);

// The MSE of each channel alone: out[c] for c < channels (their mean is mse()). Same failures.
Status channel_mse(const Image& orig, const Image& approx, double out[3], int threads = 1);

// PSNR in dB of a mean squared error against an image of this maxval; +infinity for mse 0.
double psnr_of_mse(double mse, std::uint32_t maxval);

// PSNR in dB = 10 log10(peak^2 / mse); +infinity when the images are identical. Same failures as mse.
Status psnr(const Image& orig, const Image& approx, double* out, int threads = 1);

// Convenience forms for callers that have already checked the images match: NaN on mismatch.
double mse(const Image& orig, const Image& approx);
double psnr(const Image& orig, const Image& approx);

}  // namespace erd
