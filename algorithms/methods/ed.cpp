#include "algorithms/methods/ed.h"

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/methods/exact_count.h"
#include "algorithms/methods/scaffold.h"
#include "kernel/cdt.h"

namespace erd {

Status generate_ed(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);
    const int w = image.width, h = image.height;

    // Step 1: sigma = (d / d_max)^1 with d the MMSODD after 3rd-order binomial smoothing,
    // zero extension at the borders (thesis 3.2.1).
    StageTimer timer(result);
    if (options.progress.report_cancelled("sample selection", 0.0)) return Status::failure(kCancelled);
    // Colour: the channels' MMSODDs combined (ColourChoices::density).
    Grid<double> sigma = ed_density(colour_mmsodd(image, 3, options.colour.density, options.threads), 1.0, options.threads);
    timer.lap("mmsodd density");
    if (options.progress.report_cancelled("sample selection", 0.2)) return Status::failure(kCancelled);

    // Steps 2-3: error diffusion chooses the N - 4 non-corner points; the corners are forbidden
    // to it (their density still diffuses) and always added, so the total is N exactly whenever
    // the threshold search finds N - 4.
    Grid<std::uint8_t> corners(w, h, 0);
    corners(0, 0) = corners(w - 1, 0) = corners(w - 1, h - 1) = corners(0, h - 1) = 1;
    // Nodata (a real image's holes): never chosen, no density; the outline of the valid region is
    // a constraint of the mesh, and its points count towards N.
    Cdt cdt;
    st = cdt.reset(2 * (w - 1), 2 * (h - 1));
    if (!st) return st;
    if (!(st = insert_valid_outline(image, &cdt, &result->stats, std::size_t(n)))) return st;
    if (image.has_holes())
        for (std::size_t i = 0; i < corners.size(); ++i)
            if (!image.valid[i]) {
                corners.data[i] = 1;
                sigma.data[i] = 0.0;
            }
    DiffusionParams params;
    params.startup = Startup::none;
    params.forbidden = &corners;
    params.threads = options.threads;
    DiffusionResult chosen;
    const std::size_t have = cdt.vertex_count();
    const std::size_t want = std::size_t(n) - have;
    st = select_points(sigma, want, params, &chosen);
    if (!st) return st;
    std::size_t adjusted = 0;
    if (chosen.points.size() != want) adjusted = lower_threshold_to_exact(sigma, want, params, &chosen);
    result->stats.has_diffusion = true;
    result->stats.diffusion.rho = chosen.rho;
    result->stats.diffusion.passes = chosen.passes;
    result->stats.diffusion.adjusted = adjusted;
    timer.lap("error diffusion");
    if (options.progress.report_cancelled("triangulation", 0.0)) return Status::failure(kCancelled);

    // Step 4: the Delaunay triangulation of the corners and the chosen points.
    cdt.reserve(chosen.points.size() + have);
    std::vector<VertInd> ids;
    st = cdt.insert_points(chosen.points, &ids);
    if (!st) return st;
    timer.lap("triangulate");
    finish_basic_method(cdt, image, options, &timer, result);
    return Status::success();
}

}  // namespace erd
