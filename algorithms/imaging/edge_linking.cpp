#include "algorithms/imaging/edge_linking.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace erd {

using namespace edge_flags;

namespace {

inline unsigned link_of(std::uint8_t f) { return unsigned(f) >> kLinkShift; }
inline std::uint8_t with_link(std::uint8_t f, unsigned v) {
    return std::uint8_t((f & ~kLinkField) | (v << kLinkShift));
}

}  // namespace

std::size_t hysteresis(StrongPoints* sp) {
    const PointBits& pts = *sp->points;
    std::uint8_t* flag = sp->flag;
    std::vector<std::uint32_t> stack;  // cells
    for (const std::uint32_t s : sp->seeds) {
        const std::uint32_t si = pts.index(s);
        if (flag[si] & kMain) continue;
        flag[si] |= kMain;
        stack.push_back(s);
        sp->grown.push_back(std::uint32_t(sp->mains.size()));
        while (!stack.empty()) {
            const std::uint32_t p = stack.back();
            stack.pop_back();
            const std::uint32_t i = pts.index(p);
            sp->mains.push_back(p);
            std::uint32_t nb[8];
            pts.ring(p, i, nb);
            for (int d = 0; d < 8; ++d) {
                const std::uint32_t j = nb[d];
                if (j != kNoPoint && (flag[j] & (kCandidate | kMain)) == kCandidate) {
                    flag[j] |= kMain;
                    stack.push_back(pts.step(p, d));
                }
            }
        }
    }
    std::vector<std::uint32_t>().swap(sp->seeds);  // used up: freed before the search's peak
    return sp->mains.size();
}

