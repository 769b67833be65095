#include "algorithms/methods/ed.h"

#include "algorithms/methods/ed_select.h"
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
    Grid<double> sigma = ed_sigma(image, options);
    timer.lap("mmsodd density");
    if (options.progress.report_cancelled("sample selection", 0.2)) return Status::failure(kCancelled);

    // Steps 2-3: error diffusion chooses the N - 4 non-corner points; the corners are forbidden
    // to it (their density still diffuses) and always added, so the total is N exactly whenever
    // the threshold search finds N - 4.
    Grid<std::uint8_t> corners = ed_corners(w, h);
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
    DiffusionResult chosen;
    const std::size_t have = cdt.vertex_count();
    std::size_t adjusted = 0;
    st = ed_choose(sigma, std::size_t(n) - have, options, corners, &chosen, &adjusted);
    if (!st) return st;
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
    return finish_basic_method(cdt, image, options, &timer, result);
}

}  // namespace erd
