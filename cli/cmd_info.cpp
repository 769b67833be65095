// erd info IMAGE [--json]: what an image file holds, as erd reads it.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/image_io.h"
#include "cli/json.h"

namespace erd::cli {

static const char* format_key(ImageFormat f) {
    switch (f) {
        case ImageFormat::pgm_plain: return "pgm-plain";
        case ImageFormat::pgm_raw: return "pgm-raw";
        case ImageFormat::png: return "png";
        case ImageFormat::unknown: break;
    }
    return "unknown";
}

const CommandLine kInfo = {
    "info",
    "erd info IMAGE [--json]",
    "Prints the size, maxval, bits per sample, format and sample range of a PGM (P2, P5)\n"
    "or PNG file (\"-\" reads stdin). The format is recognised from the content, not the name.",
    {
        {0, "json", nullptr, "one JSON object on stdout"},
    },
    "no warnings", 1, 1, "expected one IMAGE",
};

static int run_info(const Args& args, const Reporter& rep) {
    const std::string path = args.positional()[0];

    Image im;
    std::string warning;
    ImageFormat fmt = ImageFormat::unknown;
    Status st = read_image(path, &im, &warning, &fmt);
    if (!st) return rep.fail(st);
    rep.warn(warning);

    unsigned lo = 65535, hi = 0;
    double sum = 0;
    for (std::uint16_t v : im.samples) {
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
        sum += v;
    }
    const double mean = sum / double(im.samples.size());
    if (args.has("json")) {
        JsonObject j;
        j.str("file", path).str("format", format_key(fmt)).integer("width", im.width).integer("height", im.height);
        j.integer("maxval", im.maxval).integer("bits", im.bits()).integer("min", lo).integer("max", hi).num("mean", mean);
        std::printf("%s\n", j.text().c_str());
    } else {
        std::printf("file:    %s\nformat:  %s\nsize:    %d x %d (%zu pixels)\nmaxval:  %u\nbits:    %d\n"
                    "samples: min %u, max %u, mean %.4f\n",
                    escape_name(path).c_str(), format_name(fmt), im.width, im.height, im.pixels(), im.maxval, im.bits(), lo, hi, mean);
    }
    return 0;
}

int cmd_info(int argc, char** argv) { return run_command(kInfo, argc, argv, run_info); }

}  // namespace erd::cli
