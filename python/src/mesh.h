// erd.Mesh: a model (algorithms/model/model.h) with the method that made it and its statistics,
// seen from Python as numpy arrays; and the Status -> exception mapping every call shares.
#pragma once
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "algorithms/methods/result.h"
#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd::py {

struct Mesh {
    Model model;
    std::string method;              // "" for a mesh read from a file
    std::size_t requested = 0;       // N asked for (the vertex count for a file)
    std::size_t achieved = 0;
    RunStats run;                    // what generate's stages measured (empty for a file)
    std::vector<StageTime> stages;
    pybind11::object stats;          // the --stats fields, made on first use (None until then)
};

// Raises the exception for a failed Status: ValueError for bad input (Code::input and
// Code::density), RuntimeError for the library's internal failures; `os_error` makes every
// failure an OSError (file access). The message is the library's.
[[noreturn]] void raise_status(const Status& st, bool os_error = false);

// Defines erd.Mesh in module m.
void bind_mesh(pybind11::module_& m);

// The --stats fields of a mesh, in their order (a file's mesh: the counts; method, parameters,
// stop and stages None or empty), without the erd program's own (total time, memory, PSNR).
pybind11::dict mesh_stats(const Mesh& mesh);

}  // namespace erd::py
