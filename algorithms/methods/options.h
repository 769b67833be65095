// GenerateOptions and GenerateResult: what `erd generate` hands to a mesh-generation method and
// what it gets back. One struct serves the four methods of the thesis; each method reads the
// fields it uses. Defaults are the thesis's (Appendix A.5.1); the CLI only parses flags into it.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/methods/progress.h"

namespace erd {

struct GenerateOptions {
    // Target size. -d (percent) wins over -n, as in the thesis; with neither, density 3%.
    double density = 3.0;        // percent of W*H, counting every vertex
    bool density_given = false;  // -d given
    std::int64_t points = 0;     // -n; used when > 0 and -d not given

    // Extra stop rules of the greedy methods (GPI, ERDGPI); whichever holds first.
    double max_error = -1.0;     // --max-error: largest abs error <= E; negative: off
    double psnr = 0.0;           // --psnr: whole-image PSNR >= P dB; <= 0: off
    std::int64_t triangles = 0;  // --triangles: the mesh has >= T triangles; 0: off
    bool round_values = true;    // greedy: errors against the rounded approximation (DECISIONS.md)

    // ERD methods (erdmodel helper). Negative / -1: automatic selection (thesis 3.4.1).
    double beta = -1.0;          // -b hysteresis proportion
    double ratio = -1.0;         // -r tau_low / tau_high
    int min_length = -1;         // -l polyline minimum length
    double epsilon = -1.0;       // -e Douglas-Peucker tolerance
    int simple = -1;             // -S 0 simple, other nonsimple, -1 automatic
    int wedge_rule = 1;          // -w 1 MMSODD line search, 0 fixed distance
    int wedge_order = 5;         // -s binomial filter order for the wedge-value MMSODD
    int startup = 0;             // -B ERDED error-diffusion startup: 0 mirror, 1 force, 2 none
    int ed_select = 1;           // -f ERDED point selection: 1 error diffusion, 0 random
    std::uint64_t seed = 1;      // random selection (-f 0): fixed seed, deterministic output
    int wedge_fit = 6;           // ERD (ours, beyond the thesis): CGLS iterations of the least-squares
                                 // refit of all wedge values after refinement; 0 = the thesis's values
    double alpha_min = 0.75;     // ERD wedge-value line search range along the bisector, in pixels
    double alpha_max = 1.0;      // (ours; the thesis's is [1, 1.5], DECISIONS.md)
    int edge_zero_radius = 1;    // ERDED: density zeroed within this many pixels (Chebyshev) of an
                                 // edge pixel (ours; the thesis's "edge pixels" is 0)

    ProgressHook progress;       // optional: called with (stage, fraction) during long stages
};

// N for an image of width x height under these options: round(D*W*H/100) when -d was given or
// -n was not, else -n. No clamping: callers check 4 <= N <= W*H.
std::int64_t target_points(const GenerateOptions& o, int width, int height);

// Wall time of one stage of a method, for `erd generate` progress lines and benchmarks.
struct StageTime {
    std::string name;
    double seconds = 0.0;
};

struct GenerateResult {
    Model model;                                          // the mesh (basic or erd)
    std::vector<std::vector<LatticePoint>> polylines;     // ERD step 1 output, for -p (empty for ED/GPI)
    std::size_t requested = 0;                            // N asked for
    std::size_t achieved = 0;                             // vertices in the model
    std::vector<StageTime> stages;                        // in order
    std::vector<std::string> notes;                       // one-line facts for -v style output
                                                          // ("stop: psnr", "beta 0.055", ...)
};

// Seconds elapsed since t0, for StageTime entries.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace erd
