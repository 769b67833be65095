#include "algorithms/imaging/thinning.h"

#include <cstddef>
#include <vector>

#include "algorithms/imaging/set_points.h"

namespace erd {

namespace {

inline int popcount8(unsigned v) {
    int n = 0;
    for (; v; v &= v - 1) ++n;
    return n;
}

// Number of 0 -> 1 transitions around the ring P2, P3, ..., P9, P2.
inline int transitions(unsigned r) {
    int a = 0;
    for (int k = 0; k < 8; ++k) a += !((r >> k) & 1u) && ((r >> ((k + 1) & 7)) & 1u);
    return a;
}

// Yokoi's 8-connectivity number: the number of 8-connected components of set neighbours that the
// point touches, counted over the four 4-neighbours (N, E, S, W at bits 0, 2, 4, 6).
inline int connectivity8(unsigned r) {
    const unsigned c = ~r & 0xFFu;  // complement
    int n = 0;
    for (int k = 0; k < 8; k += 2) {
        const unsigned a = (c >> k) & 1u, b = (c >> ((k + 1) & 7)) & 1u, d = (c >> ((k + 2) & 7)) & 1u;
        n += int(a - a * b * d);
    }
    return n;
}

}  // namespace

void thin_points(const SortedPoints& pts, std::vector<std::uint8_t>* alive_points) {
    std::vector<std::uint8_t>& alive = *alive_points;
    const std::uint32_t n = std::uint32_t(pts.size());
    // Decisions depend on the 8-neighbour ring alone: tabulate them once (bit 0: Zhang-Suen
    // deletes in sub-iteration 1, bit 1: in sub-iteration 2, bit 2: a removable staircase corner).
    std::uint8_t table[256];
    for (unsigned r = 0; r < 256; ++r) {
        const int c = popcount8(r);
        const unsigned N = r & 1u, E = (r >> 2) & 1u, S = (r >> 4) & 1u, Wb = (r >> 6) & 1u;
        std::uint8_t v = 0;
        if (c >= 2 && c <= 6 && transitions(r) == 1) {
            if ((N & E & S) == 0 && (E & S & Wb) == 0) v |= 1;
            if ((N & E & Wb) == 0 && (N & S & Wb) == 0) v |= 2;
        }
        const unsigned four = r & 0x55u;
        if ((four == 0x05u || four == 0x14u || four == 0x50u || four == 0x41u) && connectivity8(r) == 1) v |= 4;
        table[r] = v;
    }
    // ring[i]: the set neighbours of point i as one byte in the order of Zhang and Suen (P2 = N,
    // P3 = NE, P4 = E, P5 = SE, P6 = S, P7 = SW, P8 = W, P9 = NW as bits 0..7), kept up to date
    // as points go, so a verdict is one table lookup. point_rings.h gives E, SE, S, SW, W, NW, N,
    // NE: direction d is bit (d + 2) mod 8, and a point in direction d from j sees j in direction
    // d + 4.
    std::vector<std::uint8_t> ring(n, 0);
    std::uint32_t nb[8];
    bool all_alive = true;
    for (std::uint32_t i = 0; i < n; ++i) all_alive = all_alive && alive[i] != 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (all_alive) {  // the ring is the set's own (the usual case): no neighbour's index needed
            const unsigned m = pts.mask(i);
            ring[i] = std::uint8_t(((m << 2) | (m >> 6)) & 0xFFu);
            continue;
        }
        if (!alive[i]) continue;
        pts.ring(i, nb);
        unsigned r = 0;
        for (int d = 0; d < 8; ++d) r |= unsigned(nb[d] != kNoPoint && alive[nb[d]] != 0) << ((d + 2) & 7);
        ring[i] = std::uint8_t(r);
    }
    auto remove = [&](std::uint32_t i) {
        alive[i] = 0;
        pts.ring(i, nb);
        for (int d = 0; d < 8; ++d)
            if (nb[d] != kNoPoint) ring[nb[d]] = std::uint8_t(ring[nb[d]] & ~(1u << ((d + 6) & 7)));
    };

    // Zhang-Suen sub-iterations delete, all at once, the points whose ring meets their rule. A
    // point's verdict changes only when its ring does, so each sub-iteration re-examines only the
    // points next to a deletion since its rule last ran (dirty bit 2 << step in alive): the same
    // deletions as sweeping every point, for a fraction of the work.
    // At first every point is marked for both rules: each rule's first run sweeps them all in
    // order (what a list of every point would give, without the list; nothing is marked again
    // for a rule before its first run, as no point has lost that rule's mark yet).
    std::vector<std::uint32_t> dirty[2], doomed;
    for (std::uint32_t i = 0; i < n; ++i)
        if (alive[i]) alive[i] = 1 | 2 | 4;
    bool swept[2] = {false, false};
    for (int step = 0; !swept[0] || !swept[1] || !dirty[0].empty() || !dirty[1].empty(); step ^= 1) {
        const std::uint8_t bit = std::uint8_t(1u << step), mark = std::uint8_t(2u << step);
        doomed.clear();
        auto examine = [&](std::uint32_t i) {
            if (!alive[i]) return;  // deleted since it was marked
            alive[i] = std::uint8_t(alive[i] & ~mark);
            if (table[ring[i]] & bit) doomed.push_back(i);
        };
        if (!swept[step]) {
            swept[step] = true;
            for (std::uint32_t i = 0; i < n; ++i) examine(i);
        } else {
            for (const std::uint32_t i : dirty[step]) examine(i);
        }
        dirty[step].clear();
        for (const std::uint32_t i : doomed) remove(i);
        for (const std::uint32_t i : doomed) {
            pts.ring(i, nb);
            for (const std::uint32_t j : nb) {
                if (j == kNoPoint || !alive[j]) continue;
                for (int k = 0; k < 2; ++k)
                    if (!(alive[j] & (2u << k))) {
                        alive[j] = std::uint8_t(alive[j] | (2u << k));
                        dirty[k].push_back(j);
                    }
            }
        }
    }

    // Staircase corners: a point whose set 4-neighbours are exactly two at a right angle (N+E, E+S,
    // S+W or W+N) and which joins only one component of neighbours. Deleted one at a time in
    // row-major order, so the decision for a point sees earlier deletions and a corner pair never
    // loses both points.
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!alive[i]) continue;
        alive[i] = 1;
        if (table[ring[i]] & 4) remove(i);
    }
}

std::size_t thin_edges(Grid<std::uint8_t>* map) {
    const int w = map->width, h = map->height;
    if (w <= 0 || h <= 0) return 0;
    // The set points as indices of a plane with a one-point frame (never allocated).
    SortedPoints pts;
    pts.stride = w + 2;
    for_each_set(map->data.data(), map->data.size(), [&](std::size_t k) {
        pts.at.push_back(std::uint32_t((k / std::size_t(w) + 1) * std::size_t(pts.stride) + k % std::size_t(w) + 1));
        map->data[k] = 0;
    });
    pts.link_rows();
    std::vector<std::uint8_t> alive(pts.size(), 1);
    thin_points(pts, &alive);
    std::size_t left = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (alive[i]) {
            const std::uint32_t s = std::uint32_t(pts.stride);
            (*map)(int(pts.at[i] % s) - 1, int(pts.at[i] / s) - 1) = 1;
            ++left;
        }
    return left;
}

}  // namespace erd
