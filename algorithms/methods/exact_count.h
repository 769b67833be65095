// Exactly N points from error diffusion (ED, ERDED): the count of a diffusion pass is not
// monotonic in its threshold, so sometimes no threshold gives the wanted count. Each method
// then corrects the nearest pass by a few points of extreme density; the rest of the points are
// the pass as error diffusion made it. Two rules, both kept because outputs depend on them:
//   ED (lower_threshold_to_exact): lower the threshold in small steps until a pass gives at
//     least the count, then drop the surplus of lowest density, ties: the later point first;
//   ERDED (adjust_to_exact): on the nearest pass, drop the least dense points (ties: the earlier
//     point first) or add the densest usable unchosen pixels (ties: row-major order).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"

namespace erd {

// Which of two points of equal density is dropped first (by position in the point list).
enum class DropTies { later_first, earlier_first };

// Removes the size() - k points of lowest density (pixel (x/2, y/2) of density), keeping the
// order of the rest. Returns the number removed (0 when size() <= k).
std::size_t drop_least_dense(const Grid<double>& density, std::size_t k, DropTies ties, std::vector<LatticePoint>* pts);

// Appends up to k - size() pixels of highest density that are neither chosen nor occupied (ties:
// row-major order). Returns the number added.
std::size_t add_densest(const Grid<double>& density, const Grid<std::uint8_t>& occupied, std::size_t k,
                        std::vector<LatticePoint>* pts);

// ED's rule on a threshold search that missed `want`: a pass with more points is trimmed; with
// fewer, rho is lowered by 0.05%, 0.1%, 0.2%, ... (at most 16 passes) until a pass reaches want,
// which is then trimmed. Updates chosen->points, rho, passes and exact; leaves the points alone
// when no pass reaches want (e.g. too little nonzero density). Returns the points removed.
std::size_t lower_threshold_to_exact(const Grid<double>& sigma, std::size_t want, const DiffusionParams& params,
                                     DiffusionResult* chosen);

// ERDED's rule: brings *pts to k points by drop_least_dense (ties: earlier first) or add_densest.
// Returns the number of points added or removed.
std::size_t adjust_to_exact(const Grid<double>& density, const Grid<std::uint8_t>& occupied, std::size_t k,
                            std::vector<LatticePoint>* pts);

}  // namespace erd
