// erd info FILE [--json]: what an image file holds, as erd reads it; for a model (.model, .erd,
// .erdz, .tri), what it holds and what its file costs, and for an .erdz the size of each section.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/imaging/georef.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/model/model_io.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/image_io.h"
#include "cli/json.h"
#include "cli/model_file.h"
#include "algorithms/model/edge_kinds.h"

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
    "erd info IMAGE|MODEL [--json]",
    "Prints the size, channels, maxval, bits per sample, format and sample range of a PGM\n"
    "(P2, P5), PPM (P3, P6), PAM (P7), PNG, JPEG, TIFF or PFM file (\"-\" reads stdin). The format is\n"
    "recognised from the content, not the name; a colour file whose channels are all equal is gray.\n"
    "A TIFF or PFM also shows its sample type, the range of its valid samples, its nodata value and\n"
    "count, and its georeferencing (GeoTIFF).\n"
    "For a model (.model, .erd, .erdz, or a -t triangulation .tri; by name or content, \"-\" too): its kind,\n"
    "size, vertices, faces, constrained edges and their kinds, channels, the file's size and bits\n"
    "per pixel; for an .erdz also the size of each section.",
    {
        {0, "json", nullptr, "one JSON object on stdout"},
    },
    "no warnings", 1, 1, "expected one IMAGE or MODEL",
};

// What a model file is, by its name or its first bytes: an .erdz, a text model (.model, .erd,
// .tri, or looks_like_model), or not a model. Standard input is told by its bytes in run_info.
static bool model_file(const std::string& path) {
    if (erdz_name(path) || model_kind_from_name(path) != ModelFileKind::unknown) return true;
    if (path == "-") return false;
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    char head[64] = {0};
    const std::size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    return looks_like_model(std::string(head, n));
}

// The kind of m's constrained edge i: Model::edges, or the other kind for an edge of
// Model::kind_exceptions (algorithms/model/edge_kinds.h); every count below goes through here.
static EdgeKind edge_kind(const Model& m, std::size_t i) {
    const auto& c = m.constraints[i];
    const std::array<std::uint32_t, 2> e{std::min(c[0], c[1]), std::max(c[0], c[1])};
    return std::binary_search(m.kind_exceptions.begin(), m.kind_exceptions.end(), e) ? exception_kind(m) : m.edges;
}

static const char* edge_kind_name(EdgeKind k) { return k == EdgeKind::hard ? "hard" : "soft"; }

// How many of m's constrained edges are of each kind, the kinds present only, soft first.
static std::vector<std::pair<EdgeKind, std::size_t>> edge_kinds(const Model& m) {
    std::size_t n[2] = {0, 0};
    for (std::size_t i = 0; i < m.constraints.size(); ++i) ++n[edge_kind(m, i) == EdgeKind::hard ? 1 : 0];
    std::vector<std::pair<EdgeKind, std::size_t>> out;
    if (n[0]) out.push_back({EdgeKind::soft, n[0]});
    if (n[1]) out.push_back({EdgeKind::hard, n[1]});
    return out;
}

// "427 constrained edges (427 hard)"; a triangulation stores no kinds.
static std::string constraints_text(const Model& m, bool triangulation) {
    std::string s = std::to_string(m.constraints.size()) + " constrained edge" + (m.constraints.size() == 1 ? "" : "s");
    if (triangulation && !m.constraints.empty()) return s + " (a triangulation stores no edge kinds)";
    std::string kinds;
    for (const auto& [k, n] : edge_kinds(m)) kinds += (kinds.empty() ? "" : ", ") + std::to_string(n) + " " + edge_kind_name(k);
    return kinds.empty() ? s : s + " (" + kinds + ")";
}

// {"soft":n,"hard":m}: the kinds present.
static JsonObject edge_kinds_json(const Model& m) {
    JsonObject j;
    for (const auto& [k, n] : edge_kinds(m)) j.integer(edge_kind_name(k), std::int64_t(n));
    return j;
}

// "erd (hard edges)", "erd" or "basic".
static const char* kind_text(const Model& m) {
    return m.kind == ModelKind::erd ? (m.edges == EdgeKind::hard ? "erd (hard edges)" : "erd") : "basic";
}

