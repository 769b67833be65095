#include "cli/model_file.h"

#include <cstdint>

#include "algorithms/codec/erdz.h"
#include "algorithms/model/model_io.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/report.h"

namespace erd::cli {

namespace {

const char* extension_of(ModelFileKind k) {
    switch (k) {
        case ModelFileKind::basic: return ".model";
        case ModelFileKind::erd: return ".erd";
        case ModelFileKind::triangulation: return ".tri";
        case ModelFileKind::unknown: break;
    }
    return "";
}

// What the text is, from its first word and, for a model, from whether it goes on after its
// faces (read_model with kind unknown decides that itself).
bool is_triangulation(const std::string& text) {
    std::size_t i = text.find_first_not_of(" \t\r\n");
    return i != std::string::npos && text.compare(i, 17, "erd-triangulation") == 0;
}

}  // namespace

Status load_model_file(const std::string& path, Model* out, std::string* warning, ModelTopology* topo, ErdzInfo* info,
                       ModelFileFacts* file) {
    std::string text;
    std::uint64_t unread = 0;
    const bool tri = model_kind_from_name(path) == ModelFileKind::triangulation;
    if (Status st = read_file(path, &text, kMaxInputBytes, model_framer(tri), nullptr, &unread); !st) return st;
    return parse_model_bytes(path, text, unread, out, warning, topo, info, file);
}

Status parse_model_bytes(const std::string& path, const std::string& text, std::uint64_t unread, Model* out,
                         std::string* warning, ModelTopology* topo, ErdzInfo* info, ModelFileFacts* file) {
    if (warning) warning->clear();
    const ModelFileKind kind = model_kind_from_name(path);
    Status st;
    // An .erdz file read as far as its header says, and a long tail after it never read: the
    // decoder's own refusal of bytes after the last section (a text file stops at a NUL, which
    // its reader refuses itself).
    if (unread && is_erdz(text))
        return Status::bad_input(escape_name(path) + ": " + std::to_string(unread) + " bytes after the last section");
    if (file) *file = ModelFileFacts{ModelFileKind::unknown, false, text.size()};
    if (is_erdz(text)) {
        if (!(st = decode_erdz_topology(text, out, topo, info))) return Status::error(st.code, escape_name(path) + ": " + st.message);
        if (file) file->kind = out->kind == ModelKind::erd ? ModelFileKind::erd : ModelFileKind::basic;
        if (file) file->erdz = true;
        return st;
    }
    if (info) *info = ErdzInfo();
    const ModelFileKind named = kind;
    ModelFileKind found = ModelFileKind::unknown;
    if (is_triangulation(text)) {
        found = ModelFileKind::triangulation;
        st = read_triangulation(text, out);
    } else {
        st = read_model(text, ModelFileKind::unknown, out, topo);
        if (st) found = out->kind == ModelKind::erd ? ModelFileKind::erd : ModelFileKind::basic;
    }
    // Content that cannot be read is reported as the name's kind would read it: the name says
    // what the file was meant to be (a cut-off .erd reads as a broken .model otherwise), and the
    // messages stay those of the reader the user asked for. Where the content reads, the same
    // reader agrees with it, so the name only ever breaks this tie.
    if (!st && named != ModelFileKind::unknown) {
        Model again;
        st = named == ModelFileKind::triangulation ? read_triangulation(text, &again) : read_model(text, named, &again);
    }
    if (!st) return Status::error(st.code, escape_name(path) + ": " + st.message);
    if (file) file->kind = found;
    if (warning && named != ModelFileKind::unknown && named != found)
        *warning = escape_name(path) + ": the content is a " + extension_of(found) + " file, not a " + extension_of(named) +
                   " as the name says; read as " + extension_of(found);
    return st;
}

Status load_input_model(const std::string& out, const std::vector<std::string>& inputs, const Reporter& rep, Model* m,
                        ModelTopology* topo) {
    if (Status st = refuse_overwrite(out, inputs); !st) return st;
    std::string warning;
    if (Status st = load_model_file(inputs[0], m, &warning, topo); !st) return st;
    rep.warn(warning);
    return Status::success();
}

bool erdz_name(const std::string& path) { return path.size() > 5 && path.compare(path.size() - 5, 5, ".erdz") == 0; }

Status encode_model_file(const std::string& path, const Model& m, const ErdzOptions& options, std::string* bytes,
                         ErdzInfo* info) {
    if (!erdz_name(path)) return write_model(m, bytes);
    Status st = encode_erdz(m, options, bytes, info);
    if (!st) return Status::error(st.code, escape_name(path) + ": " + st.message);
    return st;
}

}  // namespace erd::cli
