// erd info FILE [--json]: what an image file holds, as erd reads it; for an .erdz model, its
// header and the size of each section.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/image_io.h"
#include "cli/json.h"
#include "cli/model_file.h"

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
    "erd info IMAGE|MODEL.erdz [--json]",
    "Prints the size, channels, maxval, bits per sample, format and sample range of a PGM\n"
    "(P2, P5), PPM (P3, P6), PAM (P7), PNG or JPEG file (\"-\" reads stdin). The format is recognised\n"
    "from the content, not the name; a colour file whose channels are all equal is gray.\n"
    "For an .erdz model (by name, or a file that starts with its magic): the header, the\n"
    "size of each section in bits and the bits per pixel.",
    {
        {0, "json", nullptr, "one JSON object on stdout"},
    },
    "no warnings", 1, 1, "expected one IMAGE",
};

// A file named .erdz, or a regular file that starts with the magic.
static bool erdz_file(const std::string& path) {
    if (erdz_name(path)) return true;
    if (path == "-") return false;
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    char magic[4] = {0, 0, 0, 0};
    const bool four = std::fread(magic, 1, 4, f) == 4;
    std::fclose(f);
    return four && is_erdz(std::string(magic, 4));
}

static int erdz_info(const std::string& path, const Args& args, const Reporter& rep) {
    Model m;
    ErdzInfo info;
    std::string warning;
    Status st = load_model_file(path, &m, &warning, nullptr, &info);
    if (!st) return rep.fail(st);
    if (info.version == 0) return rep.fail(Status::bad_input(escape_name(path) + ": not an .erdz file"));
    const double px = double(m.width) * double(m.height);
    const auto bpp = [&](std::size_t bits) { return double(bits) / px; };
    const char* kind = m.kind == ModelKind::erd ? (m.edges == EdgeKind::hard ? "erd (hard edges)" : "erd") : "basic";
    if (args.has("json")) {
        JsonObject j;
        j.str("file", path).str("format", "erdz").integer("version", info.version).str("kind", m.kind == ModelKind::erd ? "erd" : "basic");
        j.str("edges", m.edges == EdgeKind::hard ? "hard" : "soft").str("method", info.method);
        j.integer("width", m.width).integer("height", m.height).integer("maxval", m.maxval).integer("channels", m.channels);
        j.num("step", info.step).integer("vertices", std::int64_t(m.vertices.size())).integer("faces", std::int64_t(m.faces.size()));
        j.integer("constraints", std::int64_t(m.constraints.size()));
        j.integer("header_bits", std::int64_t(info.header_bits)).integer("position_bits", std::int64_t(info.position_bits));
        j.integer("edge_bits", std::int64_t(info.edge_bits)).integer("flip_bits", std::int64_t(info.flip_bits));
        j.integer("value_bits", std::int64_t(info.value_bits)).integer("flips", std::int64_t(info.flips));
        j.integer("total_bits", std::int64_t(info.total_bits)).num("bpp", bpp(info.total_bits));
        std::printf("%s\n", j.text().c_str());
        return 0;
    }
    std::printf("file:      %s\nformat:    erdz %d, %s model, method %s\nsize:      %d x %d (%.0f pixels), maxval %u, %d channel%s\n"
                "mesh:      %zu vertices, %zu faces, %zu constrained edges\nstep:      %g (values within %g)\n",
                escape_name(path).c_str(), info.version, kind, info.method.empty() ? "(none)" : info.method.c_str(), m.width,
                m.height, px, m.maxval, m.channels, m.channels == 1 ? "" : "s", m.vertices.size(), m.faces.size(),
                m.constraints.size(), info.step, info.step / 2);
    std::printf("header:    %9zu bits  %.5f bpp\n", info.header_bits, bpp(info.header_bits));
    std::printf("positions: %9zu bits  %.5f bpp  (%zu free points on the %s lattice)\n", info.position_bits,
                bpp(info.position_bits), info.free_points, info.full_lattice ? "half-pixel" : "pixel");
    std::printf("edges:     %9zu bits  %.5f bpp  (%zu chains, %zu steps)\n", info.edge_bits, bpp(info.edge_bits), info.chains,
                info.chain_steps);
    std::printf("flips:     %9zu bits  %.5f bpp  (%zu edges flipped)\n", info.flip_bits, bpp(info.flip_bits), info.flips);
    std::printf("values:    %9zu bits  %.5f bpp  (%zu values)\n", info.value_bits, bpp(info.value_bits), info.coded_values);
    std::printf("total:     %9zu bits  %.5f bpp  (%zu bytes)\n", info.total_bits, bpp(info.total_bits), info.total_bits / 8);
    return 0;
}

static int run_info(const Args& args, const Reporter& rep) {
    const std::string path = args.positional()[0];
    if (erdz_file(path)) return erdz_info(path, args, rep);

    Image im;
    ImageFormat fmt = ImageFormat::unknown;
    Status st = read_input_image(path, ColourInput::keep, rep, &im, &fmt);
    if (!st) return rep.fail(st);

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
