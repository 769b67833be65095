#include "algorithms/ed.h"

#include <chrono>
#include <cstdio>

#include "algorithms/error_diffusion.h"
#include "algorithms/gpi.h"
#include "algorithms/methods.h"
#include "algorithms/mmsodd.h"
#include "kernel/cdt.h"

namespace erd {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Status generate_ed(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    *result = GenerateResult();
    Status st = check_meshable(image);
    if (!st) return st;
    std::int64_t n = target_points(options, image.width, image.height);
    st = check_target(n, image.width, image.height);
    if (!st) return st;
    result->requested = std::size_t(n);
    const int w = image.width, h = image.height;

    // Step 1: sigma = (d / d_max)^1 with d the MMSODD after 3rd-order binomial smoothing,
    // zero extension at the borders (thesis 3.2.1).
    auto t0 = std::chrono::steady_clock::now();
    Grid<double> sigma = ed_density(mmsodd(to_grid(image), 3, Border::zero), 1.0);
    result->stages.push_back({"mmsodd density", seconds_since(t0)});

    // Steps 2-3: error diffusion chooses the N - 4 non-corner points; the corners are forbidden
    // to it (their density still diffuses) and always added, so the total is N exactly whenever
    // the threshold search finds N - 4.
    t0 = std::chrono::steady_clock::now();
    Grid<std::uint8_t> corners(w, h, 0);
    corners(0, 0) = corners(w - 1, 0) = corners(w - 1, h - 1) = corners(0, h - 1) = 1;
    DiffusionParams params;
    params.startup = Startup::none;
    params.forbidden = &corners;
    DiffusionResult chosen;
    st = select_points(sigma, std::size_t(n - 4), params, &chosen);
    if (!st) return st;
    result->stages.push_back({"error diffusion", seconds_since(t0)});

    // Step 4: the Delaunay triangulation of the corners and the chosen points.
    t0 = std::chrono::steady_clock::now();
    Cdt cdt;
    st = cdt.reset(2 * (w - 1), 2 * (h - 1));
    if (!st) return st;
    cdt.reserve(chosen.points.size() + 4);
    std::vector<VertInd> ids;
    st = cdt.insert_points(chosen.points, &ids);
    if (!st) return st;
    result->stages.push_back({"triangulate", seconds_since(t0)});

    t0 = std::chrono::steady_clock::now();
    result->model = basic_model(cdt, image);
    result->achieved = result->model.size();
    result->stages.push_back({"model", seconds_since(t0)});
    char buf[96];
    std::snprintf(buf, sizeof buf, "threshold rho %.6g after %d diffusion passes", chosen.rho, chosen.passes);
    result->notes.push_back(buf);
    return Status::success();
}

}  // namespace erd
