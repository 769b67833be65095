#include "algorithms/methods/ed.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/methods/gpi.h"
#include "algorithms/methods/methods.h"
#include "algorithms/imaging/mmsodd.h"
#include "kernel/cdt.h"

namespace erd {

namespace {

// The count of a diffusion pass is not monotonic in rho, so sometimes no threshold gives exactly
// `want` points (typically the count jumps by 2 over it). Then lower rho in small steps until a
// pass gives at least `want` and drop the surplus points of lowest density (ties: the later one
// in scan order). Only a few points move; the rest is the pass as error diffusion made it.
// Leaves *chosen alone when no pass reaches `want` (e.g. too little nonzero density).
void make_exact(const Grid<double>& sigma, std::size_t want, const DiffusionParams& params, DiffusionResult* chosen) {
    std::vector<LatticePoint> pts;
    double rho = chosen->rho;
    bool found = chosen->points.size() > want;
    if (found) pts = chosen->points;
    for (int i = 0; !found && i < 16 && rho > 0.0; ++i) {
        double r = rho * (1.0 - 0.0005 * double(1 << i));
        if (!(r > 0.0)) break;
        ++chosen->passes;
        if (diffuse(sigma, r, params, &pts) >= want) {
            found = true;
            chosen->rho = r;
        }
    }
    if (!found) return;
    std::vector<std::size_t> order(pts.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto density = [&](std::size_t i) { return sigma(pts[i].x / 2, pts[i].y / 2); };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (density(a) != density(b)) return density(a) < density(b);
        return a > b;
    });
    std::vector<std::uint8_t> drop(pts.size(), 0);
    for (std::size_t k = 0; k < pts.size() - want; ++k) drop[order[k]] = 1;
    chosen->points.clear();
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!drop[i]) chosen->points.push_back(pts[i]);
    chosen->exact = true;
}

}  // namespace

Status generate_ed(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_generate(image, options, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);
    const int w = image.width, h = image.height;

    // Step 1: sigma = (d / d_max)^1 with d the MMSODD after 3rd-order binomial smoothing,
    // zero extension at the borders (thesis 3.2.1).
    auto t0 = std::chrono::steady_clock::now();
    Grid<double> sigma = ed_density(mmsodd(image, 3), 1.0);
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
    const std::size_t want = std::size_t(n - 4);
    st = select_points(sigma, want, params, &chosen);
    if (!st) return st;
    const std::size_t searched = chosen.points.size();
    if (chosen.points.size() != want) make_exact(sigma, want, params, &chosen);
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
    if (searched != want && chosen.points.size() == want) {
        std::snprintf(buf, sizeof buf, "no threshold gave %zu points exactly (nearest %zu): trimmed a larger pass",
                      want, searched);
        result->notes.push_back(buf);
    }
    return Status::success();
}

}  // namespace erd
