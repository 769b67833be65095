// The ERD model's refinement by removal (issue 45): ERDGPR is ERDGPI to K*N vertices, then greedy
// point removal (removal.h) to N by the ERD model's error, the constrained vertices kept (the kernel
// refuses them), every remaining wedge keeping its value; the mesh is then compacted and its
// wedge values assigned again as insertion assigns them, for the refit that ends every ERD method.
#pragma once
#include <cstddef>
#include <vector>

#include "algorithms/methods/erd_channels.h"
#include "algorithms/methods/removal.h"
#include "algorithms/model/erd_model.h"

namespace erd {

// ERDGPR's default K (docs/DECISIONS.md "Point removal").
constexpr double kErdgprOversample = 1.5;

// ERDGPR's ending unless the caller set any of it (GenerateOptions::ending_given): one more round
// of flips and of moves than ERDGPI's, the first moves two pixels long, more of them tried
// (docs/DECISIONS.md "Point removal").
struct ErdgprEnding {
    int flips = 3, moves = 3, move_step = 4;
    double move_min_gain = 0.02;
};
constexpr ErdgprEnding kErdgprEnding{};

// The gray ERD model's wedge values as removal sees them.
class ErdRemovalModel : public RemovalModel {
public:
    explicit ErdRemovalModel(ErdModel& model) : model_(model) {}
    double corner_value(const Cdt& cdt, EdgeInd e, int) const override { return model_.corner_value(cdt, e); }
    void corner_values(const Cdt& cdt, EdgeInd e, int, double* z) const override { z[0] = model_.corner_value(cdt, e); }
    void on_vertex_inserted(const Cdt& cdt, VertInd v) override { model_.assign_vertex(cdt, v); }
    void save_values(const Cdt& cdt, VertInd v, std::vector<double>* out) const override {
        out->assign(1, model_.corner_value(cdt, cdt.out_edge(v)));
    }
    void restore_values(const Cdt& cdt, VertInd v, const std::vector<double>& values) override {
        model_.set_entry_value(model_.corner_entry(cdt, cdt.out_edge(v)), values[0]);
    }

private:
    ErdModel& model_;
};

// The same for a colour ERD model: channel c's wedge values.
class ErdChannelsRemovalModel : public RemovalModel {
public:
    explicit ErdChannelsRemovalModel(ErdChannels& model) : model_(model) {}
    double corner_value(const Cdt& cdt, EdgeInd e, int c) const override { return model_.channel(c).corner_value(cdt, e); }
    // The channels share their wedges (erd_channels.h): corner e's entry is looked up once.
    void corner_values(const Cdt& cdt, EdgeInd e, int channels, double* z) const override {
        const std::uint32_t i = model_.channel(0).corner_lookup(cdt, e);
        const VertInd v = cdt.org(e);
        for (int c = 0; c < channels; ++c) z[c] = model_.channel(c).looked_up_value(v, i);
    }
    void on_vertex_inserted(const Cdt& cdt, VertInd v) override { model_.assign_vertex(cdt, v); }
    void save_values(const Cdt& cdt, VertInd v, std::vector<double>* out) const override {
        out->clear();
        for (int c = 0; c < model_.channels(); ++c) out->push_back(model_.channel(c).corner_value(cdt, cdt.out_edge(v)));
    }
    void restore_values(const Cdt& cdt, VertInd v, const std::vector<double>& values) override {
        for (int c = 0; c < model_.channels(); ++c) {
            ErdModel& m = model_.channel(c);
            m.set_entry_value(m.corner_entry(cdt, cdt.out_edge(v)), values[std::size_t(c)]);
        }
    }

private:
    ErdChannels& model_;
};

// Removes vertices of *cdt by least significance under `model` until n remain (real-valued errors,
// lazy as `lazy` says), then replaces *cdt by its compact copy (compact_cdt). The caller assigns
// the wedge values of the compact mesh. Adds to *stats. systems: PointRemover's (emptied once read).
Status erd_remove_to(Cdt* cdt, const Image& image, RemovalModel& model, std::size_t n, bool lazy,
                     const ProgressHook& progress, RemovalRunStats* stats, MeshSystems* systems = nullptr);

}  // namespace erd
