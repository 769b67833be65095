// Data-dependent edge flips (ours, after Li and Adams 2013 and Yu, Morse and Sederberg 2001):
// the triangulation of the final point set need not be the Delaunay one. An unconstrained
// interior edge whose two faces form a strictly convex quadrilateral is flipped when the other
// diagonal gives a smaller squared error of the model's planes over the quadrilateral's pixels
// (point evaluation at the pixels each face owns, kernel/raster.h). Constrained edges, and so
// every wedge, stay as they are; the corner values move with their vertices (an unconstrained
// edge separates no wedges). Each flip lowers the whole-image squared error, so the loop ends;
// it stops early after max_flips flips.
#pragma once
#include <cstddef>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/erd_model.h"
#include "kernel/cdt.h"

namespace erd {

struct FlipStats {
    std::size_t flips = 0;      // flips made
    std::size_t tested = 0;     // flippable edges whose two diagonals were compared
    std::size_t ahead = 0;      // tests whose sums a second thread had measured (threads >= 2)
    double sse_before = 0.0;    // squared error of the touched quadrilaterals before / after
    double sse_after = 0.0;
    std::vector<FaceInd> changed;  // faces a flip rewrote (with repeats)
};

// Flips edges of *cdt (values from model, which keeps its wedge values) while a flip lowers the
// squared error. Edges are visited from a work list seeded with every edge of the faces in
// *seed_faces (every edge when it is null); a flip puts the four outer edges of its
// quadrilateral back on it. systems, when they match *cdt (the refit's, wedge_fit.h), give the
// squared error of the faces before a flip without a pass over their pixels, and are kept in
// step: a flip rewrites the systems of its two faces.
// With threads >= 2 (0: the machine's) on a large image, a second thread measures the first
// tests ahead of the loop: the same flips and sums.
void improve_by_flips(Cdt* cdt, const Image& image, const ErdModel& model, std::size_t max_flips, FlipStats* stats,
                      const std::vector<FaceInd>* seed_faces = nullptr, MeshSystems* systems = nullptr,
                      double min_share = 0.0, int threads = 1);

// The same for a colour model (issue 17): channel c's values from models[c] on planes[c], the
// squared error summed over the channels (no systems, no skip). The models are one ErdChannels'
// channels: they share their wedges (entries in the same order), so a corner is looked up once.
void improve_by_flips(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                      std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces = nullptr,
                      int threads = 1);

struct MoveStats {
    std::size_t moves = 0;   // vertices moved
    std::size_t tested = 0;  // positions whose error was measured
};

// Vertex moves (ours): each interior vertex with no constrained edge, in index order, is tried
// at the one of its 8 lattice neighbours at distance `step` (doubled units: 2 = one pixel) that
// lies most against the gradient of its faces' squared error in its position (from the face
// systems, no pass over the pixels; the values of model as they are), and moves there when that
// lowers the squared error of its faces. A vertex whose first-order gain is below min_gain times
// its faces' error is not tried. systems as for improve_by_flips (required; moved faces are
// marked stale).
void improve_by_moves(Cdt* cdt, const Image& image, const ErdModel& model, std::int32_t step, double min_gain,
                      MeshSystems* systems, MoveStats* stats);

// The same for one triangulation's 1 or 3 channels (a colour model: models[c] on planes[c], one
// ErdChannels' channels, which share their wedges): the gradient and the errors summed over the
// channels, the channels' face systems made here (in one pass) as the moves first need them, or
// taken from *kept (optional, three channels) where its faces' corners are the same.
void improve_by_moves(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                      std::int32_t step, double min_gain, MoveStats* stats, const ColourSystems* kept = nullptr);

}  // namespace erd
