// libFuzzer target for the whole generate pipeline (algorithms/methods/methods.h), on tiny images
// made from the input bytes. Layout (missing bytes read as 0):
//   byte 0, 1   width, height: 1 + b % 24
//   byte 2, 3   maxval: 1 + (b2 << 8 | b3) % 65535
//   byte 4      method: b % method count
//   byte 5, 6   target: b5 bit 7 set -> density (b5 & 127) + b6 / 256 percent (may be 0);
//               otherwise N = (b5 << 8 | b6) % (W*H + 8) (may be out of range on purpose)
//   byte 7..12  the other options within the ranges `erd generate` accepts (beta, ratio, l,
//               epsilon, -S, -w, -s, -B, -f, seed, wedge fit, --max-error, --psnr)
//   the rest    samples (two bytes each when maxval > 255), reduced modulo maxval + 1; cycled
//               when short, zero when there are none.
// Checks: a request with N outside [4, W*H] fails with Code::input; any other failure must be
// Code::input too (never runtime). Every returned model matches the image size, holds the four
// corners, is a triangulation of the domain (check_triangulation), and is exactly the (C)DT the
// kernel builds from its vertices and constraints (rebuilt Cdt passes verify() and has the same
// faces); point and supersampled reconstruction succeed and stay within [0, maxval]; a constant
// image is reproduced exactly.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "api/erd.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/quality_target.h"
#include "algorithms/model/reconstruct.h"
#include "fuzz/fuzz_checks.h"
#include "kernel/cdt.h"

namespace {

using fuzz_checks::check;

void check_model(const erd::Image& image, const erd::GenerateResult& res) {
    using namespace erd;
    const Model& m = res.model;
    check(m.width == image.width && m.height == image.height && m.maxval == image.maxval);
    check(res.achieved == m.vertices.size());
    check(m.values.size() == m.vertices.size());
    check(check_triangulation(m).ok());
    const std::int32_t mx = 2 * (image.width - 1), my = 2 * (image.height - 1);
    for (LatticePoint c : {LatticePoint{0, 0}, LatticePoint{mx, 0}, LatticePoint{mx, my}, LatticePoint{0, my}})
        check(std::find(m.vertices.begin(), m.vertices.end(), c) != m.vertices.end());
    for (LatticePoint p : m.vertices) {
        check(p.x >= 0 && p.x <= mx && p.y >= 0 && p.y <= my);
        if (m.kind == ModelKind::basic) check(p.x % 2 == 0 && p.y % 2 == 0);
    }
    if (m.kind == ModelKind::erd) check(m.corner_values.size() == m.faces.size());

    // The kernel, given the same vertices and constraints, builds the same triangulation (after
    // the flips that the ERD methods' data-dependent flips made: api::triangulate restores them).
    Cdt cdt;
    check(api::triangulate(m, &cdt).ok());
    std::string why;
    check(cdt.verify_topology(&why));
    check(cdt.vertex_count() == m.vertices.size());
    check(cdt.face_count() == m.faces.size());
    check(canonical_faces(cdt) == canonical_faces(m.vertices, m.faces));

    bool constant = true;
    for (std::uint16_t s : image.samples) constant = constant && s == image.samples[0];
    for (bool super : {false, true}) {
        Image rec;
        check(reconstruct(m, super, &rec).ok());
        check(rec.width == image.width && rec.height == image.height && rec.maxval == image.maxval);
        check(rec.samples.size() == image.samples.size());
        for (std::uint16_t s : rec.samples) check(s <= image.maxval);
        if (constant) check(rec.samples == image.samples);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace erd;
    fuzz_checks::ByteReader in{data, size};
    Image image;
    image.width = int(1 + in.byte() % 24);
    image.height = int(1 + in.byte() % 24);
    const std::uint32_t hi = in.byte();
    image.maxval = 1 + ((hi << 8) | in.byte()) % 65535;
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    const MethodInfo& method = table[in.byte() % count];

    GenerateOptions o;
    const std::int64_t pixels = std::int64_t(image.width) * image.height;
    fuzz_checks::read_target(in, pixels, &o);
    const std::uint32_t f0 = in.byte(), f1 = in.byte(), f2 = in.byte(), f3 = in.byte(), f4 = in.byte(),
                        f5 = in.byte();
    if (f0 != 0) o.beta = double(f0) / 256.0;                   // (0, 1)
    if (f1 & 1) o.ratio = double(1 + (f1 >> 1)) / 128.0;        // (0, 1]
    if (f1 & 2) o.min_length = int(1 + (f1 >> 2) % 16);
    if (f2 & 1) o.epsilon = double(f2 >> 1) / 32.0;            // [0, 4)
    o.simple = int(f2 >> 6) % 3 - 1;                            // -1, 0, 1
    o.wedge_rule = int(f3 & 1);
    o.wedge_order = int(1 + 2 * ((f3 >> 1) % 16));              // 1, 3, ..., 31
    o.startup = int((f3 >> 5) % 3);
    o.ed_select = int(f4 & 1);
    o.seed = f4 >> 1;
    o.wedge_fit = int(f5 % 9);
    if (f5 & 16) o.max_error = double(f5 >> 5) * 8.0;
    if (f5 & 32) o.psnr = 20.0 + double(f5 >> 6) * 10.0;
    o.round_values = (f5 & 64) == 0;

    const std::size_t bytes_per = image.maxval > 255 ? 2 : 1;
    const std::size_t rest = in.pos < size ? size - in.pos : 0;
    image.samples.assign(std::size_t(pixels), 0);
    if (rest >= bytes_per) {
        const std::size_t avail = rest / bytes_per;
        for (std::size_t i = 0; i < image.samples.size(); ++i) {
            const std::uint8_t* p = data + in.pos + (i % avail) * bytes_per;
            const std::uint32_t v = bytes_per == 2 ? (std::uint32_t(p[0]) << 8 | p[1]) : p[0];
            image.samples[i] = std::uint16_t(v % (image.maxval + 1));
        }
    }

    const std::int64_t n = target_points(o, image.width, image.height);
    const bool in_range = check_target(n, image.width, image.height).ok();
    GenerateResult res;
    const Status st = run_method(method, image, o, &res);  // --psnr / --max-error: the count searched
    if (!fuzz_checks::generated(st, in_range)) return 0;
    if (res.stats.has_quality) {
        const QualitySearchStats& q = res.stats.quality;
        check(res.requested <= std::size_t(n) && res.requested >= 4);
        if (q.reached) check((o.psnr <= 0 || q.psnr >= o.psnr) && (o.max_error < 0 || q.max_error <= o.max_error));
    } else {
        check(res.requested == std::size_t(n));
    }
    check_model(image, res);
    return 0;
}
