#include "cli/model_file.h"

#include "algorithms/model/model_io.h"
#include "cli/fileio.h"

namespace erd::cli {

Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo) {
    if (warning) warning->clear();
    std::string text;
    Status st = read_file(path, &text);
    if (!st) return st;
    ModelFileKind kind = model_kind_from_name(path);
    st = kind == ModelFileKind::triangulation ? read_triangulation(text, out) : read_model(text, kind, out, topo);
    if (!st) return Status::error(st.code, path + ": " + st.message);
    return st;
}

}  // namespace erd::cli
