// Comparing two Cdts whatever their vertex numbering, for the kernel's tests and fuzz targets.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/cdt.h"
#include "kernel/predicates.h"

namespace cdt_util {

// The constrained edges as sorted coordinate quadruples, each edge's ends in the perturbation's order.
inline std::vector<std::array<std::int32_t, 4>> constraint_coords(const erd::Cdt& cdt) {
    std::vector<std::array<erd::VertInd, 2>> c;
    cdt.export_constraints(&c);
    std::vector<std::array<std::int32_t, 4>> out;
    for (const auto& e : c) {
        erd::LatticePoint a = cdt.point(e[0]), b = cdt.point(e[1]);
        if (erd::perturb_before(b, a)) std::swap(a, b);
        out.push_back({a.x, a.y, b.x, b.y});
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace cdt_util
