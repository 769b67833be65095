// erd reconstruct [MODEL] [-o OUT] [--no-aa] [--plain]: the thesis's imgsyn and imgsyn_aa.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/model/model.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "cli/command_line.h"
#include "cli/batch.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "cli/model_file.h"

namespace erd::cli {

const CommandLine kReconstruct = {
    "reconstruct",
    "erd reconstruct [MODEL...] [-o OUT] [--no-aa] [--plain] [-j JOBS] [--summary FILE]",
    "Rasterises a mesh model back into an image. MODEL is a .model (basic model: point\n"
    "evaluation at every pixel, the thesis's imgsyn) or an .erd (ERD model: 4x4 supersampling,\n"
    "imgsyn_aa, unless --no-aa or the file says \"edges hard\": then point evaluation; the pixels\n"
    "along edges a file lists as \"hard-edges\" or \"soft-edges\" as that kind says); read from\n"
    "stdin when omitted or \"-\" (the kind is then told from the content). The image has the model's maxval and size (W = max x + 1, H = max y + 1\n"
    "over the vertices), and its channels: a colour model (header \"channels 3\") gives an RGB image.\n"
    "A model of a real-valued raster (header \"range\") is point-evaluated, each pixel on the face\n"
    "that owns it, and written in its own sample type as TIFF (.tif, georeferenced as its raster,\n"
    "nodata where no face is) or PFM (.pfm); PNG and PGM get 16 bits of its range.\n"
    "Many models (several, or a folder): -o names each image by a pattern with {name}, the\n"
    "model's name without its extension (erd reconstruct out/ -o rec/{name}.png -j 4).",
    {
        {'o', "output", "OUT", "image to write (default stdout); .png gives PNG (maxval < 256), .tif TIFF, .pfm PFM, else PGM (PPM for colour)"},
        {0, "no-aa", nullptr, "point evaluation at every pixel also for a soft-edged .erd or soft edges (default there: 4x4 supersampling)"},
        {0, "plain", nullptr, "write plain PGM (P2; P3 for colour), as the thesis's imgsyn did"},
        kProgressOption,
        {'j', "jobs", "N", "one model: N threads (default and 0: one per processor); many: N models at a time (default 1)"},
        {0, "summary", "FILE", "many models: a table of file, kind, points, seconds, status (.csv, or .json)"},
    },
    "no warnings", 0, 1 << 20, nullptr,
};

static int reconstruct_one(const Args& args, const Reporter& rep, const std::string& in, const std::string& out,
                           int threads, BatchRecord* record) {
    Model model;
    ModelTopology topo;
    Status st = load_input_model(out, {in}, rep, &model, &topo);
    if (!st) return rep.fail(st);
    const bool supersample = supersampled(model) && !args.has("no-aa");
    if (args.has("no-aa")) model.kind_exceptions.clear();  // no edge of any kind supersampled
    Image im;
    Progress progress("reconstruct", !record && Progress::should_show(args.has("progress"), rep.quiet()), args.has("progress"));
    st = reconstruct(model, topo, supersample, &im, progress.hook(), threads);
    progress.finish();
    if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
    WriteOptions wo;
    wo.plain = args.has("plain");
    if (im.real() && !keeps_real_values(out))
        rep.warn(escape_name(out) + ": a real-valued model's image is written as 16-bit (its range " + format_value(im.lo) + " .. " +
                 format_value(im.hi) + " onto 0 .. 65535); .tif and .pfm keep the values");
    if (!(st = write_image(out, im, wo))) return rep.fail(st);
    if (record) {
        record->method = model.kind == ModelKind::erd ? "erd" : "basic";
        record->points = (long long)model.vertices.size();
    }
    return 0;
}

static int run_reconstruct(const Args& args, const Reporter& rep) {
    const std::vector<std::string>& models = args.positional();
    const std::string out = args.str("output", "-");
    const bool batch = wants_batch(models, out, args.has("summary"));
    Parallelism par;
    Status st = parse_parallelism(args.has("jobs"), args.str("jobs"), batch, &par);
    if (!st) return rep.usage(st.message);
    if (!batch) return reconstruct_one(args, rep, models.empty() ? "-" : models[0], out, par.threads, nullptr);
    std::vector<BatchItem> items;
    st = expand_inputs(models, {".model", ".erd", ".erdz"}, &items);
    if (st && !(st = check_patterns(items, {out == "-" ? std::string() : out}))) return rep.usage(st.message);
    if (!st) return rep.fail(st);
    if (out == "-" && items.size() > 1) return rep.usage("many models: name the images with -o and {name} (rec/{name}.pgm)");
    const BatchJob job = [&](const BatchItem& it, BatchRecord* rec) {
        return reconstruct_one(args, rep, it.input, expand_pattern(out, it), par.threads, rec);
    };
    return run_batch(items, par.jobs, job, args.str("summary"), rep, Progress::should_show(args.has("progress"), rep.quiet()),
                     {{out}, {}});
}

int cmd_reconstruct(int argc, char** argv) { return run_command(kReconstruct, argc, argv, run_reconstruct); }

}  // namespace erd::cli
