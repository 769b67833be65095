// erd.generate's keyword options: the `erd generate` flags by their long names (dashes as
// underscores), checked with the same ranges, into erd::api::Options. Unknown names raise
// TypeError naming them (with a close match); wrong types TypeError; values out of range
// ValueError with the CLI's wording.
#pragma once
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "api/erd.h"

namespace erd::py {

struct GenerateArgs {
    api::Options options;
    std::optional<long long> maxval;  // maxval=: the image's maxval (default from its dtype)
    std::optional<double> nodata;     // nodata=: the value of the pixels without data
};

// density: percent (used unless points is given); points: None or a vertex count.
GenerateArgs generate_args(double density, pybind11::handle points, const pybind11::kwargs& kwargs);

// The option names generate() takes besides image, method, density and points, sorted.
std::string option_names();

}  // namespace erd::py
