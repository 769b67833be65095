// Rate control for .erdz: the value quantisation step chosen for a target size or quality.
#pragma once
#include <string>

#include "algorithms/codec/erdz.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

// One target: bpp > 0 asks for the finest step whose file has at most bpp bits per pixel;
// psnr > 0 for the coarsest step whose decoded model reconstructs `original` at psnr dB or
// more. Steps are tried on the grid 2^(i/4), 1/4 <= step <= 256, by bisection (the size falls
// and the error grows with the step, up to the noise of single steps).
struct RateTarget {
    double bpp = 0.0;
    double psnr = 0.0;
};

struct RateResult {
    double step = 0.0;
    double bpp = 0.0;
    double psnr = 0.0;   // of the decoded model against `original` (when given, of the model's size)
    bool met = false;    // false: no step on the grid meets the target; the nearest one was taken
    int encodings = 0;   // steps tried
};

// Encodes m (options.method as given, options.step chosen) into *out. `original` is needed for
// a psnr target (it must have m's size and channels); given with a bpp target, it gives the
// chosen file's PSNR too (one more decode and reconstruction).
Status encode_erdz_for(const Model& m, const Image* original, const RateTarget& target, ErdzOptions options,
                       std::string* out, ErdzInfo* info, RateResult* result);

}  // namespace erd
