#include "algorithms/methods/gpi.h"

#include "algorithms/methods/scaffold.h"

namespace erd {

Status generate_gpi(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);

    StageTimer timer(result);
    Cdt cdt;
    st = cdt.reset(2 * (image.width - 1), 2 * (image.height - 1));
    if (!st) return st;
    cdt.reserve(std::size_t(n));
    if (!(st = insert_valid_outline(image, &cdt, &result->stats, std::size_t(n)))) return st;
    if (!(st = insert_border_points(options, &cdt))) return st;
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
