// Edge detection on the half-pixel grid: Canny with the modification of Ding and Goshtasby (2001)
// that keeps junction points, then thinning to one pixel wide (thesis 2.4.3, 2.4.4, 3.4.1 step 1.1).
//
// Pipeline, all on the (2W-1) x (2H-1) grid of phi_bar (algorithms/imaging/bilinear.h):
//   1. gradient: gx, gy = first derivative [1/2 0 -1/2] composed with the binomial of order
//      smoothing_order (5 in the thesis) along the derivative's axis, the same binomial across it;
//      g = sqrt(gx^2 + gy^2). Units: grey levels per half pixel.
//   2. tau_high = the beta-quantile of g over all grid points: with M points and k = round(beta*M)
//      (at least 1), tau_high is the k-th largest magnitude, so exactly k points have g >= tau_high
//      when magnitudes do not tie there; tied points all count (the count can exceed k, never fall
//      short). tau_low = r * tau_high.
//   3. non-maxima suppression: g at a point is compared with g linearly interpolated at the two
//      points one grid step away along +-(gx, gy)/max(|gx|,|gy|) (where that line crosses the
//      surrounding 3x3 ring, thesis Figure 2.14), bilinearly between the two ring points it falls
//      between. Kept when g > the value ahead (along +gradient) and g >= the value behind, so a
//      ridge two points wide with equal magnitudes keeps exactly one of them.
//   4. hysteresis: suppressed maxima with g >= tau_high seed; 8-connected maxima with g >= tau_low
//      are added. Result: the main edges.
//   5. modified (default): secondary edge points are points with g >= tau_low that are larger than
//      both neighbours of at least one of the four opposite pairs of the 3x3 ring (not necessarily
//      along the gradient). Short paths of secondary points that join two different main-edge
//      components (at most max_link secondary points long) are added; branches that touch fewer than
//      two main components are dropped (thesis 2.4.4). Where an edge runs into a stronger one (a T),
//      the points just before the junction sit on the stronger edge's flank and are maxima in no
//      direction, so no secondary path exists; for that case (our addition) each end of a main curve
//      also climbs the magnitude (strictly increasing, >= tau_low, at most max_link points) and the
//      climb is kept when it arrives next to a different main component.
//   6. thinning (thinning.h): Zhang-Suen, then removal of staircase corners, so every
//      edge is a one-point-wide 8-connected curve.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/image.h"
#include "algorithms/imaging/point_rings.h"
#include "kernel/status.h"

