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
        case ImageFormat::ppm_plain: return "ppm-plain";
        case ImageFormat::ppm_raw: return "ppm-raw";
        case ImageFormat::pam: return "pam";
        case ImageFormat::png: return "png";
        case ImageFormat::jpeg: return "jpeg";
        case ImageFormat::unknown: break;
    }
    return "unknown";
}

const CommandLine kInfo = {
    "info",
    "erd info IMAGE [--json]",
    "Prints the size, channels, maxval, bits per sample, format and sample range of a PGM\n"
    "(P2, P5), PPM (P3, P6), PAM (P7), PNG or JPEG file (\"-\" reads stdin). The format is recognised\n"
    "from the content, not the name; a colour file whose channels are all equal is gray.",
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
        j.integer("channels", im.channels);
        std::printf("%s\n", j.text().c_str());
    } else {
        std::printf("file:    %s\nformat:  %s\nsize:    %d x %d (%zu pixels)\n", escape_name(path).c_str(), format_name(fmt),
                    im.width, im.height, im.pixels());
        if (im.channels == 3) std::printf("channels: 3 (RGB, colour)\n");
        std::printf("maxval:  %u\nbits:    %d\nsamples: min %u, max %u, mean %.4f\n", im.maxval, im.bits(), lo, hi, mean);
    }
    return 0;
}

int cmd_info(int argc, char** argv) { return run_command(kInfo, argc, argv, run_info); }

}  // namespace erd::cli
