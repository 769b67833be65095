// The ERD model of a colour image (issue 17): one triangulation, one value per channel at every
// wedge. Channel c's wedge values are those of an ErdModel (algorithms/model/erd_model.h) on
// channel c's plane, so each channel's line search, values and least-squares refit are the gray
// ones on that plane; the wedges themselves (ids, counts, order) depend on the triangulation
// alone and are the same in every channel. The refit decouples by channel: the approximating
// function of one channel depends on that channel's values only, so fitting each channel on its
// own is the joint least-squares fit.
#pragma once
#include <memory>
#include <vector>

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/flips.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/methods/result.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/erd_model.h"
#include "algorithms/model/model.h"
#include "kernel/cdt.h"

namespace erd {

class ErdChannels {
public:
    // image: the colour samples (its planes are copied). shared_position: every wedge takes its
    // value in all channels at one line-search position, from the MMSODD combined as `density`
    // says (ColourChoices::shared_wedge_position); otherwise each channel searches its own MMSODD.
    ErdChannels(const Image& image, const WedgeValueOptions& options, bool shared_position, ColourDensity density);

    int channels() const { return int(models_.size()); }
    const ErdModel& channel(int c) const { return *models_[std::size_t(c)]; }
    ErdModel& channel(int c) { return *models_[std::size_t(c)]; }

    // Each channel's MMSODD (grid or cached pixels) taken from old's (ErdModel::take_mmsodd).
    void take_mmsodd(ErdChannels& old);
    void assign_vertex(const Cdt& cdt, VertInd v);
    void assign_all(const Cdt& cdt);
    // ErdModel::pin_pixel_vertices for every channel (a real image).
    void pin_pixel_vertices(const Cdt& cdt);
    // fit_wedge_values on every channel with options, each channel drawn towards and bounded
    // around its current (line-search) values; the stats add the channels' squared errors.
    // priors: channel c's values to draw towards and bound around instead of its current ones
    // (the line-search values when a refit already moved them); may be null.
    // systems (optional): the face systems kept from the refits and moves before (wedge_fit.h).
    void fit(const Cdt& cdt, const WedgeFitOptions& options, WedgeFitStats* stats, const ProgressHook& progress = {},
             const std::vector<std::vector<double>>* priors = nullptr, ColourSystems* systems = nullptr);
    // Every channel's current values (ErdModel::entry_value), channel by channel.
    std::vector<std::vector<double>> values() const;
    // Data-dependent flips (flips.h) on the squared error summed over the channels.
    void flip(Cdt* cdt, std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces,
              int threads = 1) const;
    // Vertex moves (flips.h improve_by_moves) on the squared error summed over the channels.
    void move(Cdt* cdt, std::int32_t step, double min_gain, MoveStats* stats, const ColourSystems* kept = nullptr) const;
    // The C-channel ERD model: values[v*C + c], corner_values[f*C + c] (algorithms/model/model.h).
    void to_model(const Cdt& cdt, int width, int height, std::uint32_t maxval, Model* out) const;

private:
    // Each channel's plane and model, appended in channel order (the flips' and moves' inputs).
    void views(std::vector<const Image*>* planes, std::vector<const ErdModel*>* models) const;

    std::vector<Image> planes_;  // sized once: the models keep references into it
    std::vector<std::unique_ptr<ErdModel>> models_;
};

// ERDGPI's greedy model in colour: each channel's plane through its wedge values.
class ColourErdGreedyModel : public GreedyModel {
public:
    explicit ColourErdGreedyModel(ErdChannels& model) : model_(model) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override { return model_.channel(0).face_plane(cdt, f); }
    int channels() const override { return model_.channels(); }
    SpanPlane channel_face_plane(const Cdt& cdt, FaceInd f, int c) const override {
        return model_.channel(c).face_plane(cdt, f);
    }
    Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>*) override {
        model_.assign_vertex(cdt, v);  // as ErdGreedyModel: only v's wedges are new
        return Status::success();
    }

private:
    ErdChannels& model_;
};

}  // namespace erd
