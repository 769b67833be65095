// Step 1.1-1.3 of the ERD framework (thesis 3.4.1) in one place: half-pixel edges (modified
// Canny, algorithms/imaging/canny.h), polylines (polylines.h), Douglas-Peucker simplification
// with the short polylines dropped (douglas_peucker.h). The ERD methods' initial mesh
// (algorithms/methods/erd_mesh.cpp), `erd edges` and the benchmark all run this chain. With hard
// edges (algorithms/imaging/edge_kind.h) the chain traces the cracks between pixels instead.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/douglas_peucker.h"
#include "algorithms/imaging/edge_kind.h"
#include "algorithms/imaging/image.h"
#include "algorithms/imaging/point_rings.h"
#include "algorithms/imaging/polylines.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

// The parameters of the chain; the defaults are the library's (those the ERD methods start from
// when the image is not simple: beta 0.055, r 0.4, l 5, epsilon one pixel).
struct EdgePolylineParams {
    CannyParams canny;
    double epsilon = 1.0;  // Douglas-Peucker tolerance in pixels (erd generate -e); >= 0
    int min_length = 5;    // the thesis's l: polylines with fewer points are dropped
    LengthRule length_rule = LengthRule::before_simplification;  // when l is counted
    ProgressHook progress;  // edge_polylines(): "edges" at its steps (detection, tracing, simplification)
};

// Doubled-coordinate units (half-pixel grid steps) per pixel of epsilon.
constexpr double kEpsilonUnitsPerPixel = 2.0;
// Douglas-Peucker tolerance on cracks, in multiples of the soft one: the side test is what binds
// (docs/DECISIONS.md "Edge kinds").
constexpr double kHardEpsilonScale = 2.0;

// How a hard-edged chain simplifies its cracks: keeping every pixel on its side
// (simplify_cracks), or plain Douglas-Peucker (fewer points, some pixels change sides).
enum class CrackRule { keep_sides, plain };

// The chain on one image, step by step, keeping what a later call can reuse: a detection with
// the same beta, r and Canny variant as the last one is skipped (the gradient pass is reused by
// the detector when it covers the new parameters), and so is a simplification with the same l
// and tolerance on the same detection (the ERD parameter selection repeats both).
class EdgePolylines {
public:
    // hard: crack edges (crack_edges with canny.beta and canny.r), simplified by `crack` below.
    // gradient: the image whose gradient the (soft) detection reads when not `image` (a colour
    // image, combined as `colour` says; colour.h ColourGradient); may be null.
    explicit EdgePolylines(const Image& image, bool hard = false, const Image* gradient = nullptr,
                           ColourGradient colour = ColourGradient::dizenzo);
    // Steps 1.1 and 1.2: edges with these parameters, traced into polylines.
    // Reports `stage` from `from` to `to` during each detect(): after the detector, the linking
    // and the tracing.
    void set_progress(ProgressHook hook, const char* stage, double from, double to) {
        progress_ = hook;
        stage_ = stage;
        from_ = from;
        to_ = to;
    }
    Status detect(const CannyParams& canny);
    // Makes the detector's gradient pass for `widest` before any detection (soft edges; nothing
    // for hard ones), so that detections with a smaller beta and then `widest` share it.
    Status prepare(const CannyParams& widest);
    // Sets the last detection (its points, polylines and stats) aside: a later detect() with its
    // parameters takes it back instead of detecting again. One is kept, and only until a detect()
    // with other parameters than its own and the current one's.
    void set_aside();
    // Step 1.3 on the last detection: epsilon in doubled-coordinate units (pixels times
    // kEpsilonUnitsPerPixel; hard: times kHardEpsilonScale too). Returns the kept polylines.
    const PolylineList& simplify(int min_length, double epsilon_units, LengthRule rule,
                                          CrackRule crack = CrackRule::keep_sides);

    const CannyStats& stats() const { return stats_; }          // of the last detection
    const PolylineList& traced() const { return traced_; }
    const PolylineList& kept() const { return kept_; }          // of the last simplification
    Grid<std::uint8_t> edge_map() const;                        // (2W-1) x (2H-1), 1 = edge
    // The detections to come are covered by `widest` (EdgeDetector::narrow; nothing for hard edges).
    void narrow(const CannyParams& widest) {
        if (!hard_) detector_.narrow(widest);
    }
    void release_detector() { detector_.release(); }
    // Incremented by every simplification actually run, so callers can cache what they derive.
    std::size_t generation() const { return generation_; }

private:
    const Image& image_;
    ProgressHook progress_;
    const char* stage_ = "";
    double from_ = 0, to_ = 1;
    bool hard_;
    CrackRule crack_ = CrackRule::keep_sides;
    std::optional<CrackDetector> cracker_;  // hard: made by the first detection
    Grid<std::uint8_t> cracks_;  // hard: the last detection's crack map, reused by the next
    EdgeDetector detector_;
    int map_w_, map_h_;  // the half-pixel grid
    bool have_edges_ = false, have_kept_ = false;
    CannyParams canny_;
    int l_ = 0;
    double eps_ = 0;
    LengthRule rule_ = LengthRule::before_simplification;
    std::size_t generation_ = 0;
    CannyStats stats_;
    PolylineList traced_;
    PolylineList kept_;
    struct Detection {
        CannyParams canny;
        CannyStats stats;
        PolylineList traced;
    };
    std::optional<Detection> aside_;
};

// The whole chain in one call. Code::input for a negative or NaN epsilon or Canny parameters out
// of range.
struct EdgePolylineResult {
    Grid<std::uint8_t> edges;          // the half-pixel edge map
    std::size_t traced = 0;            // polylines before simplification
    std::vector<Polyline> polylines;   // simplified, short ones dropped
    CannyStats stats;
};
Status edge_polylines(const Image& image, const EdgePolylineParams& params, EdgePolylineResult* out);

}  // namespace erd
