// The registry of mesh-generation methods that `erd generate --method NAME` looks up: a static
// table {name, summary, function}. ED and GPI (basic model) live in algorithms/ed.h and gpi.h;
// ERDED and ERDGPI (ERD model) are added by one line each in methods.cpp.
#pragma once
#include <cstddef>
#include <string>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "kernel/status.h"

namespace erd {

// A method meshes `image` with N = target_points(options, W, H) points. It fills *result (model,
// requested, achieved, stages) and returns ok also when it could not reach N exactly
// (achieved != requested): the caller applies the thesis's exit mode (-x). Errors: Code::input
// for impossible requests (N < 4 or N > W*H), Code::runtime for internal failures.
using MethodFn = Status (*)(const Image& image, const GenerateOptions& options, GenerateResult* result);

struct Method {
    const char* name;     // "ed", "gpi", "erded", "erdgpi"
    const char* summary;  // one line for the method list
    MethodFn run;
};

// The table and its length.
const Method* methods(std::size_t* count);

// The method of this name, or nullptr.
const Method* find_method(const std::string& name);

// Checks the image and N: W, H >= 2 (else "too small", whatever N), then 4 <= N <= W*H (the four
// corners are always vertices).
Status check_target(std::int64_t n, int width, int height);

// The common start of every method: clears *result, computes N from the options, checks the image
// and N (check_target) and records N in result->requested.
Status begin_generate(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
