#include "cli/model_file.h"

#include "algorithms/model/model_io.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/report.h"

namespace erd::cli {

Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo) {
    if (warning) warning->clear();
    std::string text;
    const ModelFileKind kind = model_kind_from_name(path);
    Status st = read_file(path, &text, kMaxInputBytes, model_framer(kind == ModelFileKind::triangulation));
    if (!st) return st;
    st = kind == ModelFileKind::triangulation ? read_triangulation(text, out) : read_model(text, kind, out, topo);
    if (!st) return Status::error(st.code, escape_name(path) + ": " + st.message);
    return st;
}

}  // namespace erd::cli
