#include "algorithms/thinning.h"

#include <cstddef>
#include <vector>

#include "algorithms/set_points.h"

namespace erd {

namespace {

// Neighbours of a point in the order of Zhang and Suen: P2 = N, P3 = NE, P4 = E, P5 = SE, P6 = S,
// P7 = SW, P8 = W, P9 = NW, as bits 0..7 of one byte.
inline unsigned ring(const std::uint8_t* p, std::ptrdiff_t s) {
    return unsigned(p[-s] != 0) | unsigned(p[-s + 1] != 0) << 1 | unsigned(p[1] != 0) << 2 |
           unsigned(p[s + 1] != 0) << 3 | unsigned(p[s] != 0) << 4 | unsigned(p[s - 1] != 0) << 5 |
           unsigned(p[-1] != 0) << 6 | unsigned(p[-s - 1] != 0) << 7;
}

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

void thin_plane(std::uint8_t* b, std::ptrdiff_t s, std::vector<std::ptrdiff_t>* live_points) {
    std::vector<std::ptrdiff_t>& live = *live_points;
    // Decisions depend on the 8-neighbour ring alone: tabulate them once (bit 0: Zhang-Suen
    // deletes in sub-iteration 1, bit 1: in sub-iteration 2, bit 2: a removable staircase corner).
    std::uint8_t table[256];
    for (unsigned r = 0; r < 256; ++r) {
        const int n = popcount8(r);
        const unsigned N = r & 1u, E = (r >> 2) & 1u, S = (r >> 4) & 1u, Wb = (r >> 6) & 1u;
        std::uint8_t v = 0;
        if (n >= 2 && n <= 6 && transitions(r) == 1) {
            if ((N & E & S) == 0 && (E & S & Wb) == 0) v |= 1;
            if ((N & E & Wb) == 0 && (N & S & Wb) == 0) v |= 2;
        }
        const unsigned four = r & 0x55u;
        if ((four == 0x05u || four == 0x14u || four == 0x50u || four == 0x41u) && connectivity8(r) == 1) v |= 4;
        table[r] = v;
    }
    // Zhang-Suen sub-iterations delete, all at once, the points whose ring meets their rule. A
    // point's verdict changes only when its ring does, so each sub-iteration re-examines only the
    // points next to a deletion since its rule last ran (dirty bit 1 << (step + 1) in the plane):
    // the same deletions as sweeping every point, for a fraction of the work.
    std::vector<std::ptrdiff_t> dirty[2] = {live, live}, doomed;
    for (std::ptrdiff_t i : live) b[i] = 1 | 2 | 4;
    const std::ptrdiff_t around[8] = {-s - 1, -s, -s + 1, -1, 1, s - 1, s, s + 1};
    for (int step = 0; !dirty[0].empty() || !dirty[1].empty(); step ^= 1) {
        const std::uint8_t bit = std::uint8_t(1u << step), mark = std::uint8_t(2u << step);
        doomed.clear();
        for (std::ptrdiff_t i : dirty[step]) {
            if (!b[i]) continue;  // deleted since it was marked
            b[i] = std::uint8_t(b[i] & ~mark);
            if (table[ring(b + i, s)] & bit) doomed.push_back(i);
        }
        dirty[step].clear();
        for (std::ptrdiff_t i : doomed) b[i] = 0;
        for (std::ptrdiff_t i : doomed)
            for (std::ptrdiff_t o : around) {
                const std::ptrdiff_t j = i + o;
                if (!b[j]) continue;
                for (int k = 0; k < 2; ++k)
                    if (!(b[j] & (2u << k))) {
                        b[j] = std::uint8_t(b[j] | (2u << k));
                        dirty[k].push_back(j);
                    }
            }
    }
    std::size_t kept = 0;
    for (std::ptrdiff_t i : live)
        if (b[i]) {
            b[i] = 1;
            live[kept++] = i;
        }
    live.resize(kept);

    // Staircase corners: a point whose set 4-neighbours are exactly two at a right angle (N+E, E+S,
    // S+W or W+N) and which joins only one component of neighbours. Deleted one at a time, so the
    // decision for a point sees earlier deletions and a corner pair never loses both points.
    std::size_t k = 0;
    for (std::ptrdiff_t i : live) {
        if (table[ring(b + i, s)] & 4)
            b[i] = 0;
        else
            live[k++] = i;
    }
    live.resize(k);
}

std::size_t thin_edges(Grid<std::uint8_t>* map) {
    const int w = map->width, h = map->height;
    if (w <= 0 || h <= 0) return 0;
    // Work on a copy with a zero frame so the ring never leaves the buffer.
    const int s = w + 2;
    std::vector<std::uint8_t> b(std::size_t(s) * std::size_t(h + 2), 0);
    std::vector<std::ptrdiff_t> live;
    for_each_set(map->data.data(), map->data.size(), [&](std::size_t k) {
        const std::ptrdiff_t i = std::ptrdiff_t(k / std::size_t(w) + 1) * s + std::ptrdiff_t(k % std::size_t(w)) + 1;
        b[std::size_t(i)] = 1;
        map->data[k] = 0;
        live.push_back(i);
    });
    thin_plane(b.data(), s, &live);
    for (std::ptrdiff_t i : live) map->data[std::size_t(i / s - 1) * std::size_t(w) + std::size_t(i % s - 1)] = 1;
    return live.size();
}

}  // namespace erd
