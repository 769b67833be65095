// erd export MODEL -o OUT.obj|OUT.ply|OUT.stl [--zscale Z] [--base H]: a mesh model as a height field for 3-D tools.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/output/export.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/fileio.h"
#include "cli/model_file.h"
#include "cli/output_format.h"

namespace erd::cli {

const CommandLine kExport = {
    "export",
    "erd export MODEL -o OUT.obj|OUT.ply|OUT.stl|OUT.glb [--zscale Z] [--base H]",
    "Writes a .model or .erd mesh as a surface: x, y in pixels with y up (y = H-1 - row), z = value * Z,\n"
    "faces counter-clockwise seen from above. For an ERD model every wedge becomes its own vertex copy,\n"
    "so the surface is cut open along the constrained edges (the model's discontinuities).\n"
    "A model of a GeoTIFF is written in its world coordinates (x, y of the pixel centres; Z 1 by\n"
    "default in a projected CRS), and a model with nodata leaves its holes open. .glb is glTF 2.0\n"
    "binary (y up, for three.js, Cesium, Blender, Unity, Unreal); STL and glTF hold world coordinates\n"
    "from the mesh's centre (named in the STL header, the glTF node's translation).",
    {
        {'o', "output", "FILE", "output mesh: FILE.obj (Wavefront), FILE.ply (ASCII PLY), FILE.stl (binary STL) or FILE.glb (glTF 2.0); \"-\" = stdout with --format"},
        {0, "format", "obj|ply|stl|glb", "output format when the file name does not say (default: from the name)"},
        {'z', "zscale", "Z", "height per sample unit (default max(W,H) / (10 maxval): the value range is a tenth of the larger side; 1 for a projected GeoTIFF)"},
        {'b', "base", "H", "STL: a solid with walls and a bottom, the surface lifted by H (basic models)"},
        kProgressOption,
    },
    "no warnings", 1, 1, "expected one MODEL",
};

static int run_export(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("-o OUT.obj, OUT.ply, OUT.stl or OUT.glb is required");
    const std::string in = args.positional()[0], out = args.str("output");

    ExportOptions opt;
    std::string format;
    Status st;
    const bool stl = args.str("format") == "stl" || (args.str("format").empty() && has_extension(out, ".stl"));
    const bool glb = args.str("format") == "glb" || (args.str("format").empty() && has_extension(out, ".glb"));
    if (stl) opt.format = MeshFormat::stl;
    else if (glb) opt.format = MeshFormat::glb;
    else if (!(st = output_format(args.str("format"), out, "obj", "ply", &format))) return rep.usage(st.message + " (or .stl, .glb)");
    else opt.format = format == "obj" ? MeshFormat::obj : MeshFormat::ply;
    opt.zscale = args.real("zscale", 0, 0, 1e12, &st);
    if (!st) return rep.usage(st.message);
    if (args.has("zscale") && !(opt.zscale > 0)) return rep.usage("--zscale must be greater than 0");
    opt.base = args.real("base", 0, 0, 1e12, &st);
    if (!st) return rep.usage(st.message);
    if (args.has("base") && !(opt.base > 0)) return rep.usage("--base must be greater than 0");
    if (args.has("base") && !stl) return rep.usage("--base applies to STL output");

    Model m;
    if (!(st = load_input_model(out, {in}, rep, &m))) return rep.fail(st);
    std::string text;
    Progress progress = progress_for("export", args, rep);
    opt.progress = progress.hook();
    st = export_mesh(m, opt, &text);
    progress.finish();
    if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
    st = write_file_atomic(out, text);
    if (!st) return rep.fail(st);
    return 0;
}

int cmd_export(int argc, char** argv) { return run_command(kExport, argc, argv, run_export); }

}  // namespace erd::cli
