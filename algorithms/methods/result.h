// GenerateResult: what a mesh-generation method gives back. Besides the model it carries, as
// typed fields, what each stage measured (the ERD parameters chosen, the greedy loop's
// statistics, the wedge refit, the error diffusion); result_lines() turns them into the lines
// `erd generate` prints, and --stats JSON and the library API read the same fields.
#pragma once
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "algorithms/methods/erd_params.h"
#include "algorithms/model/model.h"

namespace erd {

// Why greedy refinement stopped (the first rule that held).
enum class GreedyStop {
    target,     // cdt.vertex_count() reached GreedyOptions::target_vertices
    max_error,  // the largest absolute error over candidate points is <= max_error
    psnr,       // the whole-image PSNR (point evaluation) is >= psnr
    triangles,  // the triangulation has >= max_triangles triangles
    exhausted,  // no face has an admissible point with nonzero error (e.g. planar image)
};

const char* to_string(GreedyStop s);

// The greedy loop of GPI and ERDGPI (algorithms/methods/greedy.h).
struct GreedyStats {
    GreedyStop stop = GreedyStop::target;
    std::size_t insertions = 0;       // points inserted by the loop
    std::size_t banned = 0;           // candidates refused by GreedyModel::admissible
    double total_squared_error = 0.0; // over all pixels, point evaluation, at the end
    double max_error = 0.0;           // largest abs error over candidate points, at the end
    double psnr = 0.0;                // from total_squared_error and the image's peak (inf if 0)
    std::size_t two_thread_steps = 0; // re-scan steps measured on two threads (GreedyOptions::threads)
};

// The least-squares refit of the wedge values (algorithms/methods/wedge_fit.h).
struct WedgeFitStats {
    int iterations = 0;
    double sse_before = 0;  // squared error over all pixels, point evaluation
    double sse_after = 0;
};

// The error diffusion of ED and ERDED.
struct DiffusionStats {
    double rho = 0;             // threshold of the pass used
    int passes = 0;             // diffusion passes run (threshold search and exact-count retries)
    std::size_t adjusted = 0;   // points added or removed afterwards to reach N exactly
};

// Step 1 of the ERD framework and the wedge values of step 2 (ERDED, ERDGPI).
struct ErdStepStats {
    ErdParams params;                   // beta, r, l, eps, simple as used, and the loop's count
    std::size_t polylines = 0;          // simplified polylines in the initial mesh
    std::size_t initial_vertices = 0;   // N0, corners included
    std::size_t dropped_crossing = 0;   // constraint pieces the kernel refused (crossings)
    std::size_t joined_crossings = 0;   // a tile: planned side crossings a detected polyline reached
    std::size_t dropped_polylines = 0;  // polylines left out so the mesh stays within N
    std::size_t multi_wedges = 0;       // wedge values found by the line search
    std::size_t alpha_first = 0;        // ... whose maximum was at the near end of the range
    std::size_t alpha_last = 0;         // ... at the far end
    bool hard_edges = false;            // the model's edges are hard (Model::edges)
    bool edges_measured = false;        // --edges auto decided it from these counts:
    std::size_t hard_steps = 0, soft_steps = 0;  // strong steps (algorithms/imaging/edge_kind.h)
    // ERDED and ERDGPI with hard edges runs both treatments of over-budget crack curves (erd_mesh.h
    // hard_fallback) and keeps the better: their point-reconstruction PSNRs (0: not run; equal
    // when no count of step 1 fell back, so the second run was not needed). During a run,
    // plain_psnr holds the run's own PSNR when the flips' guard measured it (else 0).
    double plain_psnr = 0, exact_psnr = 0;
    bool plain_fallback = false;  // step 1's selection took the plain curves somewhere (InitialMesh)
    // Stepped or hard images under --edges auto (edge_kind.h, issue 44): the clean steps measured,
    // and the PSNRs of the three treatments tried (their own reconstructions, each edge's kind
    // chosen by fit): soft detection, hard (crack) edges, no detected edges; the best is kept
    // (scaffold.h run_erd_method).
    std::size_t clean_steps = 0, all_steps = 0;
    bool stepped = false;               // measured stepped (edge_kind.h EdgeKindStats::is_stepped)
    bool tried = false;                 // the three treatments were tried
    double tried_psnr[3] = {0, 0, 0};
    int tried_choice = -1;              // 0, 1, 2: which of them was kept
    std::size_t kind_exceptions = 0;    // edges of the other kind than the model's (Model::kind_exceptions)
};

// Point removal (algorithms/methods/removal.h) and bad-point replacement (bpr.h).
struct RemovalRunStats {
    std::size_t start = 0;        // vertices when removal began
    std::size_t removed = 0;      // vertices removed
    std::size_t evaluations = 0;  // significances computed
    int bpr_rounds = 0;           // bad-point replacement rounds run
    std::size_t bpr_moves = 0;    // points moved (kept exchanges)
    std::size_t bpr_tried = 0;    // exchanges tried
};

// A real image (issue 47): its valid region and the max-error guarantee.
struct RasterStats {
    std::size_t outline_points = 0;  // vertices of the valid region's outline (nodata images)
    std::size_t dropped_faces = 0;   // faces over nodata dropped from the model
    std::size_t dropped_vertices = 0;  // vertices only those faces had (corners in nodata)
    std::size_t fixup_insertions = 0;  // --max-error: points the last greedy pass inserted
    double max_error = -1.0;           // --max-error: the model's largest error over the valid
                                       // pixels, measured on its reconstruction (< 0: not measured)
};

// --psnr / --max-error on an integer image: the search for the fewest points whose model reaches
// the target (algorithms/methods/quality_target.h).
struct QualitySearchStats {
    int runs = 0;                // whole runs of the method made
    std::size_t points = 0;      // the count kept (the bracket's upper end)
    std::size_t below = 0;       // the largest count measured short of the target (0: none)
    bool reached = false;        // the kept model reaches the target (false: N itself falls short)
    bool exact = false;          // the method's own stop found the count (GPI's greedy loop): one run
    double psnr = 0;             // the kept model's quality, as measured (each when its target is set)
    double max_error = 0;
};

// Wall time of one stage of a method, for `erd generate` progress lines and benchmarks.
struct StageTime {
    std::string name;
    double seconds = 0.0;
};

// What the stages of a run measured; each has_ flag says whether the method ran that stage.
struct RunStats {
    bool has_erd = false;  // ERDED, ERDGPI
    ErdStepStats erd;
    bool has_diffusion = false;  // ED, ERDED with error-diffusion selection
    DiffusionStats diffusion;
    bool has_greedy = false;  // GPI, ERDGPI
    GreedyStats greedy;
    bool has_wedge_fit = false;  // ERD with wedge_fit > 0
    WedgeFitStats wedge_fit;
    bool has_removal = false;  // GPR, GPRFS, ERDGPR, --bpr
    RemovalRunStats removal;
    bool has_raster = false;  // a real image
    RasterStats raster;
    bool has_quality = false;  // --psnr / --max-error searched the count
    QualitySearchStats quality;
};

struct GenerateResult {
    Model model;                                          // the mesh (basic or erd)
    std::vector<std::vector<LatticePoint>> polylines;     // ERD step 1 output, for -p (empty for ED/GPI)
    std::size_t requested = 0;                            // N asked for
    std::size_t achieved = 0;                             // vertices in the model (with nodata: in the
                                                          // mesh before the faces over it were dropped)
    std::vector<StageTime> stages;                        // in order
    RunStats stats;
};

// The measured facts as one-line texts ("beta: 0.055", "stop: target", ...), in a fixed order:
// wedge refit, ERD step 1 and wedge values, error diffusion, greedy loop.
std::vector<std::string> result_lines(const RunStats& stats);

// Seconds elapsed since t0, for StageTime entries.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace erd
