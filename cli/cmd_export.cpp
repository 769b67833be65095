// erd export MODEL -o OUT.obj|OUT.ply [--zscale Z]: a mesh model as a height field for 3-D tools.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/output/export.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/model_file.h"
#include "cli/output_format.h"

namespace erd::cli {

const CommandLine kExport = {
    "export",
    "erd export MODEL -o OUT.obj|OUT.ply [--zscale Z]",
    "Writes a .model or .erd mesh as a surface: x, y in pixels with y up (y = H-1 - row), z = value * Z,\n"
    "faces counter-clockwise seen from above. For an ERD model every wedge becomes its own vertex copy,\n"
    "so the surface is cut open along the constrained edges (the model's discontinuities).",
    {
        {'o', "output", "FILE", "output mesh: FILE.obj (Wavefront) or FILE.ply (ASCII PLY); \"-\" = stdout with --format"},
        {0, "format", "obj|ply", "output format when the file name does not say (default: from the name)"},
        {'z', "zscale", "Z", "height per sample unit (default max(W,H) / (10 maxval): the value range is a tenth of the larger side)"},
    },
    "no warnings", 1, 1, "expected one MODEL",
};

static int run_export(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("-o OUT.obj or OUT.ply is required");
    const std::string in = args.positional()[0], out = args.str("output");

    ExportOptions opt;
    std::string format;
    Status st;
    if (!(st = output_format(args.str("format"), out, "obj", "ply", &format))) return rep.usage(st.message);
    opt.format = format == "obj" ? MeshFormat::obj : MeshFormat::ply;
    opt.zscale = args.real("zscale", 0, 0, 1e12, &st);
    if (!st) return rep.usage(st.message);
    if (args.has("zscale") && !(opt.zscale > 0)) return rep.usage("--zscale must be greater than 0");

    st = refuse_overwrite(out, {in});
    if (!st) return rep.fail(st);
    Model m;
    std::string warning;
    st = load_model_file(in, &m, &warning);
    if (!st) return rep.fail(st);
    rep.warn(warning);
    std::string text;
    st = export_mesh(m, opt, &text);
    if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
    st = write_file_atomic(out, text);
    if (!st) return rep.fail(st);
    return 0;
}

int cmd_export(int argc, char** argv) { return run_command(kExport, argc, argv, run_export); }

}  // namespace erd::cli
