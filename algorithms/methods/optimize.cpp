#include "algorithms/methods/optimize.h"

#include <algorithm>
#include <cstdint>

#include "algorithms/methods/flips.h"
#include "algorithms/methods/scaffold.h"
#include "algorithms/methods/wedge_fit.h"

namespace erd {

void optimize_by_flips(Cdt* cdt, const Image& image, const GenerateOptions& options, ErdModel* model,
                       const std::vector<double>* line_search, WedgeFitStats* stats, MeshSystems* systems) {
    // Round 1 tries every edge; later rounds (after a refit moved the values) only the edges of
    // the faces the previous round flipped, where the refit moved the most.
    // Each refit here starts from the values of the one before, which a few flips or moves have
    // barely changed: half the first refit's CG steps do (docs/DECISIONS.md "Mesh optimisation").
    WedgeFitOptions later = wedge_fit_options(options);
    later.iterations = (later.iterations + 1) / 2;
    auto refit = [&] {
        WedgeFitStats again;
        fit_wedge_values(*cdt, image, later, model, &again, line_search, {}, systems);
        if (stats) stats->sse_after = again.sse_after;
    };
    std::vector<FaceInd> seed;
    for (int round = 0; round < options.flips; ++round) {
        FlipStats fs;
        improve_by_flips(cdt, image, *model, 8 * cdt->face_count(), &fs, round == 0 ? nullptr : &seed, systems,
                         options.flip_min_share, options.threads);
        seed = std::move(fs.changed);
        if (fs.flips == 0 && options.moves == 0) break;
        const bool moves = round < options.moves && systems && options.wedge_fit > 0;
        // After round 1, a round's few flips leave the values where they were: its moves follow
        // them directly, with one refit after both.
        if (options.wedge_fit > 0 && (round == 0 || !moves)) refit();
        if (moves) {
            MoveStats ms;
            // Coarse to fine: each round's moves take half the step of the round before (at
            // least half a pixel).
            const std::int32_t step = std::max<std::int32_t>(1, options.move_step >> round);
            improve_by_moves(cdt, image, *model, step, options.move_min_gain, systems, &ms);
            refit();
        }
    }
}

void optimize_by_flips(Cdt* cdt, const GenerateOptions& options, ErdChannels* model,
                       const std::vector<std::vector<double>>* line_search, WedgeFitStats* stats,
                       ColourSystems* systems) {
    std::vector<FaceInd> seed;  // as the gray rounds above, their refits with half the steps too
    WedgeFitOptions later = wedge_fit_options(options);
    later.iterations = (later.iterations + 1) / 2;
    const bool with_moves = options.colour.moves && options.moves > 0 && options.wedge_fit > 0;
    const auto refit = [&] {
        WedgeFitStats again;
        model->fit(*cdt, later, &again, {}, line_search, systems);
        if (stats) stats->sse_after = again.sse_after;
    };
    for (int round = 0; round < options.flips; ++round) {
        FlipStats fs;
        model->flip(cdt, 8 * cdt->face_count(), &fs, round == 0 ? nullptr : &seed, options.threads);
        seed = std::move(fs.changed);
        const bool moves = with_moves && round < options.moves;
        if (fs.flips == 0 && !moves) break;
        if (options.wedge_fit > 0 && fs.flips > 0) refit();
        if (moves) {  // options.colour.moves: as the gray rounds' moves, each followed by a refit
            MoveStats ms;
            model->move(cdt, std::max<std::int32_t>(1, options.move_step >> round), options.move_min_gain, &ms, systems);
            if (ms.moves > 0) refit();
        }
    }
}

void optimize_basic_model(Cdt* cdt, const Image& image, const GenerateOptions& given, Model* model,
                          WedgeFitStats* stats) {
    if (!given.optimize) return;
    // The point set stays (no vertex moves), and every quadrilateral is tried: --optimize as it
    // was decided (docs/DECISIONS.md).
    GenerateOptions options = given;
    options.moves = 0;
    options.flip_min_share = 0;
    // With no constrained edge every vertex has one wedge, whose value is phi_bar at the vertex:
    // the sample itself at a pixel, so the fit starts from the basic model's values.
    ErdModel erd(image, wedge_options(options));
    erd.assign_all(*cdt);
    std::vector<double> samples;
    for (std::size_t i = 0; i < erd.entry_count(); ++i) samples.push_back(erd.entry_value(i));
    MeshSystems systems;
    if (options.wedge_fit > 0)
        fit_wedge_values(*cdt, image, wedge_fit_options(options), &erd, stats, &samples, {}, &systems);
    if (options.flips) optimize_by_flips(cdt, image, options, &erd, &samples, stats, &systems);
    *model = basic_model(*cdt, image);
    for (VertInd v = 0; v < model->vertices.size(); ++v) {
        // The outline of a real image's valid region is constrained, so its points have a wedge
        // over nodata too: they keep their basic values (lattice_value).
        const LatticePoint p = model->vertices[v];
        if (!image.has_holes() || (p.x % 2 == 0 && p.y % 2 == 0)) model->values[v] = erd.vertex_value(v);
    }
}

}  // namespace erd
