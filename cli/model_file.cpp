#include "cli/model_file.h"

#include "algorithms/model_io.h"
#include "cli/fileio.h"

namespace erd::cli {

Status load_model_file(const std::string& path, Model* out, std::string* warning) {
    if (warning) warning->clear();
    std::string text;
    Status st = read_file(path, &text);
    if (!st) return st;
    st = read_model(text, model_kind_from_name(path), out);
    if (!st) return Status::error(st.code, path + ": " + st.message);
    return st;
}

}  // namespace erd::cli
