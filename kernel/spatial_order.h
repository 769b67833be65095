// Spatial ordering of point batches for insertion: Hilbert curve indices and the BRIO order
// (biased randomised insertion order) that Cdt::insert_points inserts a batch in.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/predicates.h"

namespace erd {

/// Index of (x, y) along a Hilbert curve filling [0, 2^order)^2, 1 <= order <= 31 and x, y < 2^order.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int order);

/// Fills *order with 0..pts.size()-1, the indices of pts in BRIO order (Amenta, Choi, Rote):
/// rounds of doubling size (64, 64, 128, 256, ...) drawn by a fixed-seed shuffle, each round in
/// Hilbert order over [0, 2^bits)^2 (every coordinate of pts must lie in [0, 2^bits)); ties keep
/// the shuffled order. Deterministic. *tmp is scratch; both buffers are reused across calls.
void brio_order(const std::vector<LatticePoint>& pts, int bits, std::vector<std::uint64_t>* order,
                std::vector<std::uint64_t>* tmp);

}  // namespace erd
