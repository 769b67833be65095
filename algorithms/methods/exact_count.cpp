#include "algorithms/methods/exact_count.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace erd {

namespace {

std::size_t pixel_index(const Grid<double>& g, LatticePoint p) {
    return std::size_t(p.y / 2) * std::size_t(g.width) + std::size_t(p.x / 2);
}

}  // namespace

std::size_t drop_least_dense(const Grid<double>& density, std::size_t k, DropTies ties, std::vector<LatticePoint>* pts) {
    if (pts->size() <= k) return 0;
    std::vector<std::size_t> order(pts->size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    auto d = [&](std::size_t i) { return density.data[pixel_index(density, (*pts)[i])]; };
    const bool later = ties == DropTies::later_first;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (d(a) != d(b)) return d(a) < d(b);
        return later ? a > b : a < b;
    });
    const std::size_t removed = pts->size() - k;
    std::vector<std::uint8_t> drop(pts->size(), 0);
    for (std::size_t i = 0; i < removed; ++i) drop[order[i]] = 1;
    std::vector<LatticePoint> kept;
    kept.reserve(k);
    for (std::size_t i = 0; i < pts->size(); ++i)
        if (!drop[i]) kept.push_back((*pts)[i]);
    *pts = std::move(kept);
    return removed;
}

std::size_t add_densest(const Grid<double>& density, const Grid<std::uint8_t>& occupied, std::size_t k,
                        std::vector<LatticePoint>* pts) {
    if (pts->size() >= k) return 0;
    const std::uint32_t w = std::uint32_t(density.width);
    std::vector<std::uint8_t> taken(density.size(), 0);
    for (LatticePoint p : *pts) taken[pixel_index(density, p)] = 1;
    // The `want` densest free pixels (ties: the lower index first), kept in a heap whose top is
    // the least dense of them: memory for them alone, not a list of every free pixel.
    const auto before = [&](std::uint32_t a, std::uint32_t b) {
        return density.data[a] > density.data[b] || (density.data[a] == density.data[b] && a < b);
    };
    const std::size_t want = k - pts->size();
    std::vector<std::uint32_t> best;
    best.reserve(std::min(want, density.size()));
    for (std::size_t i = 0; i < density.size(); ++i) {
        if (taken[i] || occupied.data[i]) continue;
        const std::uint32_t c = std::uint32_t(i);
        if (best.size() < want) {
            best.push_back(c);
            std::push_heap(best.begin(), best.end(), before);
        } else if (before(c, best.front())) {
            std::pop_heap(best.begin(), best.end(), before);
            best.back() = c;
            std::push_heap(best.begin(), best.end(), before);
        }
    }
    std::sort(best.begin(), best.end(), before);
    for (const std::uint32_t c : best) pts->push_back({std::int32_t(2 * (c % w)), std::int32_t(2 * (c / w))});
    return best.size();
}

std::size_t lower_threshold_to_exact(const Grid<double>& sigma, std::size_t want, const DiffusionParams& params,
                                     DiffusionResult* chosen) {
    std::vector<LatticePoint> pts;
    double rho = chosen->rho;
    bool found = chosen->points.size() > want;
    if (found) pts = chosen->points;
    for (int i = 0; !found && i < 16 && rho > 0.0; ++i) {
        double r = rho * (1.0 - 0.0005 * double(1 << i));
        if (!(r > 0.0)) break;
        ++chosen->passes;
        if (diffuse(sigma, r, params, &pts) >= want) {
            found = true;
            chosen->rho = r;
        }
    }
    if (!found) return 0;
    const std::size_t removed = drop_least_dense(sigma, want, DropTies::later_first, &pts);
    chosen->points = std::move(pts);
    chosen->exact = true;
    return removed;
}

std::size_t adjust_to_exact(const Grid<double>& density, const Grid<std::uint8_t>& occupied, std::size_t k,
                            std::vector<LatticePoint>* pts) {
    if (pts->size() > k) return drop_least_dense(density, k, DropTies::earlier_first, pts);
    return add_densest(density, occupied, k, pts);
}

}  // namespace erd
