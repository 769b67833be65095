// Reading a model file (.model, .erd) from a path for the commands that draw or export one.
#pragma once
#include <string>

#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/status.h"

namespace erd::cli {

// Reads `path` ("-" = stdin) and parses it with algorithms/model/model_io.h; the kind comes from
// the name (.model / .erd), else from the content. A ".tri" name reads the -t triangulation instead
// (vertices, faces and constraints, no values: enough to draw, not to reconstruct or export).
// Messages start with the path. *warning (may be null) is cleared: reserved for non-fatal remarks.
// *topo (may be null) receives the model's adjacency for a .model or .erd (see read_model).
Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo = nullptr);

}  // namespace erd::cli
