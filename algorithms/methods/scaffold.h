// The method scaffold: the steps every mesh-generation method shares, so that each method file
// (ed, gpi, erded, erdgpi) holds only its own steps and includes no other method's header.
//
//   basic model (ED, GPI):   begin_method ... finish_basic_method
//   ERD model (ERDED, ERDGPI): begin_erd_method (N, step 1: the initial mesh) ... finish_erd_method
//                            (wedge refit, the model, the step-1 facts, the polylines)
// Stages are timed with a StageTimer into GenerateResult::stages.
#pragma once
#include <chrono>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/erd_channels.h"
#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/erd_params.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/erd_model.h"
#include "algorithms/model/model.h"
#include "kernel/cdt.h"
#include "kernel/status.h"

namespace erd {

// Times consecutive stages: lap(name) records the time since the last lap (or construction).
class StageTimer {
public:
    explicit StageTimer(GenerateResult* result) : result_(result), t0_(std::chrono::steady_clock::now()) {}
    void lap(const char* name) {
        result_->stages.push_back({name, seconds_since(t0_)});
        t0_ = std::chrono::steady_clock::now();
    }

private:
    GenerateResult* result_;
    std::chrono::steady_clock::time_point t0_;
};

// The common start of every method: clears *result, computes N from the options, checks the image
// and N (check_target) and records N in result->requested.
Status begin_method(const Image& image, const GenerateOptions& options, GenerateResult* result);

// The basic model of a triangulation whose vertices are pixels: vertex values are the samples (a
// real image's: lattice_value, also at the outline's half-pixel points).
Model basic_model(const Cdt& cdt, const Image& image);

// An image with nodata (issue 47): the outline of its valid region (algorithms/imaging/
// valid_region.h) inserted into cdt (just reset) as constraints, before anything else, so that no
// face crosses it; counted in stats->raster. Does nothing for an image without nodata. Fails
// (Code::input) when the corners and the outline are more than `target` points.
Status insert_valid_outline(const Image& image, Cdt* cdt, RunStats* stats, std::size_t target);

// A tile (options.lock_border): options.border_points inserted into cdt as plain vertices (each a
// pixel on the rectangle's sides, else Code::input). Does nothing otherwise.
Status insert_border_points(const GenerateOptions& options, Cdt* cdt);

// Gives *m (a model of image made on the whole rectangle) the image's raster facts: its meta
// (type, nodata, georeferencing) and, for a real image, real values with the image's range and
// no maxval, the faces over nodata dropped (counted in stats->raster when stats is given).
void finish_raster_model(const Image& image, Model* m, RunStats* stats);

// The end of ED and GPI: the basic model of cdt into result (model, achieved), timed as "model";
// with options.optimize, then the least-squares values and flips (optimize.h), timed as "optimize".
// A real image with --max-error: greedy insertion first goes on until the largest error over the
// valid pixels is at most E (the bound holds for the model given back; not with --optimize, which
// the CLI refuses there), and the model's largest error is measured into stats.raster.
// With options.bpr, bad-point replacement (bpr.h) on cdt first, timed as "bad-point replacement";
// its failure (cancel, kernel) is returned.
Status finish_basic_method(Cdt& cdt, const Image& image, const GenerateOptions& options, StageTimer* timer,
                         GenerateResult* result);

// The greedy loop's options for GPI and ERDGPI: stop at n vertices or by --max-error / --psnr,
// errors rounded as options.round_values says, the progress hook.
GreedyOptions greedy_options(const GenerateOptions& options, std::size_t n);

// Wedge-value options from the generate options (-w, -s, the line-search range).
WedgeValueOptions wedge_options(const GenerateOptions& options);
// The refit's options (iterations, prior weight, support bounds).
WedgeFitOptions wedge_fit_options(const GenerateOptions& options);

// Parameter flags (-b -r -l -e -S) as a request for the automatic selection.
ErdParamRequest param_request(const GenerateOptions& options);

// The common start of ERDED and ERDGPI: begin_method, the kind of edge (options.edges; auto
// measures the image: algorithms/imaging/edge_kind.h) into result->model.edges and the stats,
// then the initial mesh (framework step 1) into *cdt and *mesh, timed as the stage "initial
// mesh". hard_fallback: InitialMeshOptions::hard_fallback.
Status begin_erd_method(const Image& image, const GenerateOptions& options, ErdMethod method, Cdt* cdt,
                        InitialMesh* mesh, GenerateResult* result, bool hard_fallback = true);

// One run of ERDED or ERDGPI (from begin_erd_method with hard_fallback to finish_erd_method).
using ErdRun = Status (*)(const Image& image, const GenerateOptions& options, bool hard_fallback, GenerateResult* result);

// ERDED or ERDGPI: run(hard_fallback = true); when the model's edges are hard, also run(false),
// since each treatment of crack curves too long for the budget wins on some images
// (docs/DECISIONS.md "Edge kinds"), and keep the model whose point reconstruction has the higher
// PSNR (the first on a tie); both PSNRs go to result->stats.erd. run(false) is skipped when no
// count of run(true) took the plain curves (stats.erd.plain_fallback false): it would repeat
// run(true) exactly, so both PSNRs are run(true)'s.
// Under --edges auto, an image measured stepped (algorithms/imaging/edge_kind.h) is then
// also meshed with the other treatments of its edges (soft detection, hard edges, no detected
// edges), each model's edge kinds chosen by fit (algorithms/model/edge_kinds.h), and the model
// whose own reconstruction has the highest PSNR is kept (docs/DECISIONS.md "Edge kinds");
// stats.erd.tried_psnr has the three PSNRs.
Status run_erd_method(const Image& image, const GenerateOptions& options, ErdRun run, GenerateResult* result);

// The common end of ERDED and ERDGPI once cdt is final and *model holds its wedge values: the
// least-squares refit (options.wedge_fit > 0, stage "wedge refit"), the ERD model into result,
// the step-1 facts and the wedge-value counts, the polylines (moved out of *mesh); stage "model".
// With options.bpr, bad-point replacement (bpr.h) first, on the model's current values, then a
// fresh model of the compact mesh (line-search values) goes on.
// line_search_values: the values the refit is drawn towards and bounded around when the model's
// current values are not the line-search ones (ERDGPI's staged refits); nullptr: the current ones.
Status finish_erd_method(Cdt& cdt, const Image& image, const GenerateOptions& options, InitialMesh* mesh,
                       ErdModel* model, StageTimer* timer, GenerateResult* result,
                       const std::vector<double>* line_search_values = nullptr);
// The same for a colour image: the refit of every channel with the same options, drawn towards
// each channel's current (line-search) values (ErdChannels::fit), the flips on the error summed
// over the channels and the refit again (options.flips), the C-channel model.
Status finish_erd_method(Cdt& cdt, const Image& image, const GenerateOptions& options, InitialMesh* mesh,
                       ErdChannels* model, StageTimer* timer, GenerateResult* result);

}  // namespace erd
