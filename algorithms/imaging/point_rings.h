// 8-neighbour rings of a sparse set of grid points kept as a sorted list instead of a plane.
//
// Edge detection and tracing work on a part of a half-pixel grid; a plane of ids for neighbour
// lookups would cost 4 bytes per grid point. Here the points are plane indices in increasing
// (row-major) order beside a bit plane of the set and a count of points before every 64 cells,
// so a neighbour's list position is the count of set bits before it: constant time per ring,
// and 3/16 byte per cell whatever the density (the half-pixel grid has 4 cells per pixel).
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace erd {

constexpr std::uint32_t kNoPoint = 0xFFFFFFFFu;

// Clears the bits of the n set cells of a bit plane for which keep(k, p) is false (k: 0, 1, ...
// in increasing cell p), in one pass; returns how many stay.
template <class Keep>
std::size_t remove_bits_unless(std::uint64_t* words, std::size_t n, Keep keep) {
    std::size_t k = 0, kept = 0;
    for (std::size_t w = 0; k < n; ++w)
        for (std::uint64_t b = words[w]; b; b &= b - 1) {
            if (keep(std::uint32_t(k++), std::uint32_t(w * 64 + unsigned(__builtin_ctzll(b))))) ++kept;
            else words[w] &= ~(b & (0 - b));
        }
    return kept;
}

// A set of plane cells as one bit per cell and the number of set cells before every 64: a point's
// list position (its rank) is a count of bits, so arrays indexed by position need no list of
// positions beside them. 1/8 + 1/16 byte per cell, however many points there are. Cells are plane
// indices with a frame of at least one empty column and one empty row (SortedPoints).
class PointBits {
public:
    // From the plane indices at[0..n), strictly increasing.
    void build(const std::uint32_t* at, std::size_t n, std::ptrdiff_t stride) {
        set_stride(stride);
        size_ = n;
        const std::size_t cells = n ? std::size_t(at[n - 1]) + std::size_t(stride) + 2 : 0;
        const std::size_t words = cells / 64 + 2;  // one spare word: bits3 reads the next one
        bits_.assign(words, 0);
        for (std::size_t k = 0; k < n; ++k) bits_[at[k] >> 6] |= std::uint64_t(1) << (at[k] & 63u);
        link();
    }

    // From a bit plane of the n points (bit q & 63 of word q >> 6 for cell q) covering the row
    // below the last point's and one spare word.
    void adopt(std::vector<std::uint64_t>&& bits, std::ptrdiff_t stride, std::size_t n) {
        set_stride(stride);
        size_ = n;
        bits_ = std::move(bits);
        link();
    }

    std::size_t size() const { return size_; }
    std::ptrdiff_t stride() const { return stride_; }

    // The list position of the point at cell p (p must be in the set).
    std::uint32_t index(std::size_t p) const { return rank(p); }

    // The cell next to cell p in ring direction d (E, SE, S, SW, W, NW, N, NE: x right, y down).
    std::uint32_t step(std::uint32_t p, int d) const { return std::uint32_t(std::ptrdiff_t(p) + offset_[d]); }

    // Calls fn(k, p) for every point, k = 0, 1, ... in increasing cell p.
    template <class Fn>
    void for_each(Fn fn) const {
        std::uint32_t k = 0;
        for (std::size_t w = 0; w < bits_.size(); ++w)
            for (std::uint64_t b = bits_[w]; b; b &= b - 1) fn(k++, std::uint32_t(w * 64 + lowest_bit(b)));
    }

    // Removes the points for which keep(k, p) is false, called as for_each calls fn.
    template <class Keep>
    void remove_unless(Keep keep) {
        size_ = remove_bits_unless(bits_.data(), size_, keep);
        link();
    }

    // The directions (bit d for direction d, step() order) in which the cell p has a point.
    unsigned mask(std::size_t p) const {
        const std::size_t s = std::size_t(stride_);
        const unsigned mid = bits3(p - 1), down = bits3(p + s - 1), up = bits3(p - s - 1);
        // down row: SW, S, SE are bits 0, 1, 2 of `down`; directions 3, 2, 1.
        return ((mid >> 2) & 1u) | (((down >> 2) & 1u) << 1) | (((down >> 1) & 1u) << 2) | ((down & 1u) << 3) |
               ((mid & 1u) << 4) | ((up & 7u) << 5);
    }

    // The list positions of the points around the point at cell p, which is point i, in ring
    // order; kNoPoint where there is none.
    void ring(std::size_t p, std::uint32_t i, std::uint32_t nb[8]) const {
        const std::size_t s = std::size_t(stride_);
        const unsigned mid = bits3(p - 1);
        nb[0] = mid & 4u ? i + 1 : kNoPoint;
        nb[4] = mid & 1u ? i - 1 : kNoPoint;
        row(p + s - 1, &nb[3], &nb[2], &nb[1]);
        row(p - s - 1, &nb[5], &nb[6], &nb[7]);
    }

    // The list position of the point in direction d of point i at cell p (bit d of mask(p)).
    std::uint32_t neighbour(std::size_t p, std::uint32_t i, int d) const {
        if (d == 0) return i + 1;
        if (d == 4) return i - 1;
        const std::size_t s = std::size_t(stride_);
        const std::size_t left = d < 4 ? p + s - 1 : p - s - 1;
        const unsigned b = bits3(left);
        // Down row (d = 3, 2, 1) and up row (d = 5, 6, 7): cell `left + c` with c = 0, 1, 2.
        const unsigned c = d < 4 ? unsigned(3 - d) : unsigned(d - 5);
        return rank(left) + popcount64(b & ((1u << c) - 1u));
    }

    void clear() {
        std::vector<std::uint64_t>().swap(bits_);
        std::vector<std::uint32_t>().swap(rank_);
        size_ = 0;
    }

private:
    void set_stride(std::ptrdiff_t stride) {
        stride_ = stride;
        const std::ptrdiff_t dy[8] = {0, 1, 1, 1, 0, -1, -1, -1}, dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
        for (int d = 0; d < 8; ++d) offset_[d] = dy[d] * stride + dx[d];
    }

    void link() {
        rank_.resize(bits_.size());
        std::uint32_t before = 0;
        for (std::size_t w = 0; w < bits_.size(); ++w) {
            rank_[w] = before;
            before += std::uint32_t(popcount64(bits_[w]));
        }
    }

    static unsigned popcount64(std::uint64_t v) {
#if defined(__POPCNT__)
        return unsigned(__builtin_popcountll(v));  // one instruction (the Makefile's -mpopcnt on x86-64)
#else
        v = v - ((v >> 1) & 0x5555555555555555ull);
        v = (v & 0x3333333333333333ull) + ((v >> 2) & 0x3333333333333333ull);
        v = (v + (v >> 4)) & 0x0F0F0F0F0F0F0F0Full;
        return unsigned((v * 0x0101010101010101ull) >> 56);
#endif
    }
    static unsigned lowest_bit(std::uint64_t v) { return unsigned(__builtin_ctzll(v)); }  // v != 0

    // The bits of cells q, q + 1, q + 2 (bits 0, 1, 2).
    unsigned bits3(std::size_t q) const {
        const std::size_t w = q >> 6;
        const unsigned sh = unsigned(q & 63u);
        std::uint64_t v = bits_[w] >> sh;
        if (sh > 61) v |= bits_[w + 1] << (64 - sh);
        return unsigned(v & 7u);
    }

    // The number of points before cell q: the list position of the first point at or after it.
    std::uint32_t rank(std::size_t q) const {
        const std::size_t w = q >> 6;
        return rank_[w] + popcount64(bits_[w] & ((std::uint64_t(1) << (q & 63u)) - 1));
    }

    // The points at left, left + 1, left + 2 of one row.
    void row(std::size_t left, std::uint32_t* west, std::uint32_t* mid, std::uint32_t* east) const {
        *west = *mid = *east = kNoPoint;
        const unsigned b = bits3(left);
        if (!b) return;
        std::uint32_t k = rank(left);
        if (b & 1u) *west = k++;
        if (b & 2u) *mid = k++;
        if (b & 4u) *east = k;
    }

    std::vector<std::uint64_t> bits_;  // bit q: a point at plane index q
    std::vector<std::uint32_t> rank_;  // points before cell 64 w
    std::ptrdiff_t stride_ = 0;
    std::ptrdiff_t offset_[8] = {};  // of step()
    std::size_t size_ = 0;
};

struct SortedPoints {
    // Plane index of each point, strictly increasing; rows `stride` apart, with a frame of at
    // least one empty column and one empty row, so that index +-1 never reaches a point of
    // another row and index - stride - 1 is never negative. Grids here stay below 2^32 cells
    // (kMaxImagePixels: a half-pixel plane has under 2^31).
    std::vector<std::uint32_t> at;
    std::ptrdiff_t stride = 0;

    std::size_t size() const { return at.size(); }

    // Call after the last point is added (PointBits).
    void link_rows() { bits_.build(at.data(), at.size(), stride); }

    // The directions (bit d for direction d, order as for ring()) in which point i has a
    // neighbour in the set.
    unsigned mask(std::uint32_t i) const { return bits_.mask(at[i]); }

    // The neighbours of point i that are in the set, in the order E, SE, S, SW, W, NW, N, NE
    // (x right, y down); kNoPoint where there is none.
    void ring(std::uint32_t i, std::uint32_t nb[8]) const { bits_.ring(at[i], i, nb); }

    // The neighbour of point i in direction d, which must be in the set (bit d of mask(i)).
    std::uint32_t neighbour(std::uint32_t i, int d) const { return bits_.neighbour(at[i], i, d); }

    void clear() {
        std::vector<std::uint32_t>().swap(at);
        bits_.clear();
    }

private:
    PointBits bits_;
};

}  // namespace erd
