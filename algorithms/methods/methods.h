// The registry of mesh-generation methods: one static table that `erd generate --method NAME`,
// its help, the thesis's program names (cli/thesis_alias.cpp) and the public API (api/erd.h) all
// read. Adding a method is one row in methods.cpp; the shared steps are in scaffold.h.
#pragma once
#include <cstddef>
#include <string>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

// A method meshes `image` with N = target_points(options, W, H) points. It fills *result (model,
// requested, achieved, stages, the typed statistics) and returns ok also when it could not reach
// N exactly (achieved != requested): the caller applies the exact-count policy
// (check_exact_count). Errors: Code::input for impossible requests (N < 4 or N > W*H),
// Code::runtime for internal failures.
using MethodFn = Status (*)(const Image& image, const GenerateOptions& options, GenerateResult* result);

struct MethodInfo {
    const char* name;            // "ed", "gpi", "erded", "erdgpi"
    const char* summary;         // one line for the method list
    ModelKind model;             // what it makes: .model (basic) or .erd
    const char* thesis_program;  // the thesis's program (Appendix A.5): ywb, gpi, erd_ed, erd_gpi
    const char* thesis_flags;    // that program's option letters, each taking a value
    // Upper estimate of the peak heap bytes of one run: per pixel and per vertex of the target
    // (api/erd.h memory_estimate; docs/DECISIONS.md "Memory" has the measurements).
    std::size_t bytes_per_pixel;
    std::size_t bytes_per_point;
    MethodFn run;
};

// The table and its length.
const MethodInfo* methods(std::size_t* count);

// The method of this name, or nullptr.
const MethodInfo* find_method(const std::string& name);

// The names in table order, comma separated ("ed, gpi, erded, erdgpi").
std::string method_names();

}  // namespace erd
