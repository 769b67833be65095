// Hilbert indices and the BRIO insertion order (see spatial_order.h).
#include "kernel/spatial_order.h"

#include <algorithm>
#include <utility>

namespace erd {

namespace {

// One level of the Hilbert curve: from state s and the level's bits (x, y) to the next state and
// the base-4 digit. The state says how the sub-square's coordinates are transformed (bit 0: x and
// y swapped, bit 1: both complemented; the two commute); in quadrant (rx, ry) of the transformed
// bits the digit is (3 rx) ^ ry, and ry == 0 swaps, plus rx == 1 complements (the textbook
// rotate-and-flip loop).
constexpr unsigned hilbert_level(unsigned state, unsigned x, unsigned y, unsigned* digit) {
    unsigned rx = x ^ (state >> 1), ry = y ^ (state >> 1);
    if (state & 1u) {
        const unsigned tmp = rx;
        rx = ry;
        ry = tmp;
    }
    *digit = (3u * rx) ^ ry;
    if (ry == 0) state ^= rx == 1 ? 3u : 1u;
    return state;
}

// Three levels at once: index = state << 6 | six interleaved bits (x2 y2 x1 y1 x0 y0, top level
// first), entry = next state << 6 | three base-4 digits: a third of the steps of a level at a
// time.
struct HilbertTable {
    std::uint8_t step[256] = {};
    constexpr HilbertTable() {
        for (unsigned in = 0; in < 256; ++in) {
            unsigned state = in >> 6, digits = 0;
            for (int level = 2; level >= 0; --level) {
                unsigned digit = 0;
                state = hilbert_level(state, (in >> (2 * level + 1)) & 1u, (in >> (2 * level)) & 1u, &digit);
                digits = digits << 2 | digit;
            }
            step[in] = static_cast<std::uint8_t>(state << 6 | digits);
        }
    }
};
constexpr HilbertTable kHilbert;

// The bits of v at the even positions of the result (bit i -> bit 2i), for v < 2^32.
std::uint64_t spread_bits(std::uint32_t v) {
    std::uint64_t x = v;
    x = (x | x << 16) & 0x0000FFFF0000FFFFull;
    x = (x | x << 8) & 0x00FF00FF00FF00FFull;
    x = (x | x << 4) & 0x0F0F0F0F0F0F0F0Full;
    x = (x | x << 2) & 0x3333333333333333ull;
    x = (x | x << 1) & 0x5555555555555555ull;
    return x;
}

// Stable LSD radix sort of v on bits [low, low + bits), 8 bits a pass, ping-ponging with tmp:
// linear, and several times cheaper than std::sort on the packed keys (docs/DECISIONS.md "Kernel").
void radix_sort(std::vector<std::uint64_t>* v, std::vector<std::uint64_t>* tmp, int low, int bits) {
    tmp->resize(v->size());
    for (int shift = low; shift < low + bits; shift += 8) {
        std::size_t count[257] = {};
        for (const std::uint64_t x : *v) ++count[((x >> shift) & 0xFFu) + 1];
        for (int i = 0; i < 256; ++i) count[i + 1] += count[i];
        for (const std::uint64_t x : *v) (*tmp)[count[(x >> shift) & 0xFFu]++] = x;
        v->swap(*tmp);
    }
}

// hilbert_index, inlined into brio_order's key loop. The levels are padded at the top to a multiple
// of three; a padding level (bits 0, 0) only toggles the swap bit, so starting in state
// (padding & 1) gives the same curve as the unpadded order.
inline std::uint64_t hilbert_key(std::uint32_t x, std::uint32_t y, int order) {
    const int levels = (order + 2) / 3 * 3;
    const std::uint64_t morton = spread_bits(x) << 1 | spread_bits(y);
    std::uint64_t d = 0;
    unsigned state = unsigned(levels - order) & 1u;
    for (int level = levels - 3; level >= 0; level -= 3) {
        const unsigned step = kHilbert.step[state << 6 | (unsigned(morton >> (2 * level)) & 63u)];
        d = d << 6 | (step & 63u);
        state = step >> 6;
    }
    return d;
}

}  // namespace

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int order) { return hilbert_key(x, y, order); }

// BRIO (Amenta, Choi, Rote): points go into rounds of doubling size by a deterministic shuffle,
// each round in Hilbert order. Pure Hilbert order inserts each point next to the long thin
// triangles at the front of the filled region; the rounds keep the mesh "random-like" at every
// scale, so each insertion needs fewer flips, while the walks stay short.
// The order is that of sorting (round << 2 bits | Hilbert index, point index) pairs. Packed into
// one uint64 (always, for image-sized inputs) the sort is a radix sort on half the memory.
void brio_order(const std::vector<LatticePoint>& pts, int bits, std::vector<std::uint64_t>* order,
                std::vector<std::uint64_t>* tmp) {
    const std::size_t n = pts.size();
    std::vector<std::uint64_t>& buf = *order;
    buf.resize(n);
    if (n == 0) return;
    for (std::size_t i = 0; i < n; ++i) buf[i] = i;  // then shuffled: point index by position
    std::uint32_t state = 0x2545F491u;
    for (std::size_t i = n; i > 1; --i) {
        state = state * 1664525u + 1013904223u;
        std::swap(buf[i - 1], buf[std::size_t((std::uint64_t(state) * i) >> 32)]);
    }
    int rounds = 1;  // 64 points in round 0, then 64, 128, 256, ...: position j is in round r while j >= 64 << (r-1)
    while ((std::size_t(64) << (rounds - 1)) < n) ++rounds;
    int key_bits = 2 * bits, index_bits = 1;
    while ((std::uint64_t(rounds - 1) >> (key_bits - 2 * bits)) != 0) ++key_bits;
    while (((n - 1) >> index_bits) != 0) ++index_bits;
    const bool packed = key_bits + index_bits <= 64;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs;  // only when not packed
    if (!packed) pairs.resize(n);
    int round = 0;
    std::size_t round_end = 64;
    for (std::size_t j = 0; j < n; ++j) {
        if (j == round_end) {
            ++round;
            round_end *= 2;
        }
        const std::uint64_t index = buf[j];
        const LatticePoint q = pts[index];
        const std::uint64_t key =
            std::uint64_t(round) << (2 * bits) | hilbert_key(std::uint32_t(q.x), std::uint32_t(q.y), bits);
        if (packed)
            buf[j] = key << index_bits | index;
        else
            pairs[j] = {key, static_cast<std::uint32_t>(index)};
    }
    if (packed) {
        radix_sort(order, tmp, index_bits, key_bits);
        const std::uint64_t index_mask = (std::uint64_t(1) << index_bits) - 1;
        for (std::uint64_t& x : buf) x &= index_mask;
    } else {
        std::sort(pairs.begin(), pairs.end());
        for (std::size_t j = 0; j < n; ++j) buf[j] = pairs[j].second;
    }
}

}  // namespace erd
