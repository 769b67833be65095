// LatticePoint: a point of the doubled integer lattice, the kernel's only coordinate type.
//
// Doubled coordinates: X = 2x, Y = 2y for a pixel position (x, y), so the half-pixel lattice of the
// ERD model (thesis 3.3) is all integer points and the basic model's integer lattice is the even
// points. Bounds are the predicates' (kernel/predicates.h).
#pragma once
#include <cstdint>

namespace erd {

struct LatticePoint {
    std::int32_t x = 0;  // doubled
    std::int32_t y = 0;  // doubled
    friend bool operator==(LatticePoint a, LatticePoint b) { return a.x == b.x && a.y == b.y; }
    friend bool operator!=(LatticePoint a, LatticePoint b) { return !(a == b); }
};

}  // namespace erd
