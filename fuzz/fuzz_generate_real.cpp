// libFuzzer target for the generate pipeline on real-valued images (issue 47): float values over
// any range and offset, nodata holes, gray or colour, every method (the removal methods refuse
// them), --max-error in the data's units. Layout (missing bytes read as 0):
//   byte 0, 1   width, height: 1 + b % 24
//   byte 2      bit 0: 3 channels; bits 1-3: the value scale (1e-7 .. 1e6); bits 4-6: the offset
//   byte 3      nodata: b % 4 = 0 none, 1 pixels whose raw value ends in binary 111, 2 a rectangle
//               (bytes 4-7: x0, y0, x1, y1 modulo the size), 3 every pixel but the first
//   byte 8      method: b % method count
//   byte 9, 10  target as in fuzz_generate.cpp (density or N)
//   byte 11..14 options: edges, flips and moves, --max-error (a multiple of the scale), the slack,
//               the minimax rounds
//   the rest    raw values, two bytes each (a signed 16-bit number), cycled when short
// Checks: any failure is Code::input with a message (never runtime); an image with no valid pixel
// is refused; every model is real and a triangulation of its valid region (check_triangulation;
// the reconstruction has data exactly at the valid pixels, with finite values); when the method reports
// its largest error within --max-error E, the reconstruction's largest error over the valid
// pixels, measured here, is within E too.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/quality_target.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"
#include "fuzz/fuzz_checks.h"

namespace {

using fuzz_checks::check;

constexpr double kScales[8] = {1e-7, 1e-4, 0.01, 0.5, 1.0, 37.25, 1e3, 1e6};
constexpr double kOffsets[8] = {0.0, -1e4, 1e4, -1.0, 0.5, 1e6, -1e6, 123.25};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace erd;
    fuzz_checks::ByteReader in{data, size};
    const int w = int(1 + in.byte() % 24), h = int(1 + in.byte() % 24);
    const std::uint32_t form = in.byte();
    const int channels = (form & 1) ? 3 : 1;
    const double scale = kScales[(form >> 1) & 7], offset = kOffsets[(form >> 4) & 7];
    const std::uint32_t holes = in.byte() % 4;
    const int x0 = int(in.byte()) % w, y0 = int(in.byte()) % h, x1 = int(in.byte()) % w, y1 = int(in.byte()) % h;
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    const MethodInfo& method = table[in.byte() % count];

    GenerateOptions o;
    const std::int64_t pixels = std::int64_t(w) * h;
    fuzz_checks::read_target(in, pixels, &o);
    const std::uint32_t f0 = in.byte(), f1 = in.byte(), f2 = in.byte(), f3 = in.byte();
    o.edges = f0 % 3 == 0 ? EdgeChoice::automatic : f0 % 3 == 1 ? EdgeChoice::soft : EdgeChoice::hard;
    o.flips = int((f0 >> 2) % 3);
    o.moves = int((f0 >> 4) % 3);
    if (f1 & 1) o.max_error = double(f1 >> 1) * scale;  // 0 too
    o.max_slack = 1.0 + double(f2 % 8) / 4.0;
    o.minimax_rounds = int(f3 % 4);
    o.threads = 1 + int((f3 >> 2) & 1);

    // The raw values: signed 16-bit numbers, cycled; NaN marks nodata.
    const std::size_t rest = in.pos < size ? (size - in.pos) / 2 : 0;
    std::vector<double> values(std::size_t(pixels) * std::size_t(channels), 0.0);
    for (std::size_t k = 0; k < values.size(); ++k) {
        std::int16_t raw = 0;
        if (rest > 0) {
            const std::uint8_t* p = data + in.pos + 2 * (k % rest);
            raw = std::int16_t(std::uint16_t(p[0] << 8 | p[1]));
        }
        const std::size_t pixel = k / std::size_t(channels);
        const int x = int(pixel % std::size_t(w)), y = int(pixel / std::size_t(w));
        bool nodata = false;
        if (holes == 1) nodata = (raw & 7) == 7;
        if (holes == 2) nodata = x >= std::min(x0, x1) && x <= std::max(x0, x1) && y >= std::min(y0, y1) && y <= std::max(y0, y1);
        if (holes == 3) nodata = pixel > 0;
        values[k] = nodata ? std::nan("") : offset + scale * double(raw);
    }
    Image image;
    const Status made = make_real_image(w, h, channels, std::move(values), RasterMeta{}, &image);
    if (!fuzz_checks::accepted(made)) return 0;

    const std::int64_t n = target_points(o, w, h);
    const bool in_range = check_target(n, w, h).ok();
    GenerateResult res;
    const Status st = run_method(method, image, o, &res);
    if (!fuzz_checks::generated(st, in_range)) return 0;
    const Model& m = res.model;
    check(m.real && m.width == w && m.height == h && m.channels == channels);
    check(m.holes == image.has_holes());
    check(m.values.size() == m.vertices.size() * std::size_t(channels));
    for (double v : m.values) check(std::isfinite(v));
    check(check_triangulation(m).ok());

    Image rec;
    check(reconstruct(m, false, &rec).ok());
    check(rec.width == w && rec.height == h && rec.real());
    if (image.has_holes()) check(rec.valid == image.valid);
    for (std::size_t i = 0; i < image.pixels(); ++i)
        if (pixel_valid(image, i))
            for (int c = 0; c < channels; ++c) check(std::isfinite(rec.reals[i * std::size_t(channels) + std::size_t(c)]));
    const double reported = res.stats.raster.max_error;
    if (o.max_error >= 0 && reported >= 0 && reported <= o.max_error) {
        double e = -1;
        check(max_abs_error(image, rec, &e).ok());
        check(e <= o.max_error);
    }
    return 0;
}
