// Bad-point replacement (Adams, "An incremental/decremental Delaunay mesh-generation framework for
// image representation", Signal Processing 93 (2013); --bpr R): a post-processing step for any
// mesh. An exchange removes the worst-placed vertex (the least significant, removal.h) and inserts
// the pixel of largest error in the face of largest squared error (GPI's rule); it is kept when
// the whole-image squared error went down, else undone exactly (the CDT is unique, the vertex's
// values are put back) and that vertex is not tried again in the round. A round tries N exchanges
// (N the vertex count) or until every removable vertex was tried in vain; R rounds. So the error never goes up: the
// result is never worse than the input under the error the loop measures (point evaluation;
// rounded for the basic model).
#pragma once
#include "algorithms/imaging/image.h"
#include "algorithms/methods/removal.h"
#include "algorithms/methods/result.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

// Runs `rounds` rounds on cdt (the mesh's live vertices keep their count). The mesh may hold dead
// vertices afterwards: compact it (compact_cdt) for the model writers. Adds to stats->bpr_*.
Status bad_point_replacement(Cdt* cdt, const Image& image, RemovalModel& model, bool round_values, int rounds,
                             const ProgressHook& progress, RemovalRunStats* stats);

}  // namespace erd
