#include "algorithms/methods/gpi.h"

#include "algorithms/methods/scaffold.h"

namespace erd {

double BasicGreedyModel::sample_at(LatticePoint p) const { return double(image_.at(p.x / 2, p.y / 2)); }

SpanPlane BasicGreedyModel::face_plane(const Cdt& cdt, FaceInd f) const {
    LatticePoint p0 = cdt.point(cdt.face_vertex(f, 0));
    LatticePoint p1 = cdt.point(cdt.face_vertex(f, 1));
    LatticePoint p2 = cdt.point(cdt.face_vertex(f, 2));
    SpanPlane plane;
    plane.set(p0, sample_at(p0), p1, sample_at(p1), p2, sample_at(p2));
    return plane;
}

SpanPlane BasicGreedyModel::channel_face_plane(const Cdt& cdt, FaceInd f, int c) const {
    LatticePoint p[3];
    double z[3];
    for (int i = 0; i < 3; ++i) {
        p[i] = cdt.point(cdt.face_vertex(f, i));
        z[i] = double(image_.at(p[i].x / 2, p[i].y / 2, c));
    }
    SpanPlane plane;
    plane.set(p[0], z[0], p[1], z[1], p[2], z[2]);
    return plane;
}

bool BasicGreedyModel::integer_values(const Cdt& cdt, FaceInd f, std::int64_t z[3]) const {
    for (int i = 0; i < 3; ++i) {
        const LatticePoint p = cdt.point(cdt.face_vertex(f, i));
        z[i] = image_.at(p.x / 2, p.y / 2);
    }
    return true;
}

Status BasicGreedyModel::on_vertex_inserted(const Cdt&, VertInd, std::vector<FaceInd>*) {
    return Status::success();  // values are read from the image in face_plane
}

Status generate_gpi(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);

    StageTimer timer(result);
    Cdt cdt;
    st = cdt.reset(2 * (image.width - 1), 2 * (image.height - 1));
    if (!st) return st;
    cdt.reserve(std::size_t(n));
    timer.lap("triangulate corners");

    BasicGreedyModel model(image);
    const GreedyOptions go = greedy_options(options, std::size_t(n));
    result->stats.has_greedy = true;
    st = greedy_refine(cdt, image, model, go, &result->stats.greedy);
    if (!st) return st;
    timer.lap("greedy insertion");

    return finish_basic_method(cdt, image, options, &timer, result);
}

}  // namespace erd
