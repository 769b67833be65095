// Greedy refinement for the tests of the greedy loop (test_ed_gpi.cpp, test_greedy.cpp): a run
// from the four corners, as GPI starts.
#pragma once
#include <catch2/catch.hpp>

#include <cstddef>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/greedy.h"
#include "kernel/cdt.h"

namespace erd_test {

// Refines a fresh triangulation of im's domain (its four corners) with `model` until a rule of
// `go` stops it: the loop's statistics; the triangulation in *cdt.
inline erd::GreedyStats refine_from_corners(const erd::Image& im, erd::GreedyModel& model, const erd::GreedyOptions& go,
                                            erd::Cdt* cdt) {
    REQUIRE(cdt->reset(2 * (im.width - 1), 2 * (im.height - 1)).ok());
    erd::GreedyStats gs;
    REQUIRE(erd::greedy_refine(*cdt, im, model, go, &gs).ok());
    return gs;
}

// The same to `target` vertices, the other rules off, values rounded unless `rounded` is false.
inline erd::GreedyStats refine_to(const erd::Image& im, erd::GreedyModel& model, std::size_t target, erd::Cdt* cdt,
                                  bool rounded = true) {
    erd::GreedyOptions go;
    go.target_vertices = target;
    go.round_values = rounded;
    return refine_from_corners(im, model, go, cdt);
}

}  // namespace erd_test
