// GPI: greedy point insertion on the basic model (thesis 3.2.2; Adams's variant of
// Garland-Heckbert: the face with the largest squared error gives up its worst point).
//
// Starts from the Delaunay triangulation of the four image corners and refines it with the shared
// loop of algorithms/greedy.h; the approximation on a face is the plane through the image samples
// at its three vertices.
#pragma once
#include "algorithms/methods/greedy.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/methods/options.h"
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

// Registry entry "gpi" (algorithms/methods/methods.h contract). Stops at N vertices, or earlier by
// --max-error / --psnr, or when no point has nonzero error (achieved < requested then).
Status generate_gpi(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
