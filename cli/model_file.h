// Reading a model file (.model, .erd, .erdz) from a path for the commands that draw or export one,
// and the bytes of a model for the name it is written to.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "cli/report.h"
#include "kernel/status.h"

namespace erd::cli {

// Reads `path` ("-" = stdin) and parses it with algorithms/model/model_io.h. The content decides the
// kind: "erd-triangulation" first is the -t triangulation (vertices, faces and constraints, no
// values: enough to draw, not to reconstruct or export); a model that goes on after its faces is
// an .erd, else a .model. The name (.model, .erd, .tri) only breaks a tie: content that reads as
// nothing is reported as the named kind reads it. A name that disagrees with readable content
// sets *warning (may be null; cleared first). Messages start with the path.
// *topo (may be null) receives the model's adjacency for a .model or .erd (see read_model).
// A file that starts with the .erdz magic is decoded as one (algorithms/codec/erdz.h) whatever its
// name; *info (may be null) then receives its section sizes (zeros for a text model).
// *file (may be null) receives what the file turned out to be and its size in bytes.
struct ModelFileFacts {
    ModelFileKind kind = ModelFileKind::unknown;  // basic, erd or triangulation (an .erdz: basic or erd)
    bool erdz = false;
    std::size_t bytes = 0;  // as read
};
Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo = nullptr,
                       ErdzInfo* info = nullptr, ModelFileFacts* file = nullptr);

// load_model_file's second half: `text`, read from `path` with `unread` bytes left after what its
// framing took (0 when none or unknown), parsed as above.
Status parse_model_bytes(const std::string& path, const std::string& text, std::uint64_t unread, Model* out,
                         std::string* warning, ModelTopology* topo = nullptr, ErdzInfo* info = nullptr,
                         ModelFileFacts* file = nullptr);

// The model a subcommand draws, exports or reconstructs into `out`: refuses an `out` that is one
// of `inputs` (refuse_overwrite, cli/fileio.h; the model's path first), reads inputs[0] with
// load_model_file and prints its warning through rep.
Status load_input_model(const std::string& out, const std::vector<std::string>& inputs, const Reporter& rep, Model* m,
                        ModelTopology* topo = nullptr);

// True when the name ends with ".erdz".
bool erdz_name(const std::string& path);

// The bytes of m as the name asks: .erdz encoded with `options` (*info, may be null, gets its
// sizes), anything else the text model (algorithms/model/model_io.h write_model).
Status encode_model_file(const std::string& path, const Model& m, const ErdzOptions& options, std::string* bytes,
                         ErdzInfo* info = nullptr);

}  // namespace erd::cli
