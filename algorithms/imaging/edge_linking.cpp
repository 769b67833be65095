#include "algorithms/imaging/edge_linking.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace erd {

using namespace edge_flags;

std::size_t hysteresis(StrongPoints* sp, bool labels) {
    if (labels) sp->label.assign(sp->size(), 0);
    std::vector<std::uint32_t> stack;
    std::uint32_t component = 0;
    for (const std::uint32_t s : sp->seeds) {
        if (sp->flag[s] & kMain) continue;
        sp->flag[s] |= kMain;
        stack.push_back(s);
        ++component;
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            sp->mains.push_back(i);
            if (labels) sp->label[i] = component;
            std::uint32_t nb[8];
            sp->ring(i, nb);
            for (const std::uint32_t j : nb) {
                if (j != kNoPoint && (sp->flag[j] & (kCandidate | kMain)) == kCandidate) {
                    sp->flag[j] |= kMain;
                    stack.push_back(j);
                }
            }
        }
    }
    return sp->mains.size();
}

// Step 5, Ding-Goshtasby: join different main components through short secondary paths. A
// multi-source breadth-first search from every main point over secondary-only points labels each
// reached point with its nearest main component; where two labels meet, the two parent chains
// back to their sources are the shortest secondary link between those components. Returns the
// number of points added. The search starts from hysteresis's mains in their order (component by
// component, each in the order grown), which is the order a labelling pass over them would find.
std::size_t join_components(StrongPoints* sp, int max_link, float tl) {
    const std::size_t n = sp->size();
    std::vector<std::uint8_t>& flag = sp->flag;
    std::vector<std::uint32_t>& label = sp->label;  // main component, 0 = unreached
    // dist and back are read only at labelled points: set for the sources below, and for a
    // reached point when it is reached, so neither is initialised. back[j] is the direction
    // (point_rings.h order) from j to the point it was reached from: a byte instead of an index.
    std::unique_ptr<std::uint8_t[]> dist(new std::uint8_t[n]);
    std::unique_ptr<std::uint8_t[]> back(new std::uint8_t[n]);
    // The queue is the mains themselves, followed by the secondary points as they are reached
    // (cut off again after the search).
    std::vector<std::uint32_t>& queue = sp->mains;
    const std::size_t sources = queue.size();
    for (const std::uint32_t i : queue) dist[i] = 0;
    // p has the smaller label; the pair's key is the two labels (read back when sorting).
    struct Meeting { std::uint32_t p, q; };
    std::vector<Meeting> meetings;
    const std::uint8_t limit = std::uint8_t(max_link);
    // Every main point is taken from the queue before any reached point, and claims each free
    // secondary neighbour; so with limit >= 2 a point reached at distance `limit` is next to no
    // main point of another component and could only meet one (a meeting needs the two
    // distances to sum to at most limit): it would find no meeting and reach nothing further,
    // and is not labelled at all. This outermost shell is the largest.
    const std::uint8_t reach = limit >= 2 ? std::uint8_t(limit - 1) : limit;
    // The number of main neighbours of each main point, for the climbs below: counted here from
    // the rings the search reads anyway, and kept up to date as points become main (one ring
    // per added point instead of one per main point). Kept in `back`, which is read only at
    // points that are not main (a chain ends at the first main point).
    std::uint8_t* main_nb = back.get();
    auto became_main = [&](std::uint32_t i) {
        std::uint32_t nb[8];
        sp->ring(i, nb);
        for (const std::uint32_t j : nb)
            if (j != kNoPoint && (flag[j] & kMain)) ++main_nb[j];
    };
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t i = queue[head];
        const std::uint32_t li = label[i];
        const std::uint8_t di = dist[i];
        std::uint32_t nb[8];
        sp->ring(i, nb);
        std::uint8_t mains_around = 0;  // kept for sources only (main_nb below)
        for (int d = 0; d < 8; ++d) {
            const std::uint32_t j = nb[d];
            if (j == kNoPoint) continue;
            const std::uint8_t fj = flag[j];
            mains_around = std::uint8_t(mains_around + ((fj & kMain) != 0));
            const std::uint32_t lj = label[j];
            if (lj == 0) {
                if (di < reach && (fj & (kSecondary | kMain)) == kSecondary) {
                    label[j] = li;
                    dist[j] = std::uint8_t(di + 1);
                    back[j] = std::uint8_t((d + 4) & 7);
                    queue.push_back(j);
                }
            } else if (lj != li && std::uint32_t(di) + dist[j] <= limit) {
                if (li < lj) meetings.push_back({i, j});
                else meetings.push_back({j, i});
            }
        }
        // After the ring: back[j] was set above only at secondary points, never at a source.
        if (head < sources) main_nb[i] = mains_around;
    }
    queue.resize(sources);
    // One link per pair of components: the first found, i.e. (nearly) the shortest.
    std::size_t added = 0;
    auto key = [&](const Meeting& m) { return (std::uint64_t(label[m.p]) << 32) | label[m.q]; };
    std::stable_sort(meetings.begin(), meetings.end(), [&](const Meeting& a, const Meeting& c) { return key(a) < key(c); });
    for (std::size_t k = 0; k < meetings.size(); ++k) {
        if (k > 0 && key(meetings[k]) == key(meetings[k - 1])) continue;
        for (std::uint32_t i : {meetings[k].p, meetings[k].q})
            while (!(flag[i] & kMain)) {  // a reached point: its chain ends at a main point
                flag[i] |= kMain;
                became_main(i);
                sp->mains.push_back(i);
                ++added;
                i = sp->points->neighbour(i, back[i]);
            }
    }

    // Where an edge runs into a stronger one (the stem of a T), the last points before the
    // junction lie on the flank of the stronger edge and are maxima in no direction, so no
    // secondary path exists. From each end of a main curve, climb the magnitude (strictly
    // increasing, >= tau_low, at most max_link points) and keep the climb if it arrives next
    // to a different main component. Only strong points can be climbed to: the climb starts at
    // g >= tau_low and only rises.
    std::vector<std::uint32_t> path;
    for (std::size_t s = 0; s < sources; ++s) {
        const std::uint32_t end = sp->mains[s];  // the climbs below append to mains
        if (main_nb[end] != 1) continue;
        std::uint32_t nb[8];
        const std::uint32_t own = label[end];
        path.clear();
        std::uint32_t cur = end;
        bool joined = false;
        for (int step = 0; step <= max_link && !joined; ++step) {
            sp->ring(cur, nb);
            for (const std::uint32_t j : nb)
                if (j != kNoPoint && (flag[j] & kMain) && label[j] != own && label[j] != 0) joined = true;
            if (joined || step == max_link) break;
            std::uint32_t best = kNoPoint;
            float bg = sp->mag[cur];
            for (const std::uint32_t j : nb) {
                if (j == kNoPoint || (flag[j] & kMain)) continue;
                if (sp->mag[j] > bg && sp->mag[j] >= tl) { bg = sp->mag[j]; best = j; }
            }
            if (best == kNoPoint) break;
            path.push_back(best);
            cur = best;
        }
        if (!joined || path.empty()) continue;
        for (const std::uint32_t i : path) {
            flag[i] |= kMain;
            became_main(i);
            label[i] = own;
            sp->mains.push_back(i);
            ++added;
        }
    }
    return added;
}

}  // namespace erd
