// ERDGPI (thesis 3.4.3): the initial ERD mesh of step 1 with its wedge values (step 2), refined by
// greedy point insertion on the ERD model's approximation (algorithms/greedy.h, the loop GPI
// uses too).
//
// The face evaluator is the plane through the face's three wedge values. Errors are measured at
// the pixels a face owns by point evaluation of that plane; a pixel lying exactly on a constrained
// edge is measured against the plane of the face that owns it (not the mean of both sides), which
// keeps the per-face sums additive. A candidate on a constrained edge splits it (kernel) and the
// new vertex's two wedges get values by the line search; other vertices keep theirs.
#pragma once
#include "algorithms/model/erd_model.h"
#include "algorithms/methods/erd_params.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// The ERD model as seen by the greedy loop.
class ErdGreedyModel : public GreedyModel {
public:
    explicit ErdGreedyModel(ErdModel& model) : model_(model) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override { return model_.face_plane(cdt, f); }
    Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>* dirty) override;

private:
    ErdModel& model_;
};

// Helpers shared by the two ERD methods (ERDED uses them too).
// Wedge-value options from the generate options (-w, -s).
WedgeValueOptions wedge_options(const GenerateOptions& options);
// Parameter flags (-b -r -l -e -S) as a request for the automatic selection.
ErdParamRequest param_request(const GenerateOptions& options);
struct InitialMesh;
// The common start of ERDED and ERDGPI: checks the image and the target N (result->requested),
// then builds the initial mesh (framework step 1), timed as the stage "initial mesh".
// hard_fallback: InitialMeshOptions::hard_fallback.
Status begin_erd_method(const Image& image, const GenerateOptions& options, ErdMethod method, Cdt* cdt,
                        InitialMesh* mesh, GenerateResult* result, bool hard_fallback = true);
// Appends the chosen parameters and initial-mesh facts to result->notes ("beta: 0.028", ...).
void add_param_notes(const InitialMesh& mesh, const ErdModel& model, GenerateResult* result);

// Registry entry "erdgpi" (algorithms/methods.h contract). Stops at N vertices, or earlier by
// --max-error / --psnr, or when no pixel has nonzero error.
Status generate_erdgpi(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
