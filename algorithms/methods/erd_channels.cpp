#include "algorithms/methods/erd_channels.h"

#include "algorithms/methods/wedge_fit.h"

namespace erd {

ErdChannels::ErdChannels(const Image& image, const WedgeValueOptions& options, bool shared_position,
                         ColourDensity density) {
    planes_.reserve(std::size_t(image.channels));
    for (int c = 0; c < image.channels; ++c) planes_.push_back(channel_plane(image, c));
    Grid<double> shared;
    if (shared_position && options.rule == 1) shared = colour_mmsodd(image, options.smoothing_order, density);
    for (const Image& p : planes_) {
        models_.push_back(std::make_unique<ErdModel>(p, options));
        if (!shared.data.empty()) models_.back()->set_mmsodd(shared);
    }
}

void ErdChannels::take_mmsodd(ErdChannels& old) {
    for (std::size_t c = 0; c < models_.size() && c < old.models_.size(); ++c) models_[c]->take_mmsodd(*old.models_[c]);
}

void ErdChannels::assign_vertex(const Cdt& cdt, VertInd v) {
    for (auto& m : models_) m->assign_vertex(cdt, v);
}

void ErdChannels::assign_all(const Cdt& cdt) {
    for (auto& m : models_) m->assign_all(cdt);
}

void ErdChannels::pin_pixel_vertices(const Cdt& cdt) {
    for (auto& m : models_) m->pin_pixel_vertices(cdt);
}

void ErdChannels::fit(const Cdt& cdt, const WedgeFitOptions& options, WedgeFitStats* stats,
                      const ProgressHook& progress, const std::vector<std::vector<double>>* priors,
                      ColourSystems* systems) {
    std::vector<const Image*> planes;
    std::vector<ErdModel*> models;
    std::vector<const std::vector<double>*> prior;
    for (std::size_t c = 0; c < models_.size(); ++c) {
        planes.push_back(&planes_[c]);
        models.push_back(models_[c].get());
        if (priors) prior.push_back(&(*priors)[c]);
    }
    std::vector<WedgeFitStats> each;
    fit_wedge_values(cdt, planes, options, models, &each, priors ? &prior : nullptr, progress, systems);
    *stats = WedgeFitStats();
    for (const WedgeFitStats& s : each) {
        stats->iterations = s.iterations > stats->iterations ? s.iterations : stats->iterations;
        stats->sse_before += s.sse_before;
        stats->sse_after += s.sse_after;
    }
}

std::vector<std::vector<double>> ErdChannels::values() const {
    std::vector<std::vector<double>> out(models_.size());
    for (std::size_t c = 0; c < models_.size(); ++c)
        for (std::size_t i = 0; i < models_[c]->entry_count(); ++i) out[c].push_back(models_[c]->entry_value(i));
    return out;
}

void ErdChannels::views(std::vector<const Image*>* planes, std::vector<const ErdModel*>* models) const {
    for (std::size_t c = 0; c < models_.size(); ++c) {
        planes->push_back(&planes_[c]);
        models->push_back(models_[c].get());
    }
}

void ErdChannels::flip(Cdt* cdt, std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces,
                       int threads) const {
    std::vector<const Image*> planes;
    std::vector<const ErdModel*> models;
    views(&planes, &models);
    improve_by_flips(cdt, planes, models, max_flips, stats, seed_faces, threads);
}

void ErdChannels::move(Cdt* cdt, std::int32_t step, double min_gain, MoveStats* stats, const ColourSystems* kept) const {
    std::vector<const Image*> planes;
    std::vector<const ErdModel*> models;
    views(&planes, &models);
    improve_by_moves(cdt, planes, models, step, min_gain, stats, kept);
}

void ErdChannels::to_model(const Cdt& cdt, int width, int height, std::uint32_t maxval, Model* out) const {
    const std::size_t C = models_.size();
    Model one;
    for (std::size_t c = 0; c < C; ++c) {
        models_[c]->to_model(cdt, width, height, maxval, c == 0 ? out : &one);
        const Model& m = c == 0 ? *out : one;
        if (c == 0) {
            out->channels = int(C);
            std::vector<double> values(C * m.values.size());
            std::vector<std::array<double, 3>> corners(C * m.corner_values.size());
            for (std::size_t i = 0; i < m.values.size(); ++i) values[i * C] = m.values[i];
            for (std::size_t i = 0; i < m.corner_values.size(); ++i) corners[i * C] = m.corner_values[i];
            out->values = std::move(values);
            out->corner_values = std::move(corners);
            continue;
        }
        for (std::size_t i = 0; i < m.values.size(); ++i) out->values[i * C + c] = m.values[i];
        for (std::size_t i = 0; i < m.corner_values.size(); ++i) out->corner_values[i * C + c] = m.corner_values[i];
    }
}

}  // namespace erd
