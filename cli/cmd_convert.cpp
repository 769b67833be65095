// erd convert IN OUT: a model from one file format to another (.model / .erd text, .erdz
// binary), by the output's name; --step / --bpp / --step-psnr set the .erdz quantisation.
#include <string>

#include "algorithms/model/model_io.h"
#include "cli/codec_output.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "cli/model_file.h"
#include "cli/outputs.h"

namespace erd::cli {

const CommandLine kConvert = {
    "convert",
    "erd convert IN OUT [--step Q | --bpp B | --step-psnr P -i IMAGE] [--method NAME]",
    "Rewrites a model in the format OUT's name asks for: .erdz (binary, entropy-coded), or the\n"
    "text .model (basic model) / .erd (ERD model). IN is any model file, told by its content.\n"
    "An .erdz quantises the values to multiples of the step (error at most step / 2; a text\n"
    "model of integer values is kept exactly at step 1). Prints the .erdz's size (unless -q).",
    {
        {0, "step", "Q", ".erdz: value quantisation step (default 1)"},
        {0, "bpp", "B", ".erdz: the finest step whose file has at most B bits per pixel"},
        {0, "step-psnr", "P", ".erdz: the coarsest step whose decoded model reconstructs IMAGE at P dB or more"},
        {'i', "image", "IMAGE", "the original image, for --step-psnr"},
        {'m', "method", "NAME", ".erdz: the method name stored in the header (default none)"},
    },
    "no size line", 2, 2, "expected IN and OUT",
};

static int run_convert(const Args& args, const Reporter& rep) {
    const std::string in = args.positional()[0], out = args.positional()[1];
    CodecChoice codec;
    Status st;
    parse_codec_options(args, &codec, &st);
    if (!st) return rep.usage(st.message);
    if (codec.target.psnr > 0.0 && !args.has("image")) return rep.usage("--step-psnr needs the original image (-i IMAGE)");
    if (codec.given && !erdz_name(out)) return rep.usage("--step, --bpp and --step-psnr apply to .erdz outputs only");
    codec.erdz.method = args.str("method");
    Outputs outputs;
    std::vector<std::string> ins = {in};
    if (args.has("image")) ins.push_back(args.str("image"));
    if (!(st = outputs.check({out}, ins))) return rep.fail(st);

    Model m;
    std::string warning;
    if (!(st = load_model_file(in, &m, &warning))) return rep.fail(st);
    rep.warn(warning);
    const ModelFileKind named = model_kind_from_name(out);
    if ((named == ModelFileKind::basic && m.kind != ModelKind::basic) || (named == ModelFileKind::erd && m.kind != ModelKind::erd) ||
        named == ModelFileKind::triangulation)
        return rep.fail(Status::bad_input(escape_name(out) + ": " + escape_name(in) + " holds " +
                                          (m.kind == ModelKind::erd ? "an ERD model: name the output .erd or .erdz"
                                                                    : "a basic model: name the output .model or .erdz")));
    Image image;
    if (args.has("image")) {
        if (!(st = read_input_image(args.str("image"), ColourInput::keep, rep, &image))) return rep.fail(st);
    }
    std::string bytes, note;
    if (!(st = model_bytes_for(out, m, args.has("image") ? &image : nullptr, codec, &bytes, &note))) return rep.fail(st);
    if (!(st = outputs.stage(out, bytes))) return rep.fail(st);
    if (!(st = outputs.commit())) return rep.fail(st);
    if (!note.empty()) rep.note(escape_name(out) + ": " + note);
    return 0;
}

int cmd_convert(int argc, char** argv) { return run_command(kConvert, argc, argv, run_convert); }

}  // namespace erd::cli
