// Sample-point selection by Floyd-Steinberg error diffusion (thesis 3.2.1 ED, 3.4.2 ERDED).
//
// One pass: rows top to bottom in serpentine order (even rows left to right, odd rows right to
// left, counting rows of the scanned image), v = density + carried error; a point is chosen when
// v >= rho and then emits 2*rho (so a pass chooses about sum(density) / (2 rho) points, thesis
// eq. 3.5); the error v - emitted goes 7/16 ahead, 3/16 behind-below, 5/16 below, 1/16 ahead-below
// (mirrored on right-to-left rows). Points outside the image receive no error (it is lost).
//
// Count search: rho is searched until a pass chooses exactly K points. The count follows the
// sum / (2 rho) model of eq. 3.5 but is not monotone in rho: below relative changes of about 1/K it
// jitters by several points either way, so plain bisection stalls on a jump across K. Each sweep
// over the image runs several passes side by side (independent thresholds fill the latency of
// the carried error): the first runs 4 lanes at 0.75 .. 0.99 times the model's rho to locate the
// crossing, later ones 16 lanes on a deterministic golden-ratio sequence within +-3/K
// (relative) of where a fit of the counts near K gives K (or, with none near K yet, of the
// crossing interpolated between the closest counts on either side, twice as widely), until a
// pass gives K exactly or max_passes passes have run. Without an exact count it returns the
// pass whose count was nearest to K (ties: the smaller count) with
// exact = false. The diffused error is carried in float.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

// How the start of the scan is handled (thesis -B flag of erd_ed).
enum class Startup {
    // 0: scan an image of 2H rows, the original mirrored about its first row on top of it
    //    (rows H-1 .. 0, then 0 .. H-1); points chosen in the mirrored half are discarded and only
    //    the original half counts toward K (thesis 3.4.2, Figure 3.6).
    mirror,
    // 1: "forcing" (undefined in the thesis; ours): the error carried into the first row is primed
    //    with deterministic values spread evenly over [-rho, rho), the spread the carried error has
    //    in the steady state of the diffusion. A pixel of row 0 then fires with probability about
    //    density / (2 rho), as it would deep inside the image, instead of only after several rows
    //    have accumulated error. Values: e(x) = rho * (2 * frac((x + 1/2) * g) - 1), g = (sqrt5-1)/2.
    force,
    // 2: nothing (all carried errors start at 0).
    none,
};

struct DiffusionParams {
    Startup startup = Startup::none;
    // Optional (may be null): points with a nonzero entry are never chosen; their density still
    // enters the diffusion. Must have the density's size.
    const Grid<std::uint8_t>* forbidden = nullptr;
    int max_passes = 256;  // thresholds tried at most (4 in the first sweep, 16 in each later one)
    // Threads of the count search's sweeps of 16 lanes: 2 or more (0: the machine's processors)
    // run them as two sweeps of 8 lanes side by side, with the same points (kernel/row_parallel.h).
    int threads = 1;
};

struct DiffusionResult {
    std::vector<LatticePoint> points;  // chosen pixels in doubled coordinates (2x, 2y), row-major order
    bool exact = false;                // points.size() == K
    double rho = 0;                    // threshold of the returned pass
    int passes = 0;                    // thresholds tried by the search (4, then 16 per sweep)
    int sweeps = 0;                    // scans of the image by the search
};

// One diffusion pass with threshold rho (> 0). Returns the number of points chosen (inside the
// original image); if points is non-null they are stored there (doubled coordinates, row-major).
std::size_t diffuse(const Grid<double>& density, double rho, const DiffusionParams& params,
                    std::vector<LatticePoint>* points);

// Chooses exactly count points when the search finds a threshold that gives it (see above).
// count == 0 gives no points, exact. Fails (Code::input) when the density is empty, has negative
// or non-finite entries, or forbidden has the wrong size; Code::density is never returned here:
// the caller applies its exit mode to result->exact.
Status select_points(const Grid<double>& density, std::size_t count, const DiffusionParams& params,
                     DiffusionResult* result);

// The ED density sigma = (d / d_max)^gamma (thesis eq. 3.4), gamma > 0; all zeros when d_max <= 0.
// Takes d by value so that a caller passing a temporary (ED: the MMSODD grid) reuses its storage.
// threads: bands of rows side by side, the same bits for every count (kernel/row_parallel.h).
Grid<double> ed_density(Grid<double> d, double gamma, int threads = 1);

}  // namespace erd
