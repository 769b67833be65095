// Reading a model file (.model, .erd) from a path for the commands that draw or export one.
#pragma once
#include <string>

#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/status.h"

namespace erd::cli {

// Reads `path` ("-" = stdin) and parses it with algorithms/model/model_io.h. The content decides the
// kind: "erd-triangulation" first is the -t triangulation (vertices, faces and constraints, no
// values: enough to draw, not to reconstruct or export); a model that goes on after its faces is
// an .erd, else a .model. The name (.model, .erd, .tri) only breaks a tie: content that reads as
// nothing is reported as the named kind reads it. A name that disagrees with readable content
// sets *warning (may be null; cleared first). Messages start with the path.
// *topo (may be null) receives the model's adjacency for a .model or .erd (see read_model).
Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo = nullptr);

}  // namespace erd::cli