namespace erd {

struct CannyParams {
    double beta = 0.055;      // fraction of grid points at or above tau_high, in (0, 1]
    double r = 0.4;           // tau_low = r * tau_high, in [0, 1]
    bool modified = true;     // Ding-Goshtasby junction repair; false = plain Canny
    int smoothing_order = 5;  // odd binomial order of the gradient filter
    int max_link = 6;         // longest path (grid points) the modification may add, 0 .. 250
    bool thin = true;         // thinning to one pixel wide
    // Border extension for the gradient filter. Zero extension (the thesis's rule for ED filtering)
    // makes the whole image frame a strong edge that eats a third of the beta quantile on bull, so
    // edge detection replicates the border sample instead (docs/DECISIONS.md "Filters and MMSODD").
    Border border = Border::replicate;
    // The gradient pass (steps 1 and 3) in row bands on this many threads (kernel/row_parallel.h;
    // 0: one per processor). The edges are the same for every count.
    int threads = 1;
};

// What detect_edges measured, for reports and tests.
struct CannyStats {
    double tau_high = 0;
    double tau_low = 0;
    std::size_t above_high = 0;    // grid points with g >= tau_high
    std::size_t main_points = 0;   // after hysteresis
    std::size_t added_points = 0;  // added by the modification
    std::size_t edge_points = 0;   // final, after thinning
};

// Edge map of im on the half-pixel grid: (2W-1) x (2H-1), entry (X, Y) = 1 for an edge at lattice
// point (X, Y) (doubled coordinates), 0 elsewhere. Fails (Code::input) for an empty image or
// parameters out of range. stats may be null.
Status detect_edges(const Grid<double>& im, const CannyParams& params, Grid<std::uint8_t>* edges,
                    CannyStats* stats = nullptr);
Status detect_edges(const Image& im, const CannyParams& params, Grid<std::uint8_t>* edges,
                    CannyStats* stats = nullptr);

// Repeated detection on one image with varying beta and r (ERD's parameter selection): the
// gradient pass of step 1, most of the work, runs once and is kept for later detections while it
// covers them (it keeps the points above a lower bound of the first detection's tau_low, so it
// covers any detection with a tau_low at least as high, e.g. a smaller beta with the same r);
// otherwise it runs again. Results equal detect_edges(image, params, ...). Holds 9 bytes per kept
// point (a few percent of the half-pixel grid more than the strong points) until release() or
// destruction; the image must outlive the detector.
class EdgeDetector {
public:
    // A three-channel image is detected on its colour gradient as `colour` says (dizenzo or max;
    // luma is the caller's: it passes the luma plane).
    explicit EdgeDetector(const Image& im, ColourGradient colour = ColourGradient::dizenzo);
    ~EdgeDetector();
    EdgeDetector(const EdgeDetector&) = delete;
    EdgeDetector& operator=(const EdgeDetector&) = delete;
    Status detect(const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats = nullptr);
    // The same detection as the edge points in row-major order: point (X, Y) of the half-pixel
    // grid is plane index (Y + 1) * stride + X + 1 (a frame of at least one column; not linked).
    // edge_map() turns it into the map; trace_polylines (polylines.h) takes it as is.
    Status detect(const CannyParams& params, SortedPoints* edges, CannyStats* stats = nullptr);
    // Makes the gradient pass for `widest` now, when none is kept, without detecting: later
    // detections it covers (e.g. a smaller beta with the same r) then reuse it, whichever of them
    // comes first.
    Status prepare(const CannyParams& widest);
    // The detections to come are covered by `widest` (a beta at most its, the same r and filter):
    // the kept pass drops what they cannot use (the same results, in less memory), when the next
    // detection runs (none may: the cut is not made for nothing).
    void narrow(const CannyParams& widest);
    std::size_t pass_points() const;  // the points the kept pass holds (0: none kept)
    void release();  // frees the kept pass

    struct Pass;  // defined in canny_pass.h

private:
    void make_pass(const CannyParams& params);
    const Image& im_;
    ColourGradient colour_;
    std::unique_ptr<Pass> pass_;
    bool narrowing_ = false;  // narrow() was called since the last detection
    CannyParams narrow_;
};

// How many points the streaming pass of a detection with these parameters keeps (its strong
// points, hardly more), estimated from the rows it samples for its own first bound: about 3% of
// a pass. The peak memory of step 1 grows with it (api/erd.h memory_estimate). The whole
// half-pixel grid for an image too small to sample; 0 for an empty image or bad parameters.
std::size_t estimated_kept_points(const Image& im, const CannyParams& params);

// The row bands the gradient pass of a width x height image runs in at `threads` threads
// (CannyParams::threads); 1 for one thread or a small image.
std::size_t gradient_pass_bands(int width, int height, int threads);

// The width x height edge map (1 = edge) of points from EdgeDetector::detect.
Grid<std::uint8_t> edge_map(const SortedPoints& points, int width, int height);

// Gradient of f (any grid, no resampling) as described in step 1. Exposed for tests and tools.
void canny_gradient(const Grid<double>& f, int smoothing_order, Border border, Grid<float>* gx, Grid<float>* gy);

// The k-th largest of values[0..n) with k = max(1, round(beta * n)) (step 2). 0 for n == 0.
// Linear time (histogram then selection); values must be finite and >= 0.
double beta_quantile(const float* values, std::size_t n, double beta);

}  // namespace erd
