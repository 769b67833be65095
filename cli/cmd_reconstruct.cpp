// erd reconstruct [MODEL] [-o OUT] [--no-aa] [--plain]: the thesis's imgsyn and imgsyn_aa.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/model/model.h"
#include "algorithms/model/reconstruct.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "cli/model_file.h"

namespace erd::cli {

const CommandLine kReconstruct = {
    "reconstruct",
    "erd reconstruct [MODEL] [-o OUT] [--no-aa] [--plain]",
    "Rasterises a mesh model back into an image. MODEL is a .model (basic model: point\n"
    "evaluation at every pixel, the thesis's imgsyn) or an .erd (ERD model: 4x4 supersampling,\n"
    "imgsyn_aa, unless --no-aa or the file says \"edges hard\": then point evaluation); read from stdin when omitted or \"-\" (the kind is then told\n"
    "from the content). The image has the model's maxval and size (W = max x + 1, H = max y + 1\n"
    "over the vertices), and its channels: a colour model (header \"channels 3\") gives an RGB image.",
    {
        {'o', "output", "OUT", "image to write (default stdout); .png gives PNG (maxval < 256), else PGM (PPM for colour)"},
        {0, "no-aa", nullptr, "point evaluation at the pixels also for a soft-edged .erd (default there: 4x4 supersampling)"},
        {0, "plain", nullptr, "write plain PGM (P2; P3 for colour), as the thesis's imgsyn did"},
    },
    "no warnings", 0, 1, "expected at most one MODEL",
};

static int run_reconstruct(const Args& args, const Reporter& rep) {
    const std::string in = args.positional().empty() ? "-" : args.positional()[0];
    const std::string out = args.str("output", "-");
    Status st = refuse_overwrite(out, {in});
    if (!st) return rep.fail(st);

    Model model;
    ModelTopology topo;
    std::string warning;
    if (!(st = load_model_file(in, &model, &warning, &topo))) return rep.fail(st);
    rep.warn(warning);
    const bool supersample = supersampled(model) && !args.has("no-aa");
    Image im;
    if (!(st = reconstruct(model, topo, supersample, &im))) return rep.fail(Status::error(st.code, in + ": " + st.message));
    WriteOptions wo;
    wo.plain = args.has("plain");
    if (!(st = write_image(out, im, wo))) return rep.fail(st);
    return 0;
}

int cmd_reconstruct(int argc, char** argv) { return run_command(kReconstruct, argc, argv, run_reconstruct); }

}  // namespace erd::cli
