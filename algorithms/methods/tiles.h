// Tiles of a raster larger than one process (issue 48): the grid, the shared borders' vertices
// decided once from the border profiles, the global budget split by error, and the values on a
// tile's sides made the samples. `erd tiles` (cli/cmd_tiles.cpp) reads the raster and writes the
// files; this holds the decisions (docs/DECISIONS.md "Tiles").
//
// Grid: tiles of T pixels (T + 1 samples) sharing their border lines: the vertical lines are
// x = 0, T, 2T, ..., W - 1 and the horizontal ones y = 0, T, ..., H - 1, so tile (i, j) covers
// columns line(i) .. line(i + 1) inclusive. A line's segment between two tile corners is one
// border, meshed once: both tiles (or the one tile on the raster's outside) take its vertices.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/polylines.h"
#include "algorithms/model/model.h"

namespace erd {

struct TileGrid {
    int width = 0, height = 0, tile = 0;
    int nx = 0, ny = 0;  // tiles across and down
    // The position of vertical line i (0..nx) and horizontal line j (0..ny).
    int column(int i) const { return i >= nx ? width - 1 : i * tile; }
    int row(int j) const { return j >= ny ? height - 1 : j * tile; }
    int count() const { return nx * ny; }
};

// The grid of w x h pixels in tiles of t: nx = ceil((w - 1) / t), at least 1. Every tile is at least
// 2 x 2 samples when w, h >= 2.
TileGrid make_tile_grid(int w, int h, int t);

// The rule that picks a border's vertices from its profile z[0..L] (the samples along it): both
// ends always; then, like the greedy's 1-D form, the sample of largest abs error of the linear
// interpolation between the chosen neighbours, until that error is at most max_error (when >= 0)
// or max_interior points are chosen, or no sample is off. rounded: the error is that of the
// interpolation rounded to the nearest integer (an integer image's greedy scans).
struct ProfileRule {
    double max_error = -1.0;
    std::size_t max_interior = std::numeric_limits<std::size_t>::max();
    bool rounded = false;
};

// The indices of the chosen samples, ascending, 0 and L included (z.size() >= 2). Ties go to the
// smaller index; the result depends on z and the rule only.
std::vector<int> simplify_profile(const std::vector<double>& z, const ProfileRule& rule);

// total split in proportion to weights (largest remainders, ties to the lower index; all equal
// when the weights sum to 0): the parts sum to total.
std::vector<std::int64_t> split_budget(std::int64_t total, const std::vector<double>& weights);

// Where an ERD discontinuity crosses a shared border: between samples k and k + 1 of its profile
// z[0..L] when their difference is at least `strong` and larger than the differences just before
// and after (edge_kind.h's strong step, read along the border), with 1 <= k and k + 2 <= L (not
// at a tile corner), and the step goes on across the border: the parallel profiles kCrossingBand
// samples to either side (`before`, `after`, as long as z) each step by at least strong / 2, the
// same way, between samples m and m + 1 for some |m - k| <= kCrossingShift. The ks, ascending.
// Both tiles of the border end a constrained edge there.
constexpr int kCrossingBand = 2;
constexpr int kCrossingShift = 2 * kCrossingBand;  // edges at 26.6 degrees or more to the border
std::vector<int> profile_crossings(const std::vector<double>& z, const std::vector<double>& before,
                                   const std::vector<double>& after, double strong);

// How far (Chebyshev, doubled units) a tile's detected polyline may end from a planned crossing
// and still be continued to it (docs/DECISIONS.md "Tiles").
constexpr int kCrossingReach = 8;

// A tile's polylines (doubled coordinates, none on a side) joined to the planned crossings of its
// sides (w x h pixels). Every crossing gets a stub, a constrained edge one pixel long straight into
// the tile, listed first (inserted first, no detected piece can cut it off: then both tiles have
// the discontinuity at the crossing); the nearest free polyline end within kCrossingReach (ties to
// the earlier crossing, polyline, end) is continued to the stub's inner end. *joined counts those.
std::vector<Polyline> join_crossings(std::vector<Polyline> lines, const std::vector<LatticePoint>& crossings, int w, int h,
                                     std::size_t* joined);

// A tile's model after its run: every vertex on the rectangle's sides takes the sample at its
// pixel in all its wedges (ERD: the refit and the line search leave them off), so that the two
// tiles of a border give its vertices the same values. A basic model's are the samples already.
// A crossing vertex (between side pixels a and b, a first along the side) takes a's sample in its
// wedge that touches the side towards a, b's in the one towards b (its vertex value their mean),
// so both tiles give the seam the same step.
void pin_side_values(const Image& image, Model* m);

}  // namespace erd
