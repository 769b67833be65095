// Automatic selection of the step-1 parameters beta, r, l and epsilon (thesis 3.4.1).
//
// The thesis fixes r = 0.4, decides first whether the image is "simple" (few edges), picks
// initial values from Tables 3.1/3.2 by sampling density, then loops: while the simplified
// polylines hold more than 0.7 N points, beta := 0.75 beta and l := 2 l; when they hold fewer
// than 0.35 N points, epsilon := 1 and the simplification is redone. Every parameter the user
// set by flag stays fixed; the loop only moves the others.
//
// With req.lower_beta false (ours, --lower-beta 0) the loop doubles l alone, keeping the table's
// beta, so every iteration counts on the one detection (beta moves only when -l fixes l): faster
// where the loop repeats, better on photos at low density, worse on graphics (docs/DECISIONS.md
// "Parameter selection").
//
// The selection is written against an abstract counter so it can be tested on synthetic counts
// and so step 1 can cache the expensive part (the gradient) across iterations.
#pragma once
#include <cstddef>
#include <cstdint>

namespace erd {

enum class ErdMethod { erded, erdgpi };

// What step 1 reports for given parameters: the number of distinct points on the simplified
// polylines that survive the length filter (the vertices that become endpoints of constraints).
class ConstraintPointCounter {
public:
    virtual ~ConstraintPointCounter() = default;
    // Runs edge detection (step 1.1) with these thresholds; later count() calls use its result.
    virtual void detect(double beta, double r) = 0;
    // Steps 1.2-1.3 on the last detection: polylines, Douglas-Peucker with eps, drop short ones.
    virtual std::size_t count(int l, double eps) = 0;
    // Hints a counter may use: the widest detection still to come (make its shared work for
    // that one first, or cut what it holds to it), and that the last detection will be wanted
    // again after the next one.
    virtual void prepare(double /*beta*/, double /*r*/) {}
    virtual void narrow(double /*beta*/, double /*r*/) {}
    virtual void set_aside() {}
};

// Parameters the user fixed by flag; a negative value (or simple = -1) means "choose".
struct ErdParamRequest {
    double beta = -1;   // -b
    double r = -1;      // -r
    int l = -1;         // -l
    double eps = -1;    // -e
    int simple = -1;    // -S: -1 automatic, 0 simple, anything else not simple (thesis flag text)
    bool shortcut = true;  // the simple test's shortcut and the loop's look-ahead (below); false: the
                           // thesis's test and loop as written
    bool lower_beta = true;  // the loop lowers beta as it doubles l (the thesis); false: l alone (below)
    // The simple test's count when an earlier run on the same image made it (>= 0; a count
    // search's): its detection is not made again. Step 1 drops it for hard edges.
    std::int64_t test_points = -1;
    bool look_ahead = true;  // with shortcut: the loop's look-ahead (below); step 1 turns it off for
                             // hard edges
};

// The simple test's beta (thesis 3.4.1: with l 5 and epsilon 1).
constexpr double kSimpleTestBeta = 0.055;

// The chosen values and how they were reached (for stats).
struct ErdParams {
    double beta = 0.055;
    double r = 0.4;
    int l = 5;
    double eps = 1;
    bool simple = false;
    std::size_t simple_test_points = 0;  // constrained points of the simple test (0 when -S given)
    double simple_test_beta = 0;         // the beta they were counted at: 0.055, or the loop's first
                                         // beta when the shortcut decided (0 when -S given)
    bool simple_test_known = false;      // its count came with the request (test_points)
    std::size_t constrained_points = 0;  // constrained points with the final parameters
    int loop_iterations = 0;             // iterations of the selection loop (a detection each
                                         // when beta moves)
};

// Table 3.1 (ERDED) or 3.2 (ERDGPI): beta for a sampling density given in percent.
// Densities at or above 5% take the last row.
double erd_beta_table(ErdMethod method, double density_percent);

// Largest number of edge detections the loop runs before it gives up shrinking beta.
constexpr int kErdParamMaxIterations = 24;

// Runs the selection for a W x H image and target size n. The counter's last detection/count
// on return are those of the chosen parameters.
//
// The shortcut (ours, req.shortcut): the loop of a non-simple image starts at the table's beta (or
// -b), which below 2.5% is at most the simple test's 0.055, and a smaller beta has found fewer
// constrained points on every image measured (docs/DECISIONS.md "Parameter selection"). So that
// detection comes first, counted as the test counts (l 5, epsilon 1); when it already reaches
// the test's threshold the image is not simple and the test's own detection is not made. Else
// the test runs as written and the first detection is set aside for the loop.
//
// The look-ahead (ours, req.shortcut and req.look_ahead): before an iteration that the last
// detection, counted at the iteration's l, cannot show to stop the loop, the next iteration's
// detection may be made first; when it, counted at this iteration's l, is still over the budget
// (a smaller beta finding fewer points), this iteration cannot stop the loop either and its
// detection is skipped. The choices are the loop's, with a detection fewer per skip; one more only
// when a look-ahead's detection is not reached, which a guess of beta's effect keeps rare
// (docs/DECISIONS.md "Parameter selection").
ErdParams select_erd_params(ErdMethod method, int width, int height, std::size_t n,
                            const ErdParamRequest& req, ConstraintPointCounter& counter);

}  // namespace erd
