// `erd generate --stats FILE`: one JSON object describing a run (what was asked, what was made,
// the parameters chosen, time per stage, peak memory, PSNR). Keys, in this order:
//   method, model ("basic" | "erd"), image {width, height, maxval, channels},
//   points {requested, achieved}, vertices, faces, constrained_vertices, constrained_edges,
//   dropped_constraints, parameters ({beta, r, l, epsilon, simple, edges} or null for ED/GPI),
//   stop (greedy stop rule, or null), stages [{name, seconds}], total_seconds,
//   peak_memory_bytes, memory_estimate_bytes, psnr (only with --psnr-report; null when infinite).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/methods/options.h"

namespace erd::cli {

struct GenerateStats {
    std::string method;
    int width = 0, height = 0;
    std::uint32_t maxval = 0;
    int channels = 1;  // the model's: 1 gray, 3 RGB
    bool erd = false;
    std::size_t requested = 0, achieved = 0;
    std::size_t vertices = 0, faces = 0;
    std::size_t constrained_vertices = 0, constrained_edges = 0;
    std::size_t dropped_constraints = 0;  // constraint pieces refused as crossings (ERD step 1)
    bool has_params = false;  // ERD methods: the step-1 parameters used
    double beta = 0, r = 0, epsilon = 0;
    int l = 0;
    bool simple = false;
    bool hard_edges = false;         // the model's kind of edge ("edges": "hard" | "soft")
    std::size_t other_kind_edges = 0;  // ERD: its edges of the other kind (Model::kind_exceptions)
    std::string stop;                // empty: not a greedy method
    std::vector<StageTime> stages;   // the method's stages, then the CLI's (read, write, psnr)
    double total_seconds = 0;        // wall time of the whole command
    long long peak_memory_bytes = 0; // getrusage ru_maxrss
    long long memory_estimate_bytes = 0;  // what the memory cap compared (the estimate + the process's 1.4 MiB)
    bool has_psnr = false;
    double psnr = 0;
    bool has_quality = false;        // --psnr / --max-error searched the count (quality_target.h)
    QualitySearchStats quality;
};

// Fills the counts from the result's model (constrained edges: the model's list, or where an ERD
// model's corner values differ across an edge; constrained vertices: endpoints of those) and the
// rest from the result's typed statistics: the ERD parameters (beta, r, l, eps, simple), the
// greedy stop rule, the constraint pieces the kernel refused. The caller adds its own stages,
// total time, memory and PSNR.
GenerateStats collect_stats(const std::string& method, const Image& image, const GenerateResult& result);

// The JSON text, one object on one line, newline-terminated.
std::string stats_json(const GenerateStats& s);

// Peak resident set size of this process in bytes (getrusage; Linux reports KiB), 0 if unknown.
long long peak_memory_bytes();

}  // namespace erd::cli
