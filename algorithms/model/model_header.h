// The header block of .model and .erd files ("erd-header 1", key lines, "end"; the grammar in
// model_io.h): its reader, for read_model.
#pragma once

#include <cstdint>

#include "algorithms/model/model.h"
#include "algorithms/model/model_tokens.h"
#include "kernel/status.h"

namespace erd {

// What the header block says beyond Model's fields: the lines of the "edges" key and of the
// per-edge kind key (0 when absent), and that key's count of edge lines; a real model's keys.
struct HeaderFacts {
    int edges_line = 0;
    int listed_line = 0;
    EdgeKind listed_kind = EdgeKind::hard;  // "hard-edges N" or "soft-edges N"
    std::uint64_t listed = 0;
    bool doubled = false;   // a basic model's coordinates are doubled ("doubled")
    bool range = false;     // "range" given: a real model
    bool holes = false;     // "holes W H" given
    bool type = false;
    bool seen[11] = {};     // the raster keys given (raster_key)
};

// Reads the block from "erd-header" to "end" into *m (its keys) and *facts (what Model does not hold).
Status read_header(model_text::Tokens& tk, Model* m, HeaderFacts* facts);

}  // namespace erd
