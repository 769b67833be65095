// The checks the fuzz targets share, beyond "no crash": a refusal is one non-empty line with
// Code::input; an image a decoder accepted and a model a reader accepted keep their readers'
// promises. A broken check aborts, which libFuzzer reports as a finding.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/options.h"
#include "algorithms/model/model.h"
#include "imageio/image_format.h"
#include "kernel/predicates.h"
#include "kernel/status.h"

namespace fuzz_checks {

inline void check(bool ok) {
    if (!ok) std::abort();
}

// The kernel targets' input: bytes taken one at a time, zeros past the end.
struct ByteReader {
    const std::uint8_t* data;
    std::size_t size, pos = 0;
    bool more() const { return pos < size; }
    std::uint32_t byte() { return pos < size ? data[pos++] : 0u; }
};

// The generate targets' request, two bytes: the first's bit 7 set -> density (its low 7 bits) + the
// second / 256 percent (may be 0); otherwise N = their 16 bits % (pixels + 8) (may be out of range
// on purpose).
inline void read_target(ByteReader& in, std::int64_t pixels, erd::GenerateOptions* o) {
    const std::uint32_t t0 = in.byte(), t1 = in.byte();
    o->density_given = (t0 & 128) != 0;
    if (o->density_given) o->density = double(t0 & 127) + double(t1) / 256.0;
    else o->points = std::int64_t((t0 << 8) | t1) % (pixels + 8);
}

// The image limits the decoder targets run under: small enough that every allocation stays cheap.
inline erd::imageio::ImageLimits image_limits() {
    erd::imageio::ImageLimits limits;
    limits.max_side = 2048;
    limits.max_pixels = std::int64_t(1) << 18;
    return limits;
}

// A refusal: Code::input with one non-empty line.
inline void check_refusal(const erd::Status& s) {
    check(s.code == erd::Code::input && !s.message.empty() && s.message.find('\n') == std::string::npos);
}

// What an entry point answered: true when it accepted the input; a refusal is checked and false.
inline bool accepted(const erd::Status& s) {
    if (!s.ok()) check_refusal(s);
    return s.ok();
}

// What a method answered a generate target: true when it made a model. A request for a count
// outside [4, W*H] must be refused; any refusal is checked.
inline bool generated(const erd::Status& s, bool count_in_range) {
    if (!count_in_range) check(!s.ok());
    if (!s.ok()) check_refusal(s);
    return s.ok();
}

// A decoded image: within the limits, gray or colour, a sample per pixel and channel, none above
// maxval (which the format's own check narrows).
inline void check_image(const erd::Image& im, const erd::imageio::ImageLimits& limits) {
    check(im.width >= 1 && im.height >= 1 && im.width <= limits.max_side && im.height <= limits.max_side);
    check(std::int64_t(im.width) * im.height <= limits.max_pixels);
    check(im.channels == 1 || im.channels == 3);
    check(im.samples.size() == im.pixels() * std::size_t(im.channels));
    check(im.maxval >= 1 && im.maxval <= 65535);
    for (std::uint16_t v : im.samples) check(v <= im.maxval);
}

// A triangulation read from a file: vertices inside the W x H domain, face indices in range,
// positive faces.
inline void check_mesh(const erd::Model& m) {
    for (const auto& p : m.vertices) check(p.x >= 0 && p.y >= 0 && p.x <= 2 * m.width - 2 && p.y <= 2 * m.height - 2);
    for (const auto& f : m.faces) {
        for (std::uint32_t v : f) check(v < m.vertices.size());
        check(erd::orient2d(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) > 0);
    }
}

// A model: gray or colour, a value per vertex and channel, an ERD model's wedge values per face
// and channel, and check_mesh.
inline void check_model(const erd::Model& m) {
    check(m.channels == 1 || m.channels == 3);
    const std::size_t C = std::size_t(m.channels);
    check(m.width >= 1 && m.height >= 1 && m.values.size() == m.vertices.size() * C);
    check(m.kind != erd::ModelKind::erd || m.corner_values.size() == m.faces.size() * C);
    check_mesh(m);
}

}  // namespace fuzz_checks
