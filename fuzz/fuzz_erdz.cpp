// libFuzzer target for the .erdz decoder (algorithms/codec/erdz.h) and reconstruction of what it
// accepts.
//
// Checks beyond "no crash": a refusal is one non-empty line with Code::input; an accepted model
// keeps the decoder's promises (indices in range, positive faces, the vertices sorted by (y, x)
// inside the image, values and corner values per channel); reconstruct() accepts it and returns
// a W x H image of its channels; and it survives encode -> decode unchanged (same vertices and values, the same
// faces with the same corner values). Images above 2^16 pixels are refused by the limit.
// Replay without libFuzzer: fuzz/replay.cpp.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/model/reconstruct.h"
#include "fuzz/fuzz_checks.h"

namespace {

// The decoder's promises beyond a model's: at least 2 x 2, the vertices sorted by (y, x).
void check_model(const erd::Model& m) {
    fuzz_checks::check_model(m);
    if (m.width < 2 || m.height < 2) std::abort();
    for (std::size_t i = 1; i < m.vertices.size(); ++i) {
        const erd::LatticePoint p = m.vertices[i], q = m.vertices[i - 1];
        if (!(q.y < p.y || (q.y == p.y && q.x < p.x))) std::abort();
    }
}

// Faces with their corner values, each rotated to start at its smallest vertex, sorted.
std::vector<std::array<double, 6>> face_set(const erd::Model& m) {
    std::vector<std::array<double, 6>> out;
    const std::size_t C = std::size_t(m.channels);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& v = m.faces[f];
        const std::size_t r = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
        std::array<double, 6> e{};
        for (std::size_t k = 0; k < 3; ++k) {
            e[k] = double(v[(r + k) % 3]);
            if (m.kind == erd::ModelKind::erd)
                for (std::size_t c = 0; c < C; ++c) e[3 + k] += m.corner_values[f * C + c][(r + k) % 3] * double(c + 1);
        }
        out.push_back(e);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 1 << 16) return 0;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    erd::ErdzLimits limits;
    limits.max_pixels = std::uint64_t(1) << 16;
    erd::Model m;
    erd::ErdzInfo info;
    erd::Status s = erd::decode_erdz(bytes, &m, &info, limits);
    if (!fuzz_checks::accepted(s)) return 0;
    check_model(m);
    erd::Image im;
    if (!erd::reconstruct(m, erd::supersampled(m), &im).ok()) std::abort();
    if (im.width != m.width || im.height != m.height || im.channels != m.channels) std::abort();
    erd::ErdzOptions o;
    o.step = info.step;
    o.method = info.method;
    std::string again;
    if (!erd::encode_erdz(m, o, &again).ok()) std::abort();
    erd::Model r;
    if (!erd::decode_erdz(again, &r, nullptr, limits).ok()) std::abort();
    if (r.vertices != m.vertices || r.values != m.values || r.kind != m.kind || r.edges != m.edges ||
        r.channels != m.channels || face_set(r) != face_set(m) || r.kind_exceptions != m.kind_exceptions)
        std::abort();
    return 0;
}
