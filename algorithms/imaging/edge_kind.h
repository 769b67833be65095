// Hard or soft edges: what an image's edges are, measured from its samples, and where a hard
// edge sits (on the cracks between pixels).
//
// Measure. At every pair of 4-neighbours p, q (along x or y) whose difference d = |phi(q) -
// phi(p)| is at least kStrongStep of maxval and is the largest along the line through them
// (strictly larger than the differences one step before and after), the step is
//   hard  when both flanking differences (phi(p) - phi(p-1), phi(q+1) - phi(q)) are at most
//         kFlankRatio * d: the whole step happens between the two pixels;
//   soft  when a flanking difference of the same sign exceeds kFlankRatio * d: the step is
//         spread over more pixels (blurred by a lens, a filter or anti-aliasing);
//   neither (a ridge: a flank of the opposite sign, a line one pixel wide) otherwise.
// The image is hard when hard / (hard + soft) >= kHardFraction (docs/DECISIONS.md "Edge kinds"
// gives the measured fractions).
//
// Clean steps (issue 44: anti-aliased graphics). A strong step is also clean when the ground is
// flat on both sides of it: the transition takes one difference (the step) or two (the step and
// its larger same-sign flank: a coverage ramp one pixel wide, as anti-aliasing draws an edge), and
// the differences just outside it are at most kFlatRatio of the transition. Rendered graphics
// (flat colours, anti-aliased edges) have many; photos few, their ground is never that flat. An
// image is stepped when clean / steps >= kSteppedFraction, steps counting every strong step that
// is the largest along its line (hard, soft or neither), unless nearly all its strong steps are
// hard (hard_fraction >= kPixelArtFraction: aliased drawings, pixel art, whose crack edges need
// nothing else); the ERD methods then try soft detection, hard edges and no edges, and decide each
// edge's kind by fit (algorithms/methods/scaffold.h run_erd_method). A stepped image may be hard
// as well (a rendering whose straight edges fall on pixel boundaries: the flag of thirteen stripes).
//
// Cracks. A hard edge is traced on the half-pixel grid (doubled coordinates): the midpoint
// (2x+1, 2y) between pixels (x, y) and (x+1, y) and (2x, 2y+1) between (x, y) and (x, y+1) are
// set where the step between the two pixels is an edge (hysteresis on d, like Canny's), and a
// pixel corner (2x+1, 2y+1) where at least two of its four cracks are set. The curves run from
// corner to corner through the crack midpoints, so every pixel lies on one side of them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/polylines.h"

namespace erd {

constexpr double kStrongStep = 0.08;   // of maxval
constexpr double kFlankRatio = 0.2;
constexpr double kHardFraction = 0.6;
constexpr double kFlatRatio = 0.05;
constexpr double kSteppedFraction = 0.09;
constexpr double kPixelArtFraction = 0.9;

struct EdgeKindStats {
    std::size_t hard = 0;  // strong steps completed between two pixels
    std::size_t soft = 0;  // strong steps spread over more pixels
    std::size_t steps = 0;  // every strong step that is the largest along its line
    std::size_t clean = 0;  // ... of them with flat ground on both sides (a one- or two-pixel transition)
    double hard_fraction() const { return hard + soft ? double(hard) / double(hard + soft) : 0.0; }
    double clean_fraction() const { return steps ? double(clean) / double(steps) : 0.0; }
    // No strong step at all (a smooth image) counts as soft: nothing to gain from hard edges.
    bool is_hard() const { return hard + soft > 0 && hard_fraction() >= kHardFraction; }
    bool is_stepped() const { return hard_fraction() < kPixelArtFraction && clean_fraction() >= kSteppedFraction; }
};

EdgeKindStats measure_edge_kind(const Image& im);

// The crack edge map of im, (2W-1) x (2H-1) on the half-pixel grid (1 = edge). tau_high is the
// beta-quantile of the differences over the 2WH-W-H cracks, at least kStrongStep * maxval / 2;
// cracks with d >= tau_high seed, cracks with d >= r * tau_high that touch a set crack through a
// shared pixel corner join them.
Grid<std::uint8_t> crack_edges(const Image& im, double beta, double r);

// The same for several (beta, r) on one image (ERD's parameter selection): the histogram of the
// steps is made once. The image must outlive the detector.
class CrackDetector {
public:
    explicit CrackDetector(const Image& im);
    Grid<std::uint8_t> detect(double beta, double r) const;
    // The same into *map, whose memory is reused when it has the size already (the parameter
    // selection's detections: no fresh pages for each).
    void detect(double beta, double r, Grid<std::uint8_t>* map) const;

private:
    const Image& im_;
    std::vector<std::size_t> hist_;  // cracks per step, 0 .. maxval
    std::size_t cracks_ = 0;
};

// Douglas-Peucker for a polyline traced on a crack map that keeps every pixel on its side: a
// piece a..b is replaced by the segment a-b only when no point is further than epsilon (doubled
// units) from it and each crack midpoint's two pixels lie strictly on either side of it, the
// same way round as along the crack. Otherwise it is split at its farthest point.
Polyline simplify_cracks(const Polyline& line, double epsilon);
// simplify_cracks over lines, dropping those with fewer than min_points points before.
PolylineList simplify_crack_polylines(const PolylineList& lines, double epsilon, int min_points);

}  // namespace erd
