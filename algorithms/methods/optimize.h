// Optimisation of a finished mesh (ours, beyond the thesis).
//
// optimize_by_flips (ERDED, ERDGPI with GenerateOptions::flips): data-dependent flips of the
// unconstrained edges (algorithms/methods/flips.h) against the refitted values, then a second
// refit on the flipped mesh.
//
// --optimize for the basic model (ED, GPI): the mesh the method made, with least-squares vertex
// values in place of the image samples at the vertices, then the same flips and refit. The basic
// model's approximating function is linear in its vertex values just as the ERD model's is in
// its wedge values (a vertex without constrained edges has one wedge), so the ERD refit
// (algorithms/methods/wedge_fit.h) serves both: each vertex value starts at, is drawn towards,
// and is bounded around its sample, with the regularisation of GenerateOptions (wedge_prior,
// wedge_bounds). The point set does not change.
#pragma once
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/erd_channels.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/erd_model.h"
#include "algorithms/model/model.h"
#include "kernel/cdt.h"

namespace erd {

// Flips, then refits model's values (drawn towards line_search, wedge_fit.h) when
// options.wedge_fit > 0. systems: the face systems of the refit before (wedge_fit.h), kept in
// step with the flips so the refits after them skip the pass over the pixels.
void optimize_by_flips(Cdt* cdt, const Image& image, const GenerateOptions& options, ErdModel* model,
                       const std::vector<double>* line_search, WedgeFitStats* stats, MeshSystems* systems = nullptr);

// The same for a colour model: flips on the error summed over the channels, each channel's refit
// drawn towards (*line_search)[c]. systems (optional): the refit before's face systems, kept
// for the refits and moves here (wedge_fit.h ColourSystems).
void optimize_by_flips(Cdt* cdt, const GenerateOptions& options, ErdChannels* model,
                       const std::vector<std::vector<double>>* line_search, WedgeFitStats* stats,
                       ColourSystems* systems = nullptr);

// Replaces *model (a basic model of cdt) by the optimised one: refitted values, flipped faces.
// Does nothing unless options.optimize.
void optimize_basic_model(Cdt* cdt, const Image& image, const GenerateOptions& options, Model* model,
                          WedgeFitStats* stats);

}  // namespace erd
