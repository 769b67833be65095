// Edge kinds per edge (see edge_kinds.h).
#include "algorithms/model/edge_kinds.h"

#include <string>
#include <utility>

#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd {

std::vector<std::uint8_t> exception_pixels(const Model& m) {
    std::vector<std::uint8_t> mask(std::size_t(m.width) * std::size_t(m.height), 0);
    for (const auto& e : m.kind_exceptions)
        for_each_governed_pixel(m.vertices[e[0]], m.vertices[e[1]], m.width, m.height,
                                [&](int x, int y) { mask[std::size_t(y) * std::size_t(m.width) + std::size_t(x)] = 1; });
    return mask;
}

namespace {

// The discontinuity edges of m as sorted (smaller, larger) vertex pairs.
std::vector<std::array<std::uint32_t, 2>> discontinuities(const Model& m, const ModelTopology& topo) {
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h) {
        const std::uint32_t o = topo.twin[h];
        if (o == kNoHalfEdge || o < h || !is_discontinuity(m, topo, h)) continue;
        const std::uint32_t u = m.faces[h / 3][h % 3], w = m.faces[h / 3][(h + 1) % 3];
        out.push_back({std::min(u, w), std::max(u, w)});
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string pair_name(const std::array<std::uint32_t, 2>& e) {
    return "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]);
}

}  // namespace

Status check_kind_exceptions(const Model& m, const ModelTopology& topo) {
    if (m.kind_exceptions.empty()) return Status::success();
    if (m.kind != ModelKind::erd) return Status::bad_input("a basic model has no edge kinds");
    const std::vector<std::array<std::uint32_t, 2>> disc = discontinuities(m, topo);
    for (std::size_t i = 0; i < m.kind_exceptions.size(); ++i) {
        const auto& e = m.kind_exceptions[i];
        if (e[0] >= e[1] || (i > 0 && !(m.kind_exceptions[i - 1] < e)))
            return Status::bad_input("edge kinds: " + pair_name(e) + " is not in increasing order (or repeats)");
        if (!std::binary_search(disc.begin(), disc.end(), e))
            return Status::bad_input("edge kinds: " + pair_name(e) + " is not a discontinuity of the model");
    }
    return Status::success();
}

Status choose_edge_kinds(const Image& image, Model* m, double* psnr, int threads) {
    m->kind_exceptions.clear();
    Image point, super;
    if (Status s = reconstruct(*m, false, &point, {}, threads); !s) return s;
    if (Status s = reconstruct(*m, true, &super, {}, threads); !s) return s;
    if (point.samples.size() != image.samples.size()) return Status::failure("edge kinds: the model and the image differ in size");
    const std::size_t n = image.pixels(), W = std::size_t(image.width), C = std::size_t(image.channels);
    // A pixel's squared error (over its channels) in one of the reconstructions: computed where
    // needed, so the choice holds no per-pixel array beyond the two images and the final mask.
    const auto sq = [&](const Image& rec, std::size_t i) {
        std::int64_t e = 0;
        for (std::size_t c = 0; c < C; ++c) {
            const std::int64_t d = std::int64_t(image.samples[i * C + c]) - std::int64_t(rec.samples[i * C + c]);
            e += d * d;
        }
        return e;
    };
    std::int64_t sp = 0, ss = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sp += sq(point, i);
        ss += sq(super, i);
    }
    m->edges = sp < ss ? EdgeKind::hard : ss < sp ? EdgeKind::soft : m->edges;
    const Image& own = m->edges == EdgeKind::hard ? point : super;
    const Image& other = m->edges == EdgeKind::hard ? super : point;
    ModelTopology topo;
    if (Status s = build_topology(*m, &topo); !s) return s;
    for (const auto& e : discontinuities(*m, topo)) {
        std::int64_t g = 0;
        for_each_governed_pixel(m->vertices[e[0]], m->vertices[e[1]], m->width, m->height, [&](int x, int y) {
            const std::size_t i = std::size_t(y) * W + std::size_t(x);
            g += sq(own, i) - sq(other, i);
        });
        if (g > 0) m->kind_exceptions.push_back(e);
    }
    const std::vector<std::uint8_t> governed = exception_pixels(*m);
    std::int64_t sse = 0;
    for (std::size_t i = 0; i < n; ++i) sse += sq(governed[i] ? other : own, i);
    *psnr = psnr_of_mse(double(sse) / double(n * C), image.maxval);
    return Status::success();
}

}  // namespace erd
