// Real-valued images (issue 47): float, signed and 32-bit rasters, and rasters with nodata, made
// into an Image whose `reals` plane holds the exact values (algorithms/imaging/image.h).
//
// The methods read such an image in two ways. Values, errors and fits read `reals` (in the data's
// units, no quantisation). The stages that look for structure only (edge detection and the edge
// kind, the MMSODD densities, where the wedge line search looks) read `samples`, a 16-bit proxy of
// the same image: they are scale-free, and reading the proxy keeps their code (and the integer
// images' results) exactly as it was. Nodata pixels are filled with the value of the nearest valid
// pixel (4-neighbour distance, the first found in a breadth-first sweep from the valid pixels), so
// no filter sees a step at a hole, and marked 0 in `valid`: no error, fit or candidate reads them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

// Makes *out a real image of w x h pixels and `channels` (1 or 3) values each, interleaved as
// Image::samples: values[i] is the sample, NaN for nodata (a pixel is nodata when any of its
// channels is NaN). Fails (Code::input) on an infinite sample or when no pixel is valid. meta is
// kept as it is. `values` is taken over (moved into out->reals).
Status make_real_image(int w, int h, int channels, std::vector<double> values, const RasterMeta& meta, Image* out);

// The proxy of a real image: samples[i] = round((reals[i] - lo) * 65535 / (hi - lo)), maxval 65535
// (all 0 when lo == hi). make_real_image calls it; call it again after changing reals.
void make_proxy(Image* im);

// A real image of an integer one (the same values as doubles, no nodata), for comparing a real
// model's reconstruction with an integer original.
Image real_copy(const Image& im);

// The BT.601 luma of a real colour image, 0.299 R + 0.587 G + 0.114 B in doubles, as a real gray
// image (the same nodata, range recomputed, meta kept). A gray image is returned unchanged.
Image real_luma(const Image& im);

// The value of sample i (pixel * channels + channel) in the data's units: reals[i] for a real image,
// samples[i] otherwise. Not for inner loops.
inline double sample_value(const Image& im, std::size_t i) { return im.real() ? im.reals[i] : double(im.samples[i]); }

// A real image's value at lattice point p (doubled coordinates) in channel c: the sample at a pixel;
// at a half-pixel point the mean of the valid pixels among the 2 or 4 nearest (all of them when
// none is valid). The value of the basic model's vertices on the outline of the valid region
// (algorithms/imaging/valid_region.h), which lie between a valid and a nodata pixel.
double lattice_value_between(const Image& im, LatticePoint p, int c);  // p not a pixel
inline double lattice_value(const Image& im, LatticePoint p, int c = 0) {
    if ((p.x | p.y) & 1) return lattice_value_between(im, p, c);
    // A pixel: its sample, as lattice_value_between's mean of one gives it (-0 made +0). The
    // greedy's face planes read three of these a face.
    const std::size_t i = std::size_t(p.y / 2) * std::size_t(im.width) + std::size_t(p.x / 2);
    return 0.0 + im.reals[i * std::size_t(im.channels) + std::size_t(c)];
}

// True when pixel i (y * width + x) holds data.
inline bool pixel_valid(const Image& im, std::size_t i) { return im.valid.empty() || im.valid[i] != 0; }

// The number of valid pixels.
std::size_t valid_pixels(const Image& im);

}  // namespace erd
