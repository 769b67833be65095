// erd psnr ORIGINAL APPROX [--json]: the thesis's Cal_PSNR.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/model/metrics.h"
#include "cli/batch.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/image_io.h"
#include "cli/json.h"

namespace erd::cli {

const CommandLine kPsnr = {
    "psnr",
    "erd psnr ORIGINAL APPROX... [--channels] [--gray] [--json] [-j JOBS] [--summary FILE]",
    "Prints the PSNR of APPROX against ORIGINAL in dB with 4 decimals (\"inf\" when they are\n"
    "identical). Peak = 2^p - 1 with p = ceil(log2(maxval + 1)) of the original; PSNR =\n"
    "10 log10(peak^2 / MSE). Both images must have the same size, maxval and channels; for\n"
    "colour the MSE is averaged over the three channels and all pixels.\n"
    "Many images (several APPROX, or a folder): ORIGINAL is a pattern with {name}, the APPROX's\n"
    "name without its extension (erd psnr 'photos/{name}.png' rec/ --summary psnr.csv); each\n"
    "line is then \"APPROX PSNR\".",
    {
        {'j', "jobs", "N", "one pair: N threads (default and 0: one per processor); many: N images at a time (default 1)"},
        {0, "summary", "FILE", "many images: a table of file, points, PSNR, seconds, status (.csv, or .json)"},
        {0, "json", nullptr, "{\"mse\":..,\"peak\":..,\"psnr\":..} on stdout (psnr null when identical)"},
        {0, "channels", nullptr, "colour: also the PSNR of each channel, a second line \"R x G y B z\" (JSON: \"channels\":[..])"},
        {0, "gray", nullptr, "compare the BT.601 luma of colour images (a colour and a gray image then compare)"},
    },
    "no warnings", 2, 1 << 20, "expected ORIGINAL and APPROX",
};

// One pair; in a batch (record not null) the line names APPROX and the PSNR goes to the record.
static int psnr_one(const Args& args, const Reporter& rep, const std::string& a, const std::string& b,
                    int threads, BatchRecord* record) {
    if (a == "-" && b == "-") return rep.usage("only one of the images can be stdin");

    Image orig, approx;
    Status st;
    const ColourInput colour = args.has("gray") ? ColourInput::luma_asked : ColourInput::keep;
    if (!(st = read_input_image(a, colour, rep, &orig))) return rep.fail(st);
    if (!(st = read_input_image(b, colour, rep, &approx))) return rep.fail(st);

    double e = 0, p = 0, per[3] = {0, 0, 0};
    const bool channels = args.has("channels") && orig.channels == 3;
    // One pass over the samples for the PSNR (psnr() is psnr_of_mse of the same mse), a second
    // for the channels only when they are asked for.
    if (!(st = mse(orig, approx, &e, threads)) || (channels && !(st = channel_mse(orig, approx, per, threads)))) {
        std::string msg = a + " and " + b + ": " + st.message;
        if (st.message.find("colour and the other gray") != std::string::npos) msg += " (--gray compares their luma)";
        return rep.fail(Status::bad_input(msg));
    }
    p = psnr_of_mse(e, orig.maxval);
    const double peak = psnr_peak(orig.maxval);
    if (record) {
        record->has_psnr = !std::isinf(p);
        record->psnr = p;
        std::printf(std::isinf(p) ? "%s inf\n" : "%s %.4f\n", escape_name(b).c_str(), p);  // a name on a terminal
        return 0;
    }
    if (args.has("json")) {
        JsonObject j;
        j.num("mse", e).num("peak", peak).num("psnr", p);
        if (channels) {
            std::string list;
            for (int c = 0; c < 3; ++c) list += (c ? "," : "[") + json_number(psnr_of_mse(per[c], orig.maxval));
            j.raw("channels", list + "]");
        }
        std::printf("%s\n", j.text().c_str());
        return 0;
    }
    std::printf(std::isinf(p) ? "inf\n" : "%.4f\n", p);
    if (channels) {
        // The three on a second line, so the first stays the one number scripts read.
        for (int c = 0; c < 3; ++c) {
            const double pc = psnr_of_mse(per[c], orig.maxval);
            if (std::isinf(pc)) std::printf("%s%c inf", c ? " " : "", "RGB"[c]);
            else std::printf("%s%c %.4f", c ? " " : "", "RGB"[c], pc);
        }
        std::printf("\n");
    }
    return 0;
}

static int run_psnr(const Args& args, const Reporter& rep) {
    const std::vector<std::string>& pos = args.positional();
    const std::vector<std::string> approx(pos.begin() + 1, pos.end());
    const bool batch = wants_batch(approx, pos[0], args.has("summary"));
    Parallelism par;
    Status st = parse_parallelism(args.has("jobs"), args.str("jobs"), batch, &par);
    if (!st) return rep.usage(st.message);
    if (!batch) return psnr_one(args, rep, pos[0], pos[1], par.threads, nullptr);
    if (args.has("json")) return rep.usage("many images: --json is for one pair (--summary s.json writes a table)");
    if (!has_name_field(pos[0]))
        return rep.usage("many images: ORIGINAL must name each original by a pattern with {name} ('photos/{name}.png')");
    std::vector<BatchItem> items;
    st = expand_inputs(approx, {".pgm", ".pnm", ".png", ".ppm", ".pam", ".jpg", ".jpeg"}, &items);
    if (!st) return rep.fail(st);
    const BatchJob job = [&](const BatchItem& it, BatchRecord* rec) {
        return psnr_one(args, rep, expand_pattern(pos[0], it), it.input, par.threads, rec);
    };
    return run_batch(items, par.jobs, job, args.str("summary"), rep, false, {{}, {pos[0]}});
}

int cmd_psnr(int argc, char** argv) { return run_command(kPsnr, argc, argv, run_psnr); }

}  // namespace erd::cli
