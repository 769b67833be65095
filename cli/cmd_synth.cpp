// erd synth [-W 256 -H 256 --bits 8|16 --seed N] -o FILE: a deterministic test image.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/imaging/drawings.h"
#include "algorithms/imaging/synth.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/image_io.h"

namespace erd::cli {

const CommandLine kSynth = {
    "synth",
    "erd synth [-W 256 -H 256 --bits 8|16 --seed N] [--kind K --blur N] -o FILE",
    "Writes a deterministic test image: a smooth ramp and bump, two discs, a triangle and a\n"
    "slanted step with sharp edges, and mild noise; or, with --kind, a hard-edged picture (no\n"
    "anti-aliasing: every edge a step between two pixels), blurred with --blur. The same\n"
    "options give the same bytes.",
    {
        {'W', "width", "N", "width in pixels (default 256)"},
        {'H', "height", "N", "height in pixels (default 256)"},
        {0, "bits", "B", "bits per sample, 1..16 (default 8): maxval = 2^B - 1"},
        {0, "seed", "N", "noise seed (default 1); shapes depend on the size only"},
        {0, "no-noise", nullptr, "leave out the noise"},
        {0, "kind", "K", "mixed (default) or a hard-edged picture: drawing, cartoon, screenshot, icons, map, scene, chart, pixelart, cel"},
        {0, "blur", "N", "hard-edged kinds: N passes of the binomial [1 2 1]/4 along x and y (soft edges; default 0)"},
        {'o', "output", "FILE", "output: .png (8 bits at most) or PGM; \"-\" = stdout"},
        {0, "plain", nullptr, "write plain PGM (P2) instead of raw (P5)"},
    },
    "no messages",
};

static int run_synth(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("missing -o FILE");

    Status st;
    SynthParams p;
    p.width = int(args.integer("width", 256, 1, kMaxImageSide, &st));
    p.height = int(args.integer("height", 256, 1, kMaxImageSide, &st));
    p.bits = int(args.integer("bits", 8, 1, 16, &st));
    p.seed = std::uint64_t(args.integer("seed", 1, 0, (long long)(~0ull >> 1), &st));
    p.noise = !args.has("no-noise");
    const std::string kind = args.has("kind") ? args.str("kind") : "mixed";
    DrawingParams dp;
    dp.kind = kind;
    dp.width = p.width;
    dp.height = p.height;
    dp.bits = p.bits;
    dp.blur = int(args.integer("blur", 0, 0, 64, &st));
    if (!st) return rep.usage(st.message);
    if (kind == "mixed" && args.has("blur")) return rep.usage("--blur needs a hard-edged --kind");

    // The output checked before the image is made (its folder, a read-only file, a folder named).
    const std::string out = args.str("output");
    if (!(st = refuse_overwrite(out, {}))) return rep.fail(st);
    Image im;
    if (!(st = kind == "mixed" ? synth(p, &im) : draw_picture(dp, &im))) return rep.fail(st);
    WriteOptions wo;
    wo.plain = args.has("plain");
    if (!(st = write_image(out, im, wo))) return rep.fail(st);
    if (out != "-") rep.note("wrote " + out + " (" + std::to_string(p.width) + " x " + std::to_string(p.height) + ", maxval " +
                             std::to_string(im.maxval) + ")");
    return 0;
}

int cmd_synth(int argc, char** argv) { return run_command(kSynth, argc, argv, run_synth); }

}  // namespace erd::cli
