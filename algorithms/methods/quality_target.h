// The quality stop rules of every method: --psnr P and --max-error E ask for the fewest points
// (up to the N of -d / -n) whose finished model reaches the target. A greedy loop's own stop
// measures the mesh it is building, before the refit and flips of the ERD methods, and ED and
// ERDED have no loop at all; so the count is searched over whole runs of the method instead: the
// quality of the model each makes (reconstructed as `erd generate --psnr-report` does: 4x4
// supersampled for a soft-edged ERD model) at a count, a bracket grown by factors of 4 from N/16,
// then narrowed by interpolation of the quality in log N (bisection when that stalls) until its
// ends are within 2%. The model kept is the bracket's upper end: one that reaches the target.
//
// GenerateOptions::count_search = false (--count-search 0) keeps the first run alone: the method's
// own, its greedy loop's stop on (one run's speed; an ERD model may miss or overshoot the target).
//
// Every method of the registry gets it through run_method (the CLI and the API call that, not
// MethodInfo::run). A real image (issue 47) keeps its own rules: there --max-error is a bound the
// methods meet inside one run, and --psnr the greedy loop's stop.
#pragma once
#include <cstdint>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/result.h"
#include "kernel/status.h"

namespace erd {

// The bracket's ends are within this ratio when the search stops.
constexpr double kQualityCountTolerance = 1.02;

// Whether these options ask run_method for a search: --psnr or --max-error on an integer image.
bool wants_quality_search(const Image& image, const GenerateOptions& options);

// The quality of a finished model against its image, as the search measures it: PSNR (dB) and
// the largest absolute error (over all channels), each only when its target is set (else 0).
Status measure_quality(const Image& image, const Model& model, const GenerateOptions& options, double* db,
                       double* max_error);

// method.run at N, or, when wants_quality_search, at the count the search finds (at most N):
// result->requested is that count and result->stats.quality says how it was found. When even N
// does not reach the target, the result is N's (quality.reached false).
Status run_method(const MethodInfo& method, const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