static int erdz_info(const std::string& path, const Model& m, const ErdzInfo& info, const ModelFileFacts& file,
                     const Args& args) {
    const double px = double(m.width) * double(m.height);
    const auto bpp = [&](std::size_t bits) { return double(bits) / px; };
    if (args.has("json")) {
        JsonObject j;
        j.str("file", path).str("format", "erdz").integer("version", info.version).str("kind", m.kind == ModelKind::erd ? "erd" : "basic");
        j.str("edges", edge_kind_name(m.edges)).str("method", info.method);
        j.integer("width", m.width).integer("height", m.height).integer("maxval", m.maxval).integer("channels", m.channels);
        j.num("step", info.step).integer("vertices", std::int64_t(m.vertices.size())).integer("faces", std::int64_t(m.faces.size()));
        j.integer("constraints", std::int64_t(m.constraints.size())).object("edge_kinds", edge_kinds_json(m));
        j.integer("header_bits", std::int64_t(info.header_bits)).integer("position_bits", std::int64_t(info.position_bits));
        j.integer("kind_bits", std::int64_t(info.kind_bits));
        j.integer("edge_bits", std::int64_t(info.edge_bits)).integer("flip_bits", std::int64_t(info.flip_bits));
        j.integer("value_bits", std::int64_t(info.value_bits)).integer("flips", std::int64_t(info.flips));
        j.integer("total_bits", std::int64_t(info.total_bits)).integer("bytes", std::int64_t(file.bytes)).num("bpp", bpp(info.total_bits));
        std::printf("%s\n", j.text().c_str());
        return 0;
    }
    std::printf("file:      %s\nformat:    erdz %d, %s model, method %s\nsize:      %d x %d (%.0f pixels), maxval %u, %d channel%s\n"
                "mesh:      %zu vertices, %zu faces, %s\nstep:      %g (values within %g)\n",
                escape_name(path).c_str(), info.version, kind_text(m), info.method.empty() ? "(none)" : info.method.c_str(), m.width,
                m.height, px, m.maxval, m.channels, m.channels == 1 ? "" : "s", m.vertices.size(), m.faces.size(),
                constraints_text(m, false).c_str(), info.step, info.step / 2);
    std::printf("header:    %9zu bits  %.5f bpp\n", info.header_bits, bpp(info.header_bits));
    std::printf("positions: %9zu bits  %.5f bpp  (%zu free points on the %s lattice)\n", info.position_bits,
                bpp(info.position_bits), info.free_points, info.full_lattice ? "half-pixel" : "pixel");
    std::printf("edges:     %9zu bits  %.5f bpp  (%zu chains, %zu steps)\n", info.edge_bits, bpp(info.edge_bits), info.chains,
                info.chain_steps);
    std::printf("flips:     %9zu bits  %.5f bpp  (%zu edges flipped)\n", info.flip_bits, bpp(info.flip_bits), info.flips);
    std::printf("values:    %9zu bits  %.5f bpp  (%zu values)\n", info.value_bits, bpp(info.value_bits), info.coded_values);
    if (info.version >= 4)
        std::printf("kinds:     %9zu bits  %.5f bpp  (%zu %s edges)\n", info.kind_bits, bpp(info.kind_bits), info.other_kind_edges,
                    edge_kind_name(exception_kind(m)));
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

// A text model (.model, .erd) or triangulation (.tri): what it holds and what its file costs.
static int text_model_info(const std::string& path, const Model& m, const ModelFileFacts& file, const Args& args) {
    const bool tri = file.kind == ModelFileKind::triangulation;
    const double px = double(m.width) * double(m.height);
    const double bpp = 8.0 * double(file.bytes) / px;
    const char* ext = tri ? "tri" : file.kind == ModelFileKind::erd ? "erd" : "model";
    if (args.has("json")) {
        JsonObject j;
        j.str("file", path).str("format", ext).str("kind", tri ? "triangulation" : m.kind == ModelKind::erd ? "erd" : "basic");
        if (tri || m.kind != ModelKind::erd) j.null("edges");
        else j.str("edges", edge_kind_name(m.edges));
        j.integer("width", m.width).integer("height", m.height);
        if (tri) j.null("maxval").null("channels");
        else j.integer("maxval", m.maxval).integer("channels", m.channels);
        j.integer("vertices", std::int64_t(m.vertices.size())).integer("faces", std::int64_t(m.faces.size()));
        j.integer("constraints", std::int64_t(m.constraints.size()));
        if (tri) j.null("edge_kinds");
        else j.object("edge_kinds", edge_kinds_json(m));
        if (m.real || m.holes || !m.meta.geo.empty()) {  // a raster's model: its type, range, holes, georeferencing
            j.str("type", sample_type_name(m.meta.type)).boolean("real", m.real);
            if (m.real) j.raw("range", "[" + format_value(m.lo) + "," + format_value(m.hi) + "]");
            j.boolean("holes", m.holes).boolean("georeferenced", !m.meta.geo.empty());
        }
        j.integer("bytes", std::int64_t(file.bytes)).num("bpp", bpp);
        std::printf("%s\n", j.text().c_str());
        return 0;
    }
    std::printf("file:      %s\n", escape_name(path).c_str());
    if (tri) {
        std::printf("format:    .tri text, triangulation (no values: erd render draws it, nothing reconstructs it)\n"
                    "size:      %d x %d (%.0f pixels)\n", m.width, m.height, px);
    } else {
        std::printf("format:    .%s text, %s model\nsize:      %d x %d (%.0f pixels), maxval %u, %d channel%s\n", ext, kind_text(m),
                    m.width, m.height, px, m.maxval, m.channels, m.channels == 1 ? "" : "s");
    }
    std::printf("mesh:      %zu vertices, %zu faces, %s\n", m.vertices.size(), m.faces.size(), constraints_text(m, tri).c_str());
    if (m.real) std::printf("values:    real (%s), range %.10g .. %.10g\n", sample_type_name(m.meta.type), m.lo, m.hi);
    if (m.holes) std::printf("holes:     the faces over nodata are dropped (holes in the mesh)\n");
    if (!m.meta.geo.empty()) std::printf("georef:    %s\n", describe_georef(m.meta.geo).c_str());
    std::printf("file size: %zu bytes, %.5f bpp\n", file.bytes, bpp);
    return 0;
}

// A model file's facts; `text` (may be null) holds its bytes when they were read already (stdin).
static int model_info(const std::string& path, const std::string* text, const Args& args, const Reporter& rep) {
    Model m;
    ErdzInfo info;
    ModelFileFacts file;
    std::string warning;
    Status st = text ? parse_model_bytes(path, *text, 0, &m, &warning, nullptr, &info, &file)
                     : load_model_file(path, &m, &warning, nullptr, &info, &file);
    if (!st) return rep.fail(st);
    rep.warn(warning);
    return file.erdz ? erdz_info(path, m, info, file, args) : text_model_info(path, m, file, args);
}

// An image's facts.
static int image_info(const std::string& path, const Image& im, ImageFormat fmt, const Args& args) {
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

static int run_info(const Args& args, const Reporter& rep) {
    const std::string path = args.positional()[0];
    Image im;
    ImageFormat fmt = ImageFormat::unknown;
    if (path != "-") {
        if (model_file(path)) return model_info(path, nullptr, args, rep);
        if (Status st = read_input_image(path, ColourInput::keep, rep, &im, &fmt); !st) return rep.fail(st);
        return image_info(path, im, fmt, args);
    }
    // Standard input is read once, as far as its content goes, and told by its bytes: a model or an image.
    std::string bytes, warning;
    bool more = false;
    if (Status st = read_file(path, &bytes, kMaxInputBytes, model_or_image_framer(ImageLimits()), &more); !st)
        return rep.fail(st);
    if (looks_like_model(bytes.substr(0, 64))) return model_info(path, &bytes, args, rep);
    if (Status st = decode_image_bytes(path, bytes, more, 0, &im, &warning, &fmt); !st) return rep.fail(st);
    rep.warn(warning);
    return image_info(path, im, fmt, args);
}

int cmd_info(int argc, char** argv) { return run_command(kInfo, argc, argv, run_info); }

}  // namespace erd::cli
