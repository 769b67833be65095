// The checks of check_triangulation (reconstruct.h) and the face planes (prepared_model.h).
#include "algorithms/model/prepared_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/predicates.h"

namespace erd {
namespace {

Status not_triangulation(const std::string& why) {
    return Status::bad_input("not a triangulation of the image domain: " + why);
}

std::string pt(LatticePoint p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

}  // namespace

Status prepare_model(const Model& m, bool count_pixels, const ModelTopology* given, PreparedModel* p) {
    if (m.width < 2 || m.height < 2 || m.width > kMaxImageSide || m.height > kMaxImageSide)
        return Status::bad_input("image size " + std::to_string(m.width) + " x " + std::to_string(m.height) +
                                 " out of range (2.." + std::to_string(kMaxImageSide) + " a side)");
    if (std::int64_t(m.width) * m.height > kMaxImagePixels)
        return Status::bad_input("image " + std::to_string(m.width) + " x " + std::to_string(m.height) + " is larger than the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    if (m.real) {
        if (!std::isfinite(m.lo) || !std::isfinite(m.hi) || m.lo > m.hi) return Status::bad_input("model's value range is not a finite lo <= hi");
    } else if (m.maxval < 1 || m.maxval > 65535) {
        return Status::bad_input("maxval " + std::to_string(m.maxval) + " out of range (1..65535)");
    }
    if (m.channels != 1 && m.channels != 3)
        return Status::bad_input("model has " + std::to_string(m.channels) + " channels (1 or 3)");
    const std::size_t nv = m.vertices.size(), nf = m.faces.size(), C = std::size_t(m.channels);
    if (m.values.size() != nv * C)
        return Status::bad_input("model has " + std::to_string(m.values.size()) + " values for " + std::to_string(nv) + " vertices" +
                                 (C > 1 ? " in " + std::to_string(C) + " channels" : ""));
    const bool erd = m.kind == ModelKind::erd;
    if (erd && m.corner_values.size() != nf * C)
        return Status::bad_input("ERD model has corner values for " + std::to_string(m.corner_values.size()) + " of " +
                                 std::to_string(nf * C) + (C > 1 ? " face channels" : " faces"));
    for (double z : m.values)
        if (!std::isfinite(z)) return Status::bad_input("model has a vertex value that is not a finite number");
    if (erd)
        for (const auto& c : m.corner_values)
            for (double z : c)
                if (!std::isfinite(z)) return Status::bad_input("model has a wedge value that is not a finite number");
    const RasterDomain dom{2 * m.width - 2, 2 * m.height - 2};
    p->dom = dom;
    for (std::size_t v = 0; v < nv; ++v) {
        const LatticePoint q = m.vertices[v];
        if (q.x < 0 || q.y < 0 || q.x > dom.max_x || q.y > dom.max_y)
            return not_triangulation("vertex " + std::to_string(v) + " " + pt(q) + " lies outside the domain");
    }
    if (given && given->twin.size() == 3 * nf && given->corner_begin.size() == nv + 1) {
        p->topo = given;
    } else {
        if (Status s = build_topology(m, &p->own); !s) return not_triangulation(s.message);
        p->topo = &p->own;
    }
    const ModelTopology& topo = *p->topo;
    // Areas (twice, doubled coordinates) must add up to the rectangle's.
    const std::int64_t target = 2 * std::int64_t(dom.max_x) * dom.max_y;
    std::int64_t area = 0;
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m.faces[f];
        const std::int64_t o = orient2d(m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]]);
        if (o <= 0) return not_triangulation("face " + std::to_string(f) + (o == 0 ? " is degenerate" : " is not positively oriented"));
        area += o;
        if (area > target) return not_triangulation("the faces overlap (their areas add up to more than the rectangle)");
    }
    // A model with nodata leaves holes where the image has no data (model.h has_holes); its faces
    // must still not overlap, which the paired edges below and the pixel count check locally.
    const bool holes = has_holes(m);
    if (area != target && !holes) return not_triangulation("the faces leave holes (their areas add up to less than the rectangle)");
    const auto on_border_line = [&](LatticePoint a, LatticePoint b) {
        return (a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) || (a.x == dom.max_x && b.x == dom.max_x) ||
               (a.y == dom.max_y && b.y == dom.max_y);
    };
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h) {
        if (topo.twin[h] != kNoHalfEdge || holes) continue;
        const std::uint32_t u = m.faces[h / 3][h % 3], w = m.faces[h / 3][(h + 1) % 3];
        if (!on_border_line(m.vertices[u], m.vertices[w]))
            return not_triangulation("edge " + std::to_string(u) + "-" + std::to_string(w) + " of face " + std::to_string(h / 3) +
                                     " has no neighbouring face but is not on the border");
    }
    // Positive faces inside the rectangle, areas adding up to it, edges paired up and unpaired
    // edges on the border: a triangulation, so every lattice point has exactly one owner
    // (kernel/raster.h). check_triangulation() counts the pixels all the same.
    if (count_pixels) {
        std::vector<std::uint8_t> owned(std::size_t(m.width) * std::size_t(m.height), 0);
        std::vector<Span> spans;
        for (const auto& fc : m.faces) {
            scan_triangle(Lattice::pixels(), dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
            for (const Span& s : spans) {
                std::uint8_t* row = owned.data() + std::size_t(s.y) * std::size_t(m.width);
                for (std::int32_t x = s.x_begin; x <= s.x_end; ++x) row[x] = std::uint8_t(std::min(row[x] + 1, 2));
            }
        }
        for (std::size_t i = 0; i < owned.size(); ++i)
            if (owned[i] != 1 && !(holes && owned[i] == 0))
                return not_triangulation("pixel (" + std::to_string(i % std::size_t(m.width)) + ", " +
                                         std::to_string(i / std::size_t(m.width)) + ") is owned by " +
                                         (owned[i] == 0 ? "no face" : "several faces"));
    }
    p->planes.resize(nf * C);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& fc = m.faces[f];
        const std::uint32_t h = std::uint32_t(3 * f);
        for (std::size_t c = 0; c < C; ++c) {
            const int k = int(c);
            p->planes[f * C + c].set(m.vertices[fc[0]], corner_value(m, h, k), m.vertices[fc[1]], corner_value(m, h + 1, k),
                                     m.vertices[fc[2]], corner_value(m, h + 2, k));
        }
    }
    return Status::success();
}

}  // namespace erd
