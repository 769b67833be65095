#include "algorithms/methods/greedy_models.h"

#include "algorithms/imaging/real_image.h"

namespace erd {

double BasicGreedyModel::sample_at(LatticePoint p) const {
    if (image_.real()) return lattice_value(image_, p);
    return double(image_.at(p.x / 2, p.y / 2));
}

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
        z[i] = image_.real() ? lattice_value(image_, p[i], c) : double(image_.at(p[i].x / 2, p[i].y / 2, c));
    }
    SpanPlane plane;
    plane.set(p[0], z[0], p[1], z[1], p[2], z[2]);
    return plane;
}

bool BasicGreedyModel::integer_values(const Cdt& cdt, FaceInd f, std::int64_t z[3]) const {
    if (image_.real()) return false;
    for (int i = 0; i < 3; ++i) {
        const LatticePoint p = cdt.point(cdt.face_vertex(f, i));
        z[i] = image_.at(p.x / 2, p.y / 2);
    }
    return true;
}

Status BasicGreedyModel::on_vertex_inserted(const Cdt&, VertInd, std::vector<FaceInd>*) {
    return Status::success();  // values are read from the image in face_plane
}

Status ErdGreedyModel::on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>*) {
    // Every face around v is new, and no other vertex's wedges changed (a split keeps the wedge
    // ids of the edge's end points), so nothing else is dirty.
    model_.assign_vertex(cdt, v);
    return Status::success();
}

}  // namespace erd
