// Step 1 of the ERD framework (thesis 3.4.1): the initial mesh of ERDED and ERDGPI.
//
//   1.1-1.3 half-pixel edges with beta, r; polylines; Douglas-Peucker with epsilon, polylines
//       shorter than l dropped (the chain of algorithms/imaging/edge_polylines.h; with hard
//       edges its crack version, algorithms/imaging/edge_kind.h);
//   1.4 P = polyline vertices + the four corners, E = polyline segments, constrained DT.
// beta, r, l, epsilon come from the automatic selection (algorithms/erd_params.h) unless given.
// Constraint segments the kernel refuses (they would cross an earlier one) are counted.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/douglas_peucker.h"
#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/methods/erd_params.h"
#include "algorithms/imaging/image.h"
#include "algorithms/imaging/polylines.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

struct InitialMeshOptions {
    ErdMethod method = ErdMethod::erdgpi;
    std::size_t target = 0;  // N, the final mesh size (it steers the parameter selection)
    ErdParamRequest request; // flags the user gave
    // When l is counted (docs/DECISIONS.md "Edge detection and polylines" has the numbers).
    LengthRule length_rule = LengthRule::before_simplification;
    // Doubled-coordinate units per unit of epsilon: 2 = epsilon in pixels, 1 = in half pixels
    // (docs/DECISIONS.md "Edge detection and polylines").
    double eps_unit = kEpsilonUnitsPerPixel;
    // Hard edges (algorithms/imaging/edge_kind.h): step 1.1 traces the cracks between pixels
    // instead of Canny's half-pixel maxima, and step 1.3 keeps every pixel on its side.
    bool hard_edges = false;
    // Hard edges whose side-keeping curves hold more points than the selection accepts (0.7 N):
    // true = plain Douglas-Peucker on the same cracks at that beta; false = keep the side test
    // and let the selection shrink beta and grow l.
    bool hard_fallback = true;
    // User constraints (GenerateOptions::constraints; may be null) and whether to detect edges.
    const std::vector<Polyline>* constraints = nullptr;
    bool detect = true;
    // An image with nodata (issue 47): the outline of its valid region, inserted first (before the
    // user's constraints), and the pixels near nodata (algorithms/imaging/valid_region.h), where
    // detected polylines are cut. Neither is in out->polylines. May be null.
    const std::vector<Polyline>* outline = nullptr;
    const std::vector<std::uint8_t>* near_nodata = nullptr;
    // A tile (GenerateOptions::border_crossings): points on its sides where a constrained edge must
    // end; the polylines (cut at the sides by near_nodata) are joined to them (tiles.h
    // join_crossings). May be null.
    const std::vector<LatticePoint>* side_crossings = nullptr;
    // A real image meshed to --max-error E: detected polylines whose step (the median over their
    // segments of the difference of the image 1.5 pixels to either side) is below this are left
    // out, so that only cliffs that pay for their points become constraints. 0: all kept.
    double min_step = 0.0;
    // Colour (issue 17): the colour image whose gradient soft-edge detection reads instead of the
    // image given (its luma), combined as colour_gradient says; null: the image given.
    const Image* colour = nullptr;
    ColourGradient colour_gradient = ColourGradient::luma;
    // "initial mesh" with the fraction done: each edge detection, each count, the insertion.
    ProgressHook progress;
    // Threads of edge detection's gradient pass (CannyParams::threads): the same mesh for any.
    int threads = 1;
};

struct InitialMesh {
    ErdParams params;                  // the parameters used
    Grid<std::uint8_t> edges;          // half-pixel edge map of the chosen parameters, (2W-1)x(2H-1)
    std::vector<Polyline> polylines;   // simplified polylines that made it into the mesh
    std::size_t constraint_points = 0; // distinct polyline points (before the kernel)
    std::size_t dropped_crossing = 0;  // constraint pieces refused by the kernel (crossings)
    std::size_t joined_crossings = 0;  // side_crossings a detected polyline was continued to
    std::size_t dropped_polylines = 0; // polylines left out because the mesh would exceed N
    std::size_t n0 = 0;                // vertices of the initial mesh (corners included)
    // Some count of the parameter selection took the plain curves (hard_fallback): only then can
    // a run without the fallback come out differently.
    bool plain_fallback = false;
};

// Builds the initial mesh of image into cdt (reset first). User constraints (options.constraints)
// go in first and are kept whole: a point outside the image, more distinct points than N - 4, or
// two user segments crossing fail with Code::input; they are appended to out->polylines and
// marked in out->edges.
// The mesh never has more than max(4, N) vertices: if the polylines hold more points than that
// (tiny N), whole polylines are left out, longest kept first.
Status build_initial_mesh(const Image& image, const InitialMeshOptions& options,
                          Cdt* cdt, InitialMesh* out);

// Inserts P and E of the given polylines into cdt (points already there are shared). Adds the
// refused constraint pieces (crossing an earlier constrained edge) to *dropped, or with
// refuse_crossing fails (Code::input, naming the segment) at the first one.
Status insert_polylines(const std::vector<Polyline>& polylines, Cdt* cdt, std::size_t* dropped,
                        bool refuse_crossing = false);

// Distinct points of a set of polylines (they share end points at junctions).
std::size_t distinct_points(const PolylineList& polylines);

}  // namespace erd
