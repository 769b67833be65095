#include "algorithms/methods/methods.h"

#include <cmath>

#include "algorithms/methods/ed.h"
#include "algorithms/methods/gpi.h"
#include "algorithms/methods/erded.h"
#include "algorithms/methods/erdgpi.h"

namespace erd {

namespace {

const Method kMethods[] = {
    {"ed", "error diffusion on the MMSODD (thesis 3.2.1, ywb), basic model", generate_ed},
    {"gpi", "greedy point insertion (thesis 3.2.2, gpi), basic model", generate_gpi},
    {"erded", "ERD model, error-diffusion refinement (thesis 3.4.2, erd_ed)", generate_erded},
    {"erdgpi", "ERD model, greedy point insertion (thesis 3.4.3, erd_gpi)", generate_erdgpi},
};

}  // namespace

const Method* methods(std::size_t* count) {
    *count = sizeof kMethods / sizeof kMethods[0];
    return kMethods;
}

const Method* find_method(const std::string& name) {
    for (const Method& m : kMethods)
        if (name == m.name) return &m;
    return nullptr;
}

std::int64_t target_points(const GenerateOptions& o, int width, int height) {
    if (o.points > 0 && !o.density_given) return o.points;
    // D is a percentage; round half away from zero (7864 for 3% of 512 x 512 = 7864.32).
    return std::int64_t(std::llround(o.density * double(width) * double(height) / 100.0));
}

Status check_target(std::int64_t n, int width, int height) {
    std::int64_t pixels = std::int64_t(width) * std::int64_t(height);
    // Size first, so a 1x1 or 1xN image always gets the same "too small" line whatever N is.
    if (width < 2 || height < 2)
        return Status::bad_input("image is " + std::to_string(width) + "x" + std::to_string(height) +
                                 "; meshing needs at least 2x2 pixels");
    if (n < 4)
        return Status::bad_input("target of " + std::to_string(n) +
                                 " points is below 4 (the four corners are always vertices)");
    if (n > pixels)
        return Status::bad_input("target of " + std::to_string(n) + " points exceeds the " +
                                 std::to_string(pixels) + " pixels of the image");
    return Status::success();
}

Status begin_generate(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    *result = GenerateResult();
    const std::int64_t n = target_points(options, image.width, image.height);
    Status st = check_target(n, image.width, image.height);
    if (!st) return st;
    result->requested = std::size_t(n);
    return Status::success();
}

}  // namespace erd
