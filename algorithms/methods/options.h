// GenerateOptions: what `erd generate` hands to a mesh-generation method (algorithms/methods/
// result.h has what it gets back). One struct serves the four methods of the thesis; each method
// reads the fields it uses. Defaults are the thesis's (Appendix A.5.1); the CLI only parses flags into it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "kernel/progress.h"
#include "algorithms/methods/result.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

// How the methods treat the channels of a colour image (issue 17): one triangulation and one set
// of constrained edges shared by the channels, a value per channel at every vertex and wedge.
// The defaults are the measured choices (docs/DECISIONS.md "Colour methods"); the other values
// are kept for that measurement (tools/eval_colour.sh). Gray images ignore all of it.
struct ColourChoices {
    // Greedy candidate (GPI, ERDGPI): the pixel with the largest single channel error (true) or
    // the largest sum of squared channel errors (false). Faces are keyed on the sum either way.
    bool max_channel_error = true;
    ColourDensity density = ColourDensity::sum;  // ED's and ERDED's MMSODD over the channels
    // Wedge values: each channel's own line search on its own MMSODD (false), or one position
    // per wedge from the MMSODD combined as `density` says, read in every channel (true).
    bool shared_wedge_position = false;
    // The cheap alternative, for comparison only: ERDGPI's greedy loop on the luma plane and its
    // gray model; the colour values are then assigned and refit on the final mesh.
    bool greedy_on_luma = false;
    // The ERD methods' edge detection (step 1): on the luma's gradient, Di Zenzo's colour gradient
    // or the largest channel's (colour.h ColourGradient). The edge kind and hard (crack) edges
    // read the luma whatever this says.
    ColourGradient edges = ColourGradient::luma;
    // The ending's vertex moves (GenerateOptions::moves) on the channels too; off: flips only
    // (ERDGPI's, ERDED's colour ending). ERDGPR's own ending turns it on.
    bool moves = false;
};

// --edges: what the ERD methods take the image's edges to be (algorithms/imaging/edge_kind.h).
enum class EdgeChoice { automatic, soft, hard };

struct GenerateOptions {
    // Target size. -d (percent) wins over -n, as in the thesis; with neither, density 3%.
    double density = 3.0;        // percent of W*H, counting every vertex
    bool density_given = false;  // -d given
    std::int64_t points = 0;     // -n; used when > 0 and -d not given

    // Extra stop rules of the greedy methods (GPI, ERDGPI); whichever holds first.
    double max_error = -1.0;     // --max-error: largest abs error <= E; negative: off
    // Real images with --max-error (issue 47, ERD methods): the greedy stops at max_slack * E, the
    // values are fitted towards the smallest largest error (minimax_fit.h, this many rounds), and
    // insertion goes on to E. 0 rounds: the greedy goes to E and no such fit.
    double max_slack = 1.6;
    int minimax_rounds = 2;
    // ... and step 1 keeps the detected polylines whose step across is at least this many E
    // (erd_mesh.h InitialMeshOptions::min_step).
    double min_step_factor = 4.0;
    double psnr = 0.0;           // --psnr: whole-image PSNR >= P dB; <= 0: off
    // --psnr / --max-error on an integer image (algorithms/methods/quality_target.h): search the
    // fewest points whose model reaches the target (true), or keep the method's own run (false:
    // one run, its greedy loop's stop; --count-search 0).
    bool count_search = true;
    std::int64_t triangles = 0;  // --triangles: the mesh has >= T triangles; 0: off
    bool round_values = true;    // greedy: errors against the rounded approximation (DECISIONS.md)

