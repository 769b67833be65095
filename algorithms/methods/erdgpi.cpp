#include "algorithms/methods/erdgpi.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "algorithms/methods/erd_channels.h"
#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/erd_removal.h"
#include "algorithms/methods/scaffold.h"

namespace erd {

namespace {

// ERDGPI on a colour image, from the initial mesh (step 1, on the luma plane): the greedy loop
// on all channels' errors (ColourErdGreedyModel), or for comparison on the luma plane's gray
// model (ColourChoices::greedy_on_luma) with the colour values assigned to the final mesh.
Status erdgpi_colour(const Image& image, const GenerateOptions& options, std::size_t start, Cdt* cdt,
                     InitialMesh* mesh, StageTimer* timer, GenerateResult* result) {
    const std::size_t n = start;
    const WedgeValueOptions wo = wedge_options(options);
    GreedyOptions go = greedy_options(options, n);
    go.round_values = false;  // as in gray
    result->stats.has_greedy = true;
    ErdChannels model(image, wo, options.colour.shared_wedge_position, options.colour.density);
    Status st;
    if (options.colour.greedy_on_luma) {
        const Image luma = luma_of(image);
        ErdModel gray(luma, wo);
        gray.assign_all(*cdt);
        ErdGreedyModel greedy(gray);
        if (cdt->vertex_count() < n && !(st = greedy_refine(*cdt, luma, greedy, go, &result->stats.greedy))) return st;
        model.assign_all(*cdt);
    } else {
        model.assign_all(*cdt);
        ColourErdGreedyModel greedy(model);
        if (cdt->vertex_count() < n && !(st = greedy_refine(*cdt, image, greedy, go, &result->stats.greedy))) return st;
    }
    timer->lap("greedy insertion");
    if (cdt->vertex_count() > result->requested && !options.lock_border) {
        // As gray: the values refitted first (each channel drawn towards its line-search values).
        WedgeFitStats unused;
        if (options.removal_refit > 0 && options.wedge_fit > 0) model.fit(*cdt, wedge_fit_options(options), &unused);
        ErdChannelsRemovalModel rm(model);
        result->stats.has_removal = true;
        st = erd_remove_to(cdt, image, rm, result->requested, options.removal_lazy, options.progress,
                           &result->stats.removal);
        if (!st) return st;
        // A fresh model of the compact mesh: its wedge values as insertion assigns them.
        ErdChannels compact(image, wo, options.colour.shared_wedge_position, options.colour.density);
        compact.take_mmsodd(model);  // as gray's: the MMSODD the line searches computed is kept
        compact.assign_all(*cdt);
        timer->lap("point removal");
        return finish_erd_method(*cdt, image, options, mesh, &compact, timer, result);
    }
    return finish_erd_method(*cdt, image, options, mesh, &model, timer, result);
}

// ERDGPI to `oversample` * N vertices (1: N, plain ERDGPI), then removal to N (erd_removal.h).
Status erdgpi_run(const Image& image, const GenerateOptions& options, bool hard_fallback, double oversample,
                  GenerateResult* result) {
    Cdt cdt;
    InitialMesh mesh;
    Status st = begin_erd_method(image, options, ErdMethod::erdgpi, &cdt, &mesh, result, hard_fallback);
    if (!st) return st;
    mesh.edges = Grid<std::uint8_t>();  // only ERDED reads the edge map again
    const std::size_t start =
        std::max(result->requested, std::min(image.pixels(), std::size_t(double(result->requested) * oversample + 0.5)));
    const std::int64_t n = std::int64_t(start);
    StageTimer timer(result);

    if (options.progress.report_cancelled("wedge values", 0.0)) return Status::failure(kCancelled);
    if (image.channels > 1) return erdgpi_colour(image, options, start, &cdt, &mesh, &timer, result);
    ErdModel model(image, wedge_options(options));
    model.assign_all(cdt);
    timer.lap("wedge values");

    ErdGreedyModel greedy(model);
    GreedyOptions go = greedy_options(options, std::size_t(n));
    // A real image with --max-error: a looser bound first, the minimax fit and the last
    // insertions reach E (finish_erd_method).
    if (image.real() && options.max_error >= 0 && options.minimax_rounds > 0) go.max_error = options.max_error * options.max_slack;
    // Real-valued errors: the ERD model is judged by its supersampled reconstruction, which
    // rounding the point evaluation does not model (DECISIONS.md: +0.85 dB on bull at 0.125%).
    go.round_values = false;
    go.supersampled = options.supersampled_errors;
    result->stats.has_greedy = true;
    // Staged refits (ours): refinement stops at K evenly spaced sizes between the initial mesh and
    // N, the wedge values are refitted, and refinement goes on against the refitted errors. The
    // line-search value of every wedge is kept, so each refit (and the last) is drawn towards
    // and bounded around it (wedge_fit.h).
    std::vector<double> line_search;
    const bool staged = options.refit_stages > 0 && options.wedge_fit > 0;
    const std::size_t n0 = cdt.vertex_count();
    for (int k = 1; staged && k <= options.refit_stages; ++k) {
        go.target_vertices = n0 + (std::size_t(n) - std::min(n0, std::size_t(n))) * std::size_t(k) /
                                      std::size_t(options.refit_stages + 1);
        if (cdt.vertex_count() < go.target_vertices) {
            st = greedy_refine(cdt, image, greedy, go, &result->stats.greedy);
            if (!st) return st;
        }
        for (std::size_t i = line_search.size(); i < model.entry_count(); ++i) line_search.push_back(model.entry_value(i));
        fit_wedge_values(cdt, image, wedge_fit_options(options), &model, nullptr, &line_search);
    }
    go.target_vertices = std::size_t(n);
    if (cdt.vertex_count() < std::size_t(n)) {
        st = greedy_refine(cdt, image, greedy, go, &result->stats.greedy);
        if (!st) return st;
    }
    timer.lap("greedy insertion");
    for (std::size_t i = line_search.size(); staged && i < model.entry_count(); ++i)
        line_search.push_back(model.entry_value(i));
    // A tile's fixed side vertices (options.lock_border) are never removed: its initial mesh may
    // hold more than N (side and constraint points), and then stays so.
    if (cdt.vertex_count() > result->requested && !options.lock_border) {
        // Removal to N in options.removal_stages stages of equal size ratio; before each the
        // wedge values are refitted (options.removal_refit), drawn towards the line-search ones,
        // so that the significances see values like the final ones. Each stage ends with the
        // compact mesh and a fresh model (its values the line-search ones again).
        std::unique_ptr<ErdModel> current;
        ErdModel* m = &model;
        const std::size_t from = cdt.vertex_count();
        const int stages = std::max(1, options.removal_stages);
        result->stats.has_removal = true;
        // The refit's face systems give removal its first face errors (PointRemover).
        MeshSystems systems;
        const auto refit = [&](bool first) {
            systems = MeshSystems();
            if (options.removal_refit <= 0 || options.wedge_fit <= 0) return;
            std::vector<double> ls;
            for (std::size_t i = 0; i < m->entry_count(); ++i) ls.push_back(m->entry_value(i));
            fit_wedge_values(cdt, image, wedge_fit_options(options), m, nullptr, staged && first ? &line_search : &ls,
                             {}, &systems);
        };
        for (int cycle = 0; cycle <= options.removal_cycles; ++cycle) {
            if (cycle > 0) {  // insertion again to the start size, against the refitted values
                refit(false);
                ErdGreedyModel again(*m);
                go.target_vertices = from;
                st = greedy_refine(cdt, image, again, go, &result->stats.greedy);
                if (!st) return st;
            }
            const std::size_t top = cdt.vertex_count();
            for (int k = 1; k <= stages; ++k) {
                const std::size_t to =
                    k == stages ? result->requested
                                : std::size_t(double(top) * std::pow(double(result->requested) / double(top),
                                                                     double(k) / double(stages)) + 0.5);
                refit(cycle == 0 && k == 1);
                ErdRemovalModel rm(*m);
                st = erd_remove_to(&cdt, image, rm, to, options.removal_lazy, options.progress, &result->stats.removal,
                                   &systems);
                if (!st) return st;
                auto fresh = std::make_unique<ErdModel>(image, wedge_options(options));
                fresh->take_mmsodd(*m);
                fresh->assign_all(cdt);
                current = std::move(fresh);
                m = current.get();
            }
        }
        timer.lap("point removal");
        return finish_erd_method(cdt, image, options, &mesh, m, &timer, result);
    }
    return finish_erd_method(cdt, image, options, &mesh, &model, &timer, result, staged ? &line_search : nullptr);
}

Status erdgpi_once(const Image& image, const GenerateOptions& options, bool hard_fallback, GenerateResult* result) {
    return erdgpi_run(image, options, hard_fallback, 1.0, result);
}

Status erdgpr_once(const Image& image, const GenerateOptions& options, bool hard_fallback, GenerateResult* result) {
    if (Status st = removal_accepts(image, "erdgpr"); !st) return st;
    Status st = erdgpi_run(image, options, hard_fallback, options.oversample > 0 ? options.oversample : kErdgprOversample,
                           result);
    // Vertices that insertion put on constrained edges cannot be removed: when they alone exceed
    // N (tiny N on an edge-rich image), plain ERDGPI makes the mesh instead.
    if (st && result->achieved > result->requested) {
        *result = GenerateResult();
        st = erdgpi_run(image, options, hard_fallback, 1.0, result);
    }
    return st;
}

}  // namespace

Status generate_erdgpi(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    return run_erd_method(image, options, erdgpi_once, result);
}

Status generate_erdgpr(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    if (options.ending_given) return run_erd_method(image, options, erdgpr_once, result);
    GenerateOptions o = options;
    o.flips = kErdgprEnding.flips;
    o.moves = kErdgprEnding.moves;
    o.move_step = kErdgprEnding.move_step;
    o.move_min_gain = kErdgprEnding.move_min_gain;
    o.colour.moves = true;
    return run_erd_method(image, o, erdgpr_once, result);
}

}  // namespace erd
