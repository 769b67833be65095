// erd info IMAGE [--json]: what an image file holds, as erd reads it.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/image_io.h"
#include "cli/report.h"

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

int cmd_info(int argc, char** argv) {
    Reporter rep("info");
    static const std::vector<OptionSpec> specs = {
        {0, "json", nullptr, "one JSON object on stdout"},
        {'q', "quiet", nullptr, "no warnings"},
        {'h', "help", nullptr, "show this help"},
    };
    const char* usage = "erd info IMAGE [--json]";
    Args args;
    Status st = args.parse(argc, argv, 1, specs);
    if (!st) return rep.usage(st.message, usage);
    if (args.has("help")) {
        std::printf("usage: %s\n\nPrints the size, maxval, bits per sample, format and sample range of a PGM (P2, P5)\n"
                    "or PNG file (\"-\" reads stdin). The format is recognised from the content, not the name.\n\n%s",
                    usage, describe(specs).c_str());
        return 0;
    }
    rep.set_quiet(args.has("quiet"));
    if (args.positional().size() != 1) return rep.usage("expected one IMAGE", usage);
    const std::string path = args.positional()[0];

    Image im;
    std::string warning;
    ImageFormat fmt = ImageFormat::unknown;
    st = read_image(path, &im, &warning, &fmt);
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
        std::printf("{\"file\":%s,\"format\":\"%s\",\"width\":%d,\"height\":%d,\"maxval\":%u,\"bits\":%d,"
                    "\"min\":%u,\"max\":%u,\"mean\":%s}\n",
                    json_string(path).c_str(), format_key(fmt), im.width, im.height, im.maxval, im.bits(), lo, hi,
                    json_number(mean).c_str());
    } else {
        std::printf("file:    %s\nformat:  %s\nsize:    %d x %d (%zu pixels)\nmaxval:  %u\nbits:    %d\n"
                    "samples: min %u, max %u, mean %.4f\n",
                    escape_name(path).c_str(), format_name(fmt), im.width, im.height, im.pixels(), im.maxval, im.bits(), lo, hi, mean);
    }
    return 0;
}

}  // namespace erd::cli