    // ERD methods (erdmodel helper). Negative / -1: automatic selection (thesis 3.4.1).
    double beta = -1.0;          // -b hysteresis proportion
    double ratio = -1.0;         // -r tau_low / tau_high
    int min_length = -1;         // -l polyline minimum length
    double epsilon = -1.0;       // -e Douglas-Peucker tolerance
    int simple = -1;             // -S 0 simple, other nonsimple, -1 automatic
    bool simple_shortcut = true; // (ours) the simple test decided by the loop's first detection when
                                 // its count already reaches the test's threshold (erd_params.h);
                                 // --thesis: always the test's own detection
    bool lower_beta = true;      // the parameter loop lowers beta as it doubles l (the thesis's);
                                 // false: l alone, on one detection (--lower-beta 0, erd_params.h)
    std::int64_t simple_test_points = -1;  // the simple test's count, known from an earlier run on
                                           // this image (the count search sets it; erd_params.h)
    int wedge_rule = 1;          // -w 1 MMSODD line search, 0 fixed distance
    int wedge_order = 5;         // -s binomial filter order for the wedge-value MMSODD
    int startup = 0;             // -B ERDED error-diffusion startup: 0 mirror, 1 force, 2 none
    int ed_select = 1;           // -f ERDED point selection: 1 error diffusion, 0 random
    std::uint64_t seed = 1;      // random selection (-f 0): fixed seed, deterministic output
    int wedge_fit = 6;           // ERD (ours, beyond the thesis): CGLS iterations of the least-squares
                                 // refit of all wedge values after refinement; 0 = the thesis's values
    double wedge_prior = 0.01;    // ERD refit: weight of each line-search value, in pixel observations
    double wedge_bounds = 0.5;  // ERD refit: clamp each value into its pixels' sample range
                                 // widened by this fraction of it; < 0: off
                                 // (algorithms/methods/wedge_fit.h WedgeFitOptions)
    int refit_stages = 0;        // ERDGPI (ours): refit the wedge values this many times during
                                 // refinement, so later insertions see the refitted errors
    int moves = 2;               // ERD (ours): rounds (of the flips') with vertex moves + refit
    int move_step = 2;           // their first round's step in doubled lattice units (halved each round after)
    double move_min_gain = 0.05; // moves predicted to gain less than this share of the error are not tried
    double flip_min_share = 0.2;  // quadrilaterals below this share of the mean error are not tried
    int flips = 2;               // ERD (ours): rounds of data-dependent flips + refit after the refit
    bool ending_given = false;   // flips, moves, move_step or move_min_gain set by the caller: ERDGPR
                                 // keeps them (else its own ending, erd_removal.h kErdgprEnding)
    bool optimize = false;       // ED, GPI (--optimize, ours): least-squares vertex values
    // Point removal (issue 45; algorithms/methods/removal.h).
    double oversample = 0.0;     // --oversample K: GPRFS's ED start and ERDGPR's ERDGPI start hold
                                 // K*N points (0: the method's default, docs/DECISIONS.md "Point removal")
    int removal_refit = 1;       // ERDGPR: refit the wedge values before each removal stage (0: off)
    int removal_cycles = 0;      // ERDGPR: insertion to K*N and removal to N again this many times
    int removal_stages = 1;      // ERDGPR: removal stages (each ends with a compact mesh)
    bool removal_lazy = false;   // --lazy: recompute stale significances when they reach the top
                                 // instead of at once (cheaper, worse: docs/DECISIONS.md "Point removal")
    int id_cycles = 4;           // ID: insertion/removal cycles after the growth to N (--id-cycles)
    double id_share = 1.0;       // ID: each cycle inserts and removes this share of N (--id-share)
    int bpr = 0;                 // --bpr R: rounds of bad-point replacement after the method (bpr.h)
    double alpha_min = 0.75;     // ERD wedge-value line search range along the bisector, in pixels
    double alpha_max = 1.0;      // (ours; the thesis's is [1, 1.5], DECISIONS.md)
    EdgeChoice edges = EdgeChoice::automatic;  // ERD: auto measures the image; --thesis: soft
    int edge_zero_radius = 1;    // ERDED: density zeroed within this many pixels (Chebyshev) of an
                                 // edge pixel (ours; the thesis's "edge pixels" is 0)
    bool supersampled_errors = false;  // ERDGPI: refinement errors against the 4x4-supersampled
                                 // approximation (the thesis's, --thesis); false: point evaluation
    // ERD: user constraints (breaklines, --constraints), polylines in doubled coordinates (the -p
    // format), kept as constrained edges beside the detected ones, or alone with detect = false
    // (--no-detect). Policy (docs/DECISIONS.md "User constraints"): points outside the image, or
    // two user segments crossing, are refused; duplicate and overlapping segments merge; a detected
    // piece crossing a user segment is dropped.
    std::vector<std::vector<LatticePoint>> constraints;
    bool detect = true;

    // A tile of a larger raster (issue 48, algorithms/methods/tiles.h): its rectangle's sides are
    // shared with its neighbours, so their vertices are decided before the tile runs. With
    // lock_border, GPI and ERDGPI insert border_points (on the sides, doubled coordinates) after
    // the corners and add no other point on a side (the greedy bans the side pixels; ERD step 1
    // cuts detected polylines where they reach a side). Off: nothing changes.
    bool lock_border = false;
    std::vector<LatticePoint> border_points;
    // ERDGPI on a tile: where a discontinuity crosses a side (the plan's, between two side pixels:
    // one coordinate odd). Each ends a constrained edge: the detected polyline that ends nearest
    // it, within kCrossingReach, continued to it, else a stub one pixel long into the tile.
    std::vector<LatticePoint> border_crossings;

    ColourChoices colour;        // colour images only (channels == 3)

    ProgressHook progress;       // optional: called with (stage, fraction) during long stages
    // Threads of the image stages (MMSODD, density, edge detection's gradient, reconstruction,
    // PSNR: kernel/row_parallel.h); 0 = the machine's processors. Outputs are the same for every
    // count; the CLI's -j sets it for one file.
    int threads = 1;
};

// N for an image of width x height under these options: round(D*W*H/100) when -d was given or
// -n was not, else -n. No clamping: check_target checks 4 <= N <= W*H.
std::int64_t target_points(const GenerateOptions& o, int width, int height);

// Checks the image and N: W, H >= 2 (else "too small", whatever N), then 4 <= N <= W*H (the four
// corners are always vertices).
Status check_target(std::int64_t n, int width, int height);

// What to do when a method cannot hit the requested vertex count exactly (the thesis's -x).
enum class ExactMode {
    fail = 0,    // Code::density ("target sampling density not achieved exactly ..."); the model
                 // is still filled in
    warn = 1,    // ok, with the same sentence as a warning
    ignore = 2,  // ok, silently
};

// The exact-count policy: ok when achieved == requested or mode is ignore; Code::density with
// the sentence under fail; under warn ok with the sentence in *warning (cleared otherwise).
Status check_exact_count(std::size_t requested, std::size_t achieved, ExactMode mode, std::string* warning);

// The thesis's method exactly, as erd_ed and erd_gpi run it (--thesis): the options beyond the
// thesis (wedge refit, the line-search range, the ERDED edge radius, hard edges) set to the
// thesis's values (soft edges).
// Other fields stay as they are in *o.
void set_thesis_preset(GenerateOptions* o);
// GenerateOptions() with the thesis preset.
GenerateOptions thesis_options();

}  // namespace erd
