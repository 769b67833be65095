#include "algorithms/methods/ed_select.h"

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/methods/exact_count.h"

namespace erd {

Grid<double> ed_sigma(const Image& image, const GenerateOptions& options) {
    return ed_density(colour_mmsodd(image, 3, options.colour.density, options.threads), 1.0, options.threads);
}

Grid<std::uint8_t> ed_corners(int w, int h) {
    Grid<std::uint8_t> corners(w, h, 0);
    corners(0, 0) = corners(w - 1, 0) = corners(w - 1, h - 1) = corners(0, h - 1) = 1;
    return corners;
}

Status ed_choose(const Grid<double>& sigma, std::size_t count, const GenerateOptions& options,
                 const Grid<std::uint8_t>& forbidden, DiffusionResult* chosen, std::size_t* adjusted) {
    DiffusionParams params;
    params.startup = Startup::none;
    params.forbidden = &forbidden;
    params.threads = options.threads;
    Status st = select_points(sigma, count, params, chosen);
    if (!st) return st;
    *adjusted = 0;
    if (chosen->points.size() != count) *adjusted = lower_threshold_to_exact(sigma, count, params, chosen);
    return Status::success();
}

}  // namespace erd
