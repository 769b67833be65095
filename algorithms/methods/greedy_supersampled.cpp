// The 4x4-supersampled approximation greedy refinement measures errors against
// (GreedyOptions::supersampled, the thesis's ERDGPI): each face's plane painted at the sub-samples
// it owns, and the border lines' and corners' values that reconstruction clamps sub-samples onto.
#include "algorithms/methods/greedy_refiner.h"

#include <cstddef>
#include <cstdint>

namespace erd {

void GreedyRefiner::paint(FaceInd f) {
    const LatticePoint a = cdt_.point(cdt_.face_vertex(f, 0)), b = cdt_.point(cdt_.face_vertex(f, 1)),
                       c = cdt_.point(cdt_.face_vertex(f, 2));
    const SpanPlane plane = model_.face_plane(cdt_, f);
    const Lattice sub = Lattice::supersample();
    const std::size_t sw = 4 * std::size_t(image_.width);
    scan_triangle(sub, domain_, a, b, c, &spans_);
    const double dv = plane.step_x(sub);
    for (const Span& sp : spans_) {
        float* row = &sub_[std::size_t(sp.y) * sw];
        double v = plane.at(sub, sp.x_begin, sp.y);
        for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i, v += dv) row[i] = float(v);
        touched_.push_back({sp.y >> 2, sp.x_begin >> 2, sp.x_end >> 2});
    }
    // The border lines (as algorithms/model/reconstruct.cpp clamps onto them) and the corners.
    const std::int32_t mx = domain_.max_x, my = domain_.max_y;
    const auto touches_x = [&](std::int32_t x) { return a.x == x || b.x == x || c.x == x; };
    const auto touches_y = [&](std::int32_t y) { return a.y == y || b.y == y || c.y == y; };
    const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
    if (touches_x(0) || touches_x(mx)) {
        const Lattice cols{4, 4 * mx, 2, 0, -3};
        scan_triangle(cols, domain_, a, b, c, &spans_);
        for (const Span& sp : spans_)
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i) {
                (i == 0 ? left_ : right_)[std::size_t(sp.y)] = float(plane.at(cols, i, sp.y));
                const std::int32_t x = i == 0 ? 0 : last_x;
                touched_.push_back({sp.y >> 2, x, x});
            }
    }
    if (touches_y(0) || touches_y(my)) {
        const Lattice rows{4, 2, 4 * my, -3, 0};
        scan_triangle(rows, domain_, a, b, c, &spans_);
        for (const Span& sp : spans_) {
            float* line = sp.y == 0 ? top_.data() : bottom_.data();
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i) line[i] = float(plane.at(rows, i, sp.y));
            touched_.push_back({sp.y == 0 ? 0 : last_y, sp.x_begin >> 2, sp.x_end >> 2});
        }
    }
    // A corner (always a vertex) takes the plane of the face owning its pixel: its value in
    // that face (reconstruction: the mean of its wedges, which differs only when an edge
    // constraint ends at the corner).
    for (int k = 0; k < 4; ++k) {
        const std::int32_t i = (k & 1) ? last_x : 0, j = (k & 2) ? last_y : 0;
        if (triangle_owns(Lattice::pixels(), domain_, a, b, c, i, j)) {
            corner_[k] = plane.at(double(2 * i), double(2 * j));
            touched_.push_back({j, i, i});
        }
    }
}

double GreedyRefiner::border_sum(std::int32_t x, std::int32_t y) const {
    const std::size_t sw = 4 * std::size_t(image_.width);
    const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
    double s = 0;
    for (int l = 0; l < 4; ++l) {
        const std::int32_t jy = 4 * y + l;
        const bool out_y = (y == 0 && l < 2) || (y == last_y && l >= 2);
        const float* row = &sub_[std::size_t(jy) * sw + 4 * std::size_t(x)];
        for (int k = 0; k < 4; ++k) {
            const std::int32_t ix = 4 * x + k;
            const bool out_x = (x == 0 && k < 2) || (x == last_x && k >= 2);
            if (out_x && out_y) s += corner_[(x == 0 ? 0 : 1) + (y == 0 ? 0 : 2)];
            else if (out_x) s += (x == 0 ? left_ : right_)[std::size_t(jy)];
            else if (out_y) s += (y == 0 ? top_ : bottom_)[std::size_t(ix)];
            else s += row[k];
        }
    }
    return s;
}

}  // namespace erd
