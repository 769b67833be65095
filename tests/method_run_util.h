// One method run at a density with a kind of edge, and the PSNR of a model's own reconstruction:
// for the tests of edge kinds (hard edges, issue 15; edges of two kinds, issue 44).
#pragma once
#include <catch2/catch.hpp>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd_test {

// The registry's method `method` on im at `density` percent with --edges `edges`.
inline erd::GenerateResult run_method(const char* method, const erd::Image& im, double density,
                                      erd::EdgeChoice edges = erd::EdgeChoice::automatic) {
    erd::GenerateOptions o;
    o.density = density;
    o.density_given = true;
    o.edges = edges;
    erd::GenerateResult r;
    const erd::MethodInfo* m = erd::find_method(method);
    REQUIRE(m != nullptr);
    REQUIRE(m->run(im, o, &r).ok());
    return r;
}

// PSNR of m's own reconstruction (reconstruct(m, supersampled(m))) against im.
inline double own_psnr(const erd::Image& im, const erd::Model& m) {
    erd::Image rec;
    REQUIRE(erd::reconstruct(m, erd::supersampled(m), &rec).ok());
    double db = 0;
    REQUIRE(erd::psnr(im, rec, &db).ok());
    return db;
}

}  // namespace erd_test
