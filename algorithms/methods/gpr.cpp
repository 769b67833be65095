#include "algorithms/methods/gpr.h"

#include <algorithm>
#include <vector>

#include "algorithms/methods/ed_select.h"
#include "algorithms/methods/removal.h"
#include "algorithms/methods/scaffold.h"

namespace erd {

namespace {

// Removal from the points in *cdt to N, then the compact mesh and the basic model.
Status remove_to_n(Cdt* cdt, const Image& image, const GenerateOptions& options, StageTimer* timer,
                   GenerateResult* result) {
    SampleRemovalModel model(image);
    PointRemover remover(*cdt, image, model, options.round_values);
    remover.lazy = options.removal_lazy;
    remover.start();
    Status st = remover.run_to(result->requested, options.progress);
    if (!st) return st;
    result->stats.has_removal = true;
    result->stats.removal.start = remover.stats().removed + cdt->live_vertex_count();
    result->stats.removal.removed = remover.stats().removed;
    result->stats.removal.evaluations = remover.stats().evaluations;
    timer->lap("point removal");
    Cdt compact;
    st = compact_cdt(*cdt, &compact);
    if (!st) return st;
    *cdt = std::move(compact);
    return finish_basic_method(*cdt, image, options, timer, result);
}

// Every pixel, as lattice points in row order.
std::vector<LatticePoint> all_pixels(const Image& image) {
    std::vector<LatticePoint> all;
    all.reserve(image.pixels());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) all.push_back(LatticePoint{2 * x, 2 * y});
    return all;
}

// The start points triangulated (a stage named `lap`, when given), then removal to N.
Status remove_from(const std::vector<LatticePoint>& pts, const char* lap, const Image& image,
                   const GenerateOptions& options, StageTimer* timer, GenerateResult* result) {
    Cdt cdt;
    Status st = cdt.reset(2 * (image.width - 1), 2 * (image.height - 1));
    if (!st) return st;
    cdt.reserve(pts.size() + 4);
    std::vector<VertInd> ids;
    if (!(st = cdt.insert_points(pts, &ids, false))) return st;
    if (lap) timer->lap(lap);
    return remove_to_n(&cdt, image, options, timer, result);
}

}  // namespace

Status generate_gpr(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    if (!(st = removal_accepts(image, "gpr"))) return st;
    StageTimer timer(result);
    return remove_from(all_pixels(image), "triangulate all pixels", image, options, &timer, result);
}

Status generate_gprfs(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    if (!(st = removal_accepts(image, "gprfs"))) return st;
    StageTimer timer(result);
    const double k = options.oversample > 0 ? options.oversample : kGprfsOversample;
    const std::size_t start = std::min(image.pixels(), std::size_t(double(result->requested) * k + 0.5));
    std::vector<LatticePoint> pts;
    if (start >= image.pixels()) {
        pts = all_pixels(image);
    } else {
        DiffusionResult chosen;
        std::size_t adjusted = 0;
        st = ed_choose(ed_sigma(image, options), start - 4, options, ed_corners(image.width, image.height), &chosen,
                       &adjusted);
        if (!st) return st;
        pts = std::move(chosen.points);
    }
    timer.lap("error diffusion");
    return remove_from(pts, nullptr, image, options, &timer, result);
}

Status generate_id(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    if (!(st = removal_accepts(image, "id"))) return st;
    StageTimer timer(result);
    const std::size_t n = result->requested;
    Cdt cdt;
    st = cdt.reset(2 * (image.width - 1), 2 * (image.height - 1));
    if (!st) return st;
    SampleRemovalModel model(image);
    PointRemover r(cdt, image, model, options.round_values);
    r.lazy = options.removal_lazy;
    r.track_faces();
    const auto grow = [&](std::size_t to) -> Status {
        LatticePoint p;
        VertInd v;
        while (cdt.live_vertex_count() < to && r.worst_pixel(&p)) {
            Status s = r.insert(p, &v);
            if (!s) return s;
            if (options.progress && options.progress.report_cancelled("incremental/decremental", 0.0))
                return Status::failure(kCancelled);
        }
        return Status::success();
    };
    if (!(st = grow(n))) return st;
    timer.lap("greedy insertion");
    r.start();
    const std::size_t extra = std::max<std::size_t>(1, std::size_t(double(n) * options.id_share + 0.5));
    result->stats.has_removal = true;
    for (int c = 0; c < options.id_cycles; ++c) {
        if (!(st = grow(std::min(image.pixels(), n + extra)))) return st;
        if (!(st = r.run_to(n, options.progress))) return st;
    }
    result->stats.removal.start = n + extra;
    result->stats.removal.removed = r.stats().removed;
    result->stats.removal.evaluations = r.stats().evaluations;
    timer.lap("incremental/decremental cycles");
    Cdt compact;
    if (!(st = compact_cdt(cdt, &compact))) return st;
    cdt = std::move(compact);
    return finish_basic_method(cdt, image, options, &timer, result);
}

}  // namespace erd
