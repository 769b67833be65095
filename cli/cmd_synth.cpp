// erd synth [-W 256 -H 256 --bits 8|16 --seed N] -o FILE: a deterministic test image.
#include <cstdio>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>

#include "algorithms/imaging/drawings.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/imaging/synth.h"
#include "algorithms/imaging/synth_dem.h"
#include "cli/outputs.h"
#include "imageio/row_writer.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/image_io.h"

namespace erd::cli {

const CommandLine kSynth = {
    "synth",
    "erd synth [-W 256 -H 256 --bits 8|16 --seed N] [--kind K --blur N] [--type T --solid] -o FILE",
    "Writes a deterministic test image: a smooth ramp and bump, two discs, a triangle and a\n"
    "slanted step with sharp edges, and mild noise; or, with --kind, a hard-edged picture (no\n"
    "anti-aliasing: every edge a step between two pixels), blurred with --blur; or, with --kind dem,\n"
    "an elevation model in metres (relief at six scales, three faults and a mesa with cliffs, lakes\n"
    "and a corner of nodata) written row by row as TIFF (.tif, --type float32 or int16, ...) or PFM\n"
    "(.pfm), so that it may be larger than memory; .png/.pgm get its 16 bits (range onto 0..65535,\n"
    "nodata filled with the nearest height). The same options give the same bytes.",
    {
        {'W', "width", "N", "width in pixels (default 256)"},
        {'H', "height", "N", "height in pixels (default 256)"},
        {0, "bits", "B", "bits per sample, 1..16 (default 8): maxval = 2^B - 1"},
        {0, "seed", "N", "noise seed (default 1); shapes depend on the size only"},
        {0, "no-noise", nullptr, "leave out the noise"},
        {0, "kind", "K", "mixed (default) or a hard-edged picture: drawing, cartoon, screenshot, icons, map, scene, chart, pixelart, cel"},
        {0, "blur", "N", "hard-edged kinds: N passes of the binomial [1 2 1]/4 along x and y (soft edges; default 0)"},
        {0, "type", "T", "--kind dem, TIFF: sample type float32 (default), float64, int16, int32, uint16"},
        {0, "solid", nullptr, "--kind dem: no nodata"},
        {'o', "output", "FILE", "output: .png (8 bits at most) or PGM; \"-\" = stdout"},
        {0, "plain", nullptr, "write plain PGM (P2) instead of raw (P5)"},
    },
    "no messages",
};

namespace {

// The staged temporary of an output as imageio's byte sink.
class FdSink : public imageio::ByteSink {
public:
    explicit FdSink(int fd) : fd_(fd) {}
    bool write_at(std::uint64_t off, const void* data, std::size_t n) override {
        const char* p = static_cast<const char*>(data);
        while (n > 0) {
            const ssize_t k = ::pwrite(fd_, p, n, off_t(off));
            if (k < 0 && errno == EINTR) continue;
            if (k <= 0) return false;
            p += k;
            off += std::uint64_t(k);
            n -= std::size_t(k);
        }
        return true;
    }
    std::size_t read_at(std::uint64_t off, void* data, std::size_t n) override {
        const ssize_t k = ::pread(fd_, data, n, off_t(off));
        return k > 0 ? std::size_t(k) : 0;
    }
    std::uint64_t size() override {
        struct stat st {};
        return ::fstat(fd_, &st) == 0 ? std::uint64_t(st.st_size) : 0;
    }

private:
    int fd_;
};

constexpr int kMaxRowSide = 1 << 20;

// --kind dem: the elevation model (algorithms/imaging/synth_dem.h) row by row.
int synth_dem(const Args& args, const Reporter& rep, int w, int h, std::uint64_t seed) {
    DemParams dp;
    dp.width = w;
    dp.height = h;
    dp.seed = seed;
    dp.holes = !args.has("solid");
    const std::string out = args.str("output");
    const ImageFormat fmt = imageio::format_for_name(out);
    RasterMeta meta;
    meta.type = SampleType::f32;
    if (args.has("type")) {
        const std::string t = args.str("type");
        const SampleType kAll[] = {SampleType::u16, SampleType::u32, SampleType::i16, SampleType::i32, SampleType::f32, SampleType::f64};
        bool found = false;
        for (SampleType k : kAll)
            if (t == sample_type_name(k)) meta.type = k, found = true;
        if (!found) return rep.usage("--type must be float32, float64, int16, int32, uint16 or uint32");
        if (fmt != ImageFormat::tiff) return rep.usage("--type is for a .tif output");
    }
    // A georeferencing of its own: 10 m pixels in UTM zone 33N (EPSG:32633), pixel (0, 0) at
    // (500000, 5200000), as a survey's GeoTIFF has.
    meta.geo.pixel_scale = {10.0, 10.0, 0.0};
    meta.geo.tiepoints = {0.0, 0.0, 0.0, 500000.0, 5200000.0, 0.0};
    meta.geo.keys = {1, 1, 0, 3, 1024, 0, 1, 1, 1025, 0, 1, 1, 3072, 0, 1, 32633};
    if (dp.holes && meta.type != SampleType::f32 && meta.type != SampleType::f64) {
        meta.has_nodata = true;
        meta.nodata = meta.type == SampleType::i16 ? -32768 : meta.type == SampleType::i32 ? -2147483648.0 : 0;
    }
    std::vector<double> row(std::size_t(w) * 1);
    Status st;
    if (fmt == ImageFormat::tiff || fmt == ImageFormat::pfm) {
        Outputs outputs;
        if (!(st = outputs.check({out}, {}))) return rep.fail(st);
        st = outputs.stage_stream(out, [&](int fd) {
            FdSink sink(fd);
            std::unique_ptr<imageio::RowWriter> wr;
            Status s = imageio::open_row_writer(fmt, &sink, w, h, 1, meta, &wr);
            for (int y = 0; s && y < h; ++y) {
                dem_row(dp, y, row.data());
                s = wr->write_row(row.data());
            }
            if (s) s = wr->finish();
            return s ? s : Status::failure(escape_name(out) + ": " + s.message);
        });
        if (!st || !(st = outputs.commit())) return rep.fail(st);
    } else if (fmt == ImageFormat::pgm_raw && !dp.holes && !args.has("plain") && out != "-") {
        // Raw PGM without nodata (--solid): by rows as well, in two passes (the range first), the
        // same bytes as the whole image's 16-bit proxy (real_image.h make_proxy): rasters larger
        // than memory for `erd tiles` (issue 48).
        double lo = INFINITY, hi = -INFINITY;
        for (int y = 0; y < h; ++y) {
            dem_row(dp, y, row.data());
            for (double v : row) lo = std::min(lo, v), hi = std::max(hi, v);
        }
        const double l2 = 0.5 * lo, half_span = 0.5 * hi - l2;
        const double k = half_span > 0 ? 65535.0 / half_span : 0.0;
        Outputs outputs;
        if (!(st = outputs.check({out}, {}))) return rep.fail(st);
        st = outputs.stage_stream(out, [&](int fd) {
            FdSink sink(fd);
            const std::string head = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n65535\n";
            if (!sink.write_at(0, head.data(), head.size())) return Status::failure(escape_name(out) + ": " + std::strerror(errno));
            std::vector<unsigned char> bytes(2 * std::size_t(w));
            for (int y = 0; y < h; ++y) {
                dem_row(dp, y, row.data());
                for (std::size_t x = 0; x < std::size_t(w); ++x) {
                    const double q = (0.5 * row[x] - l2) * k + 0.5;
                    const auto v = std::uint16_t(q > 0 ? (q >= 65535.0 ? 65535.0 : q) : 0.0);
                    bytes[2 * x] = std::uint8_t(v >> 8);
                    bytes[2 * x + 1] = std::uint8_t(v & 0xff);
                }
                if (!sink.write_at(head.size() + std::uint64_t(y) * bytes.size(), bytes.data(), bytes.size()))
                    return Status::failure(escape_name(out) + ": " + std::strerror(errno));
            }
            return Status::success();
        });
        if (!st || !(st = outputs.commit())) return rep.fail(st);
    } else {
        // PNG, PGM: the 16-bit proxy of the whole model (it must be in memory).
        if (w > kMaxImageSide || h > kMaxImageSide || std::int64_t(w) * h > kMaxImagePixels)
            return rep.usage("--kind dem larger than " + std::to_string(kMaxImageSide) + " a side or 2^28 pixels is written by rows: "
                             "to .tif, .pfm or a raw .pgm with --solid");
        std::vector<double> all(std::size_t(w) * std::size_t(h));
        for (int y = 0; y < h; ++y) dem_row(dp, y, all.data() + std::size_t(y) * std::size_t(w));
        Image im;
        if (!(st = make_real_image(w, h, 1, std::move(all), meta, &im))) return rep.fail(st);
        im.reals.clear();  // written as its 16-bit proxy
        im.valid.clear();
        if (!(st = write_image(out, im))) return rep.fail(st);
    }
    if (out != "-") rep.note("wrote " + out + " (" + std::to_string(w) + " x " + std::to_string(h) + ", elevation model)");
    return 0;
}

}  // namespace

static int run_synth(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("missing -o FILE");

    Status st;
    SynthParams p;
    // The elevation model is made by rows: up to 2^20 a side where it is written by rows.
    const int side = args.str("kind") == "dem" ? kMaxRowSide : kMaxImageSide;
    p.width = int(args.integer("width", 256, 1, side, &st));
    p.height = int(args.integer("height", 256, 1, side, &st));
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
    if (kind == "dem") return synth_dem(args, rep, p.width, p.height, p.seed);
    if (args.has("type") || args.has("solid")) return rep.usage("--type and --solid are for --kind dem");

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
