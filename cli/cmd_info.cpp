// erd info FILE [--json]: what an image file holds, as erd reads it; for an .erdz model, its
// header and the size of each section.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/imaging/georef.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/model/model_io.h"
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
        case ImageFormat::tiff: return "tiff";
        case ImageFormat::pfm: return "pfm";
        case ImageFormat::unknown: break;
    }
    return "unknown";
}

const CommandLine kInfo = {
    "info",
    "erd info IMAGE|MODEL.erdz [--json]",
    "Prints the size, channels, maxval, bits per sample, format and sample range of a PGM\n"
    "(P2, P5), PPM (P3, P6), PAM (P7), PNG, JPEG, TIFF or PFM file (\"-\" reads stdin). The format is\n"
    "recognised from the content, not the name; a colour file whose channels are all equal is gray.\n"
    "A TIFF or PFM also shows its sample type, the range of its valid samples, its nodata value and\n"
    "count, and its georeferencing (GeoTIFF).\n"
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

// A TIFF or PFM (or any real image): the type, the valid samples' range and mean, nodata, georeferencing.
static int raster_info(const std::string& path, const Image& im, ImageFormat fmt, const Args& args) {
    const std::size_t n = im.pixels(), C = std::size_t(im.channels);
    double lo = 0, hi = 0, sum = 0;
    std::size_t valid = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!pixel_valid(im, i)) continue;
        for (std::size_t c = 0; c < C; ++c) {
            const double v = sample_value(im, i * C + c);
            lo = valid == 0 && c == 0 ? v : std::min(lo, v);
            hi = valid == 0 && c == 0 ? v : std::max(hi, v);
            sum += v;
        }
        ++valid;
    }
    const double mean = valid ? sum / double(valid * C) : 0.0;
    const std::size_t nodata = n - valid;
    const RasterMeta& meta = im.meta;
    const std::string type = sample_type_name(meta.type);
    const std::string nd = meta.has_nodata ? (std::isnan(meta.nodata) ? std::string("nan") : format_value(meta.nodata)) : std::string();
    PixelToWorld w;
    const bool geo = pixel_to_world(meta.geo, &w);
    if (args.has("json")) {
        JsonObject j;
        j.str("file", path).str("format", format_key(fmt)).integer("width", im.width).integer("height", im.height);
        j.integer("channels", im.channels).str("type", type).boolean("real", im.real());
        j.num("min", lo).num("max", hi).num("mean", mean);
        if (meta.has_nodata && !std::isnan(meta.nodata)) j.num("nodata", meta.nodata);
        else if (meta.has_nodata) j.str("nodata", "nan");
        else j.null("nodata");
        j.integer("nodata_pixels", std::int64_t(nodata));
        j.boolean("georeferenced", !meta.geo.empty());
        if (geo)
            j.raw("pixel_to_world", "[" + format_value(w.a) + "," + format_value(w.b) + "," + format_value(w.c) + "," + format_value(w.d) +
                                        "," + format_value(w.e) + "," + format_value(w.f) + "]");
        const int epsg = geo_epsg(meta.geo);
        if (epsg) j.integer("epsg", epsg);
        else j.null("epsg");
        std::printf("%s\n", j.text().c_str());
        return 0;
    }
    std::printf("file:    %s\nformat:  %s\nsize:    %d x %d (%zu pixels)\n", escape_name(path).c_str(), format_name(fmt), im.width,
                im.height, n);
    if (C == 3) std::printf("channels: 3 (RGB, colour)\n");
    std::printf("type:    %s (%s)\n", type.c_str(), im.real() ? "real values: meshed without quantisation" : "integer samples");
    std::printf("samples: min %.10g, max %.10g, mean %.10g (over the valid pixels)\n", lo, hi, mean);
    if (meta.has_nodata || nodata)
        std::printf("nodata:  %s, %zu pixels (%.4g%%)\n", meta.has_nodata ? nd.c_str() : "NaN samples", nodata,
                    100.0 * double(nodata) / double(n));
    else
        std::printf("nodata:  none\n");
    std::printf("georef:  %s\n", describe_georef(meta.geo).c_str());
    return 0;
}

static int run_info(const Args& args, const Reporter& rep) {
    const std::string path = args.positional()[0];
    if (erdz_file(path)) return erdz_info(path, args, rep);

    Image im;
    ImageFormat fmt = ImageFormat::unknown;
    Status st = read_input_image(path, ColourInput::keep, rep, &im, &fmt);
    if (!st) return rep.fail(st);
    if (fmt == ImageFormat::tiff || fmt == ImageFormat::pfm || im.real()) return raster_info(path, im, fmt, args);

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
