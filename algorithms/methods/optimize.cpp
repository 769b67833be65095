#include "algorithms/methods/optimize.h"

#include "algorithms/methods/flips.h"
#include "algorithms/methods/scaffold.h"
#include "algorithms/methods/wedge_fit.h"

namespace erd {

void optimize_by_flips(Cdt* cdt, const Image& image, const GenerateOptions& options, ErdModel* model,
                       const std::vector<double>* line_search, WedgeFitStats* stats, WedgeFitCache* cache) {
    // Round 1 tries every edge; later rounds (after a refit moved the values) only the edges of
    // the faces the previous round flipped, where the refit moved the most.
    std::vector<FaceInd> seed;
    for (int round = 0; round < options.flips; ++round) {
        FlipStats fs;
        improve_by_flips(cdt, image, *model, 8 * cdt->face_count(), &fs, round == 0 ? nullptr : &seed);
        seed = std::move(fs.changed);
        if (fs.flips == 0) break;
        if (options.wedge_fit > 0) {
            WedgeFitStats again;
            fit_wedge_values(*cdt, image, wedge_fit_options(options), model, &again, line_search, {}, cache);
            if (stats) stats->sse_after = again.sse_after;
        }
    }
}

void optimize_basic_model(Cdt* cdt, const Image& image, const GenerateOptions& options, Model* model,
                          WedgeFitStats* stats) {
    if (!options.optimize) return;
    // With no constrained edge every vertex has one wedge, whose value is phi_bar at the vertex:
    // the sample itself at a pixel, so the fit starts from the basic model's values.
    ErdModel erd(image, wedge_options(options));
    erd.assign_all(*cdt);
    std::vector<double> samples;
    for (std::size_t i = 0; i < erd.entry_count(); ++i) samples.push_back(erd.entry_value(i));
    WedgeFitCache cache;
    if (options.wedge_fit > 0) fit_wedge_values(*cdt, image, wedge_fit_options(options), &erd, stats, &samples, {}, &cache);
    if (options.flips) optimize_by_flips(cdt, image, options, &erd, &samples, stats, &cache);
    *model = basic_model(*cdt, image);
    for (VertInd v = 0; v < model->vertices.size(); ++v) model->values[v] = erd.vertex_value(v);
}

}  // namespace erd
