#include "algorithms/methods/gpi.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "algorithms/methods/methods.h"

namespace erd {

namespace {

std::string format_real(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

}  // namespace

double BasicGreedyModel::sample_at(LatticePoint p) const { return double(image_.at(p.x / 2, p.y / 2)); }

SpanPlane BasicGreedyModel::face_plane(const Cdt& cdt, FaceInd f) const {
    LatticePoint p0 = cdt.point(cdt.face_vertex(f, 0));
    LatticePoint p1 = cdt.point(cdt.face_vertex(f, 1));
    LatticePoint p2 = cdt.point(cdt.face_vertex(f, 2));
    SpanPlane plane;
    plane.set(p0, sample_at(p0), p1, sample_at(p1), p2, sample_at(p2));
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

Model basic_model(const Cdt& cdt, const Image& image) {
    Model m;
    m.kind = ModelKind::basic;
    m.width = image.width;
    m.height = image.height;
    m.maxval = image.maxval;
    m.vertices = cdt.points();
    m.values.reserve(m.vertices.size());
    for (LatticePoint p : m.vertices) m.values.push_back(double(image.at(p.x / 2, p.y / 2)));
    std::vector<std::array<VertInd, 3>> faces;
    cdt.export_faces(&faces);
    m.faces.assign(faces.begin(), faces.end());
    return m;
}

Status generate_gpi(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_generate(image, options, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);

    auto t0 = std::chrono::steady_clock::now();
    Cdt cdt;
    st = cdt.reset(2 * (image.width - 1), 2 * (image.height - 1));
    if (!st) return st;
    cdt.reserve(std::size_t(n));
    result->stages.push_back({"triangulate corners", seconds_since(t0)});

    t0 = std::chrono::steady_clock::now();
    BasicGreedyModel model(image);
    GreedyOptions go;
    go.target_vertices = std::size_t(n);
    go.max_error = options.max_error;
    go.psnr = options.psnr;
    go.max_triangles = options.triangles > 0 ? std::size_t(options.triangles) : 0;
    go.round_values = options.round_values;
    go.progress = options.progress;
    GreedyStats gs;
    st = greedy_refine(cdt, image, model, go, &gs);
    if (!st) return st;
    result->stages.push_back({"greedy insertion", seconds_since(t0)});

    t0 = std::chrono::steady_clock::now();
    result->model = basic_model(cdt, image);
    result->achieved = result->model.size();
    result->stages.push_back({"model", seconds_since(t0)});
    result->notes.push_back(std::string("stop: ") + to_string(gs.stop));
    result->notes.push_back("insertions: " + std::to_string(gs.insertions));
    result->notes.push_back("max abs error: " + format_real("%.4g", gs.max_error));
    result->notes.push_back("psnr (point evaluation): " + format_real("%.4f", gs.psnr));
    return Status::success();
}

}  // namespace erd
