// The two mesh models as the greedy loop (greedy.h) sees them: the basic model (GPI, and the
// max-error pass of ED on a real image) and the ERD model (ERDGPI, and that pass of ERDED). Shared
// by the methods and their scaffold, so no method includes another's header.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/model/erd_model.h"
#include "kernel/status.h"

namespace erd {

// The basic model as a GreedyModel: vertex value = image sample at the vertex (a pixel).
class BasicGreedyModel : public GreedyModel {
public:
    explicit BasicGreedyModel(const Image& image) : image_(image) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override;
    // The samples at the face's vertices: always integers.
    bool integer_values(const Cdt& cdt, FaceInd f, std::int64_t z[3]) const override;
    Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>* dirty) override;
    // Colour: channel c's plane through the face's vertex samples of that channel.
    int channels() const override { return image_.channels; }
    SpanPlane channel_face_plane(const Cdt& cdt, FaceInd f, int c) const override;

private:
    double sample_at(LatticePoint p) const;
    const Image& image_;
};

// The ERD model as seen by the greedy loop.
class ErdGreedyModel : public GreedyModel {
public:
    explicit ErdGreedyModel(ErdModel& model) : model_(model) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override { return model_.face_plane(cdt, f); }
    Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>* dirty) override;

private:
    ErdModel& model_;
};

}  // namespace erd