// Step 5, Ding-Goshtasby: join different main components through short secondary paths. A
// multi-source breadth-first search from every main point over secondary-only points labels each
// reached point with its nearest main component; where two labels meet, the two parent chains
// back to their sources are the shortest secondary link between those components. Returns the
// number of points added. The search starts from hysteresis's mains in their order (component by
// component, each in the order grown), which is the order a labelling pass over them would find.
// Label: an unsigned type that holds the number of components.
template <class Label>
std::size_t join_with(StrongPoints* sp, int max_link, float tl) {
    const PointBits& pts = *sp->points;
    std::uint8_t* flag = sp->flag;
    // The queue is the mains themselves, followed by the secondary points as they are reached
    // (cut off again after the search), so its points come by distance: the distance of the point
    // taken is the level of the queue it is in, and no point keeps its own. The way back from a
    // reached point is the link field of its flags (edge_flags): a direction instead of an index.
    CellList& queue = sp->mains;
    const std::size_t sources = queue.size();
    // The main component of each point, 1, 2, ... in the order grown; 0 = unreached.
    std::vector<Label> label(sp->size(), 0);
    CellList::Cursor at;
    for (std::size_t c = 0; c < sp->grown.size(); ++c) {
        const std::size_t end = c + 1 < sp->grown.size() ? sp->grown[c + 1] : sources;
        while (at.index < end) label[pts.index(queue.next(&at))] = Label(c + 1);
    }
    // p has the smaller label; the pair's key is the two labels (read back when sorting).
    struct Meeting { std::uint32_t p, q; };  // cells
    std::vector<Meeting> meetings;
    std::uint64_t last_pair = 0;  // no pair has label 0
    const std::uint8_t limit = std::uint8_t(max_link);
    // Every main point is taken from the queue before any reached point, and claims each free
    // secondary neighbour; so with limit >= 2 a point reached at distance `limit` is next to no
    // main point of another component and could only meet one (a meeting needs the two
    // distances to sum to at most limit): it would find no meeting and reach nothing further,
    // and is not labelled at all. This outermost shell is the largest.
    const std::uint8_t reach = limit >= 2 ? std::uint8_t(limit - 1) : limit;
    // Whether reached point k at cell q is at most `most` steps from its source: its way back
    // followed (the search makes no point main, so every way back ends at a source).
    const auto within = [&](std::uint32_t q, std::uint32_t k, unsigned most) {
        for (unsigned steps = 0; !(flag[k] & kMain); ++steps) {
            if (steps == most) return false;
            q = pts.step(q, int(link_of(flag[k])));
            k = pts.index(q);
        }
        return true;
    };
    // The number of main neighbours of each main point (up to 2: the climbs below ask for 1),
    // for the climbs: counted here from the rings the search reads anyway, and kept up to date as
    // points become main (one ring per added point instead of one per main point). Kept in the
    // link field, which holds a way back only at points that are not main (a chain ends at the
    // first main point).
    auto became_main = [&](std::uint32_t p, std::uint32_t i) {
        std::uint32_t nb[8];
        pts.ring(p, i, nb);
        for (const std::uint32_t j : nb)
            if (j != kNoPoint && (flag[j] & kMain)) {
                const unsigned c = link_of(flag[j]);
                flag[j] = with_link(flag[j], c < 2 ? c + 1 : 2);
            }
    };
    // The queue is decoded once, kAhead places ahead of the point taken, into a window of the
    // cells decoded last; the labels and flags around each are fetched as it is decoded: on noise
    // they are read all over the arrays (docs/DECISIONS.md "Memory").
    constexpr std::size_t kAhead = 8, kWindow = 16;
    std::uint32_t window[kWindow];
    const CellList::Cursor end_of_sources = queue.end();
    CellList::Cursor read;
    std::size_t level_end = sources;
    unsigned di = 0;  // the distance of the points taken
    for (std::size_t head = 0; head < queue.size(); ++head) {
        if (head == level_end) {
            ++di;
            level_end = queue.size();
        }
        for (; read.index <= head + kAhead && read.index < queue.size();) {
            const std::size_t q = queue.next(&read), s = std::size_t(pts.stride());
            window[(read.index - 1) % kWindow] = std::uint32_t(q);
            for (const std::size_t c : {q - s, q, q + s}) {
                const std::uint32_t k = pts.index(c);  // at most the point count
                __builtin_prefetch(label.data() + k);
                __builtin_prefetch(flag + k);
            }
        }
        const bool source = head < sources;
        const std::uint32_t p = window[head % kWindow];
        const std::uint32_t i = pts.index(p);
        const Label li = label[i];
        std::uint32_t nb[8];
        pts.ring(p, i, nb);
        unsigned mains_around = 0;  // kept for sources only (the link field below)
        for (int d = 0; d < 8; ++d) {
            const std::uint32_t j = nb[d];
            if (j == kNoPoint) continue;
            const std::uint8_t fj = flag[j];
            mains_around += (fj & kMain) != 0;
            // Only main points and the secondary points the search reaches are labelled: the
            // others need no look at their label (a third of the rings on noise).
            if (!(fj & (kMain | kSecondary))) continue;
            const Label lj = label[j];
            if (lj == 0) {
                if (di < reach && (fj & (kSecondary | kMain)) == kSecondary) {
                    label[j] = li;
                    flag[j] = with_link(fj, unsigned((d + 4) & 7));
                    queue.push_back(pts.step(p, d));
                }
            } else if (lj != li) {
                // A labelled point is a source (distance 0, main) or was reached (at most `reach`
                // away): the distances reach `limit` together only from di >= 2.
                if ((fj & kMain) || di + reach <= limit || within(pts.step(p, d), j, limit - di)) {
                    // The same pair as the last meeting: a later one of its key, which the
                    // first found outranks (most meetings repeat the last along a boundary).
                    const std::uint64_t pair = li < lj ? (std::uint64_t(li) << 32) | lj : (std::uint64_t(lj) << 32) | li;
                    if (pair == last_pair) continue;
                    last_pair = pair;
                    if (li < lj) meetings.push_back({p, pts.step(p, d)});
                    else meetings.push_back({pts.step(p, d), p});
                }
            }
        }
        // After the ring: the link field was set above only at secondary points, never at a source.
        if (source) flag[i] = with_link(flag[i], std::min(mains_around, 2u));
    }
    queue.truncate(end_of_sources);
    // One link per pair of components: the first found, i.e. (nearly) the shortest.
    std::size_t added = 0;
    auto key = [&](const Meeting& m) {
        return (std::uint64_t(label[pts.index(m.p)]) << 32) | label[pts.index(m.q)];
    };
    std::stable_sort(meetings.begin(), meetings.end(), [&](const Meeting& a, const Meeting& c) { return key(a) < key(c); });
    for (std::size_t k = 0; k < meetings.size(); ++k) {
        if (k > 0 && key(meetings[k]) == key(meetings[k - 1])) continue;
        for (std::uint32_t p : {meetings[k].p, meetings[k].q}) {
            std::uint32_t i = pts.index(p);
            while (!(flag[i] & kMain)) {  // a reached point: its chain ends at a main point
                const int back = int(link_of(flag[i]));
                flag[i] |= kMain;
                became_main(p, i);
                ++added;
                p = pts.step(p, back);
                i = pts.index(p);
            }
        }
    }

    // Where an edge runs into a stronger one (the stem of a T), the last points before the
    // junction lie on the flank of the stronger edge and are maxima in no direction, so no
    // secondary path exists. From each end of a main curve, climb the magnitude (strictly
    // increasing, >= tau_low, at most max_link points) and keep the climb if it arrives next
    // to a different main component. Only strong points can be climbed to: the climb starts at
    // g >= tau_low and only rises.
    struct Step { std::uint32_t p, i; };
    std::vector<Step> path;
    for (CellList::Cursor s; s.index < sources;) {
        const std::uint32_t end = queue.next(&s);
        const std::uint32_t ei = pts.index(end);
        if (link_of(flag[ei]) != 1) continue;
        std::uint32_t nb[8];
        const Label own = label[ei];
        path.clear();
        Step cur{end, ei};
        bool joined = false;
        for (int step = 0; step <= max_link && !joined; ++step) {
            pts.ring(cur.p, cur.i, nb);
            for (const std::uint32_t j : nb)
                if (j != kNoPoint && (flag[j] & kMain) && label[j] != own && label[j] != 0) joined = true;
            if (joined || step == max_link) break;
            int best = -1;
            float bg = sp->mag[cur.i];
            for (int d = 0; d < 8; ++d) {
                const std::uint32_t j = nb[d];
                if (j == kNoPoint || (flag[j] & kMain)) continue;
                if (sp->mag[j] > bg && sp->mag[j] >= tl) { bg = sp->mag[j]; best = d; }
            }
            if (best < 0) break;
            cur = Step{pts.step(cur.p, best), nb[best]};
            path.push_back(cur);
        }
        if (!joined || path.empty()) continue;
        for (const Step& st : path) {
            flag[st.i] |= kMain;
            became_main(st.p, st.i);
            label[st.i] = own;
            ++added;
        }
    }
    return added;
}

// Labels take 2 bytes a point where the components allow it (thousands on noise up to 2048^2),
// 4 beyond: the same search either way.
std::size_t join_components(StrongPoints* sp, int max_link, float tl) {
    return sp->grown.size() < 65536 ? join_with<std::uint16_t>(sp, max_link, tl)
                                    : join_with<std::uint32_t>(sp, max_link, tl);
}

}  // namespace erd
