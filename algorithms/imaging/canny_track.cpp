// Steps 2 and 4 to 6 of edge detection, read from a gradient pass (canny_pass.h): the thresholds,
// hysteresis and the junction repair of the modification, and thinning.
#include "algorithms/imaging/canny_pass.h"

#include <cstddef>
#include <utility>
#include <vector>

#include "algorithms/imaging/edge_linking.h"
#include "algorithms/imaging/float_bins.h"
#include "algorithms/imaging/thinning.h"

namespace erd {

using namespace edge_flags;
using namespace canny_detail;

bool EdgeDetector::Pass::track(const CannyParams& params, bool release, SortedPoints* edges, CannyStats* stats) {
    if (params.smoothing_order != smoothing_order || params.border != border) return false;
    const std::size_t M = std::size_t(pl.w) * std::size_t(pl.h);
    const std::size_t k_high = k_of(params.beta, M);
    if (at_or_above_floor < k_high) return false;  // the k-th largest is below the counted bins

    // 2. Thresholds: the bin of the k-th largest, then selection inside it. Every value in that
    // bin was at or above the bound of its time, so the kept points hold them all; bin 0 aside,
    // where only g = 0 is missing (never kept) and hist counts all of the bin.
    std::size_t above = 0, above_high = 0;
    const std::uint32_t bin = kth_bin(hist.data(), hist.size(), k_high, &above, hist_base);
    std::vector<float> in_bin;
    in_bin.reserve(count(bin));
    const std::size_t n = kept.size();
    const float* g = mag.data();
    for_each_at_least(g, n, bin_floor(bin), [&](std::size_t k) {
        if (float_bin(g[k]) == bin) in_bin.push_back(g[k]);
    });
    if (bin == 0) in_bin.resize(count(0), 0.0f);
    const double tau_high = select_in_bin(&in_bin, k_high, above, &above_high);
    const double tau_low = params.r * tau_high;
    std::vector<float>().swap(in_bin);
    const float th = float(tau_high), tl = float(tau_low);
    if (tl < low) return false;  // strong points may be missing

    // The kept points with g >= tau_low are the strong points, with the pass's flags this
    // detection uses; the others have none. Every point loses the last detection's flags.
    StrongPoints sp(kept);
    sp.mag = g;
    sp.flag = flag.data();
    const std::uint8_t used = params.modified ? std::uint8_t(kCandidate | kSecondary) : std::uint8_t(kCandidate);
    std::uint8_t* f = flag.data();
    std::size_t flagged = 0;
    kept.for_each([&](std::uint32_t k, std::uint32_t p) {
        std::uint8_t fk = std::uint8_t(f[k] & kPassFlags);
        if (g[k] >= tl) {
            fk = std::uint8_t(fk | ((fk >> kPassShift) & used));
            flagged += (fk & used) != 0;
            if ((fk & kCandidate) && g[k] >= th) sp.seeds.push_back(p);
        }
        f[k] = fk;
    });

    // 4, 5. The search's queue holds every point it labels: the flagged points at most (room
    // for them up front: no copy while it grows; pages it never fills cost nothing).
    const bool join = params.modified && params.max_link > 0;
    if (join) sp.mains.reserve(flagged);
    const std::size_t main_points = hysteresis(&sp);
    const std::size_t added = join ? join_components(&sp, params.max_link, tl) : 0;

    // 6. The main points, in row-major order, thinned as a sparse set.
    const std::size_t main_count = main_points + added;
    sp = StrongPoints(kept);  // the search's queue goes before the list is made
    SortedPoints mains;
    mains.stride = pl.stride;
    mains.at.reserve(main_count);
    kept.for_each([&](std::uint32_t k, std::uint32_t p) {
        if (f[k] & kMain) mains.at.push_back(p);
    });
    if (release) clear();
    if (params.thin) {
        std::vector<std::uint8_t> alive(mains.size(), 1);
        mains.link_rows();
        thin_points(mains, &alive);
        std::size_t kept_n = 0;  // the survivors, in place: not a second list beside the first
        for (std::size_t k = 0; k < mains.size(); ++k)
            if (alive[k]) mains.at[kept_n++] = mains.at[k];
        mains.at.resize(kept_n);
    }
    *edges = SortedPoints();
    edges->stride = pl.stride;
    edges->at = std::move(mains.at);
    const std::size_t edge_points = edges->size();
    if (stats) {
        stats->tau_high = tau_high;
        stats->tau_low = tau_low;
        stats->above_high = above_high;
        stats->main_points = main_points;
        stats->added_points = added;
        stats->edge_points = edge_points;
    }
    return true;
}

void EdgeDetector::Pass::clear() {
    kept.clear();
    mag.reset();
    flag.reset();
}

}  // namespace erd
