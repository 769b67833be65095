// 8-neighbour rings of a sparse set of grid points kept as a sorted list instead of a plane.
//
// Edge detection and tracing work on a few percent of a half-pixel grid; a plane of ids for
// neighbour lookups would cost 4 bytes per grid point and miss the cache. Here the points are
// plane indices in increasing (row-major) order, and each point remembers where, in that list,
// the row above and the row below start near it, so its ring is found with a few comparisons.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace erd {

constexpr std::uint32_t kNoPoint = 0xFFFFFFFFu;

struct SortedPoints {
    // Plane index of each point, strictly increasing; rows `stride` apart, with a frame of at
    // least one empty column so that index +-1 never reaches a point of another row. Grids here
    // stay below 2^32 cells (kMaxImagePixels: a half-pixel plane has under 2^29).
    std::vector<std::uint32_t> at;
    std::ptrdiff_t stride = 0;

    std::size_t size() const { return at.size(); }

    // Call after the last point is added (two merge sweeps over `at`).
    void link_rows() {
        const std::size_t n = at.size();
        up_.resize(n);
        down_.resize(n);
        std::size_t ku = 0, kd = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::ptrdiff_t p = std::ptrdiff_t(at[i]);
            while (ku < n && std::ptrdiff_t(at[ku]) < p - stride - 1) ++ku;
            while (kd < n && std::ptrdiff_t(at[kd]) < p + stride - 1) ++kd;
            up_[i] = std::uint32_t(ku);
            down_[i] = std::uint32_t(kd);
        }
    }

    // The neighbours of point i that are in the set, in the order E, SE, S, SW, W, NW, N, NE
    // (x right, y down); kNoPoint where there is none.
    void ring(std::uint32_t i, std::uint32_t nb[8]) const {
        const std::ptrdiff_t p = std::ptrdiff_t(at[i]);
        const std::size_t n = at.size();
        nb[0] = i + 1 < n && std::ptrdiff_t(at[i + 1]) == p + 1 ? i + 1 : kNoPoint;
        nb[4] = i > 0 && std::ptrdiff_t(at[i - 1]) == p - 1 ? i - 1 : kNoPoint;
        row(down_[i], p + stride - 1, &nb[3], &nb[2], &nb[1]);
        row(up_[i], p - stride - 1, &nb[5], &nb[6], &nb[7]);
    }

    void clear() {
        std::vector<std::uint32_t>().swap(at);
        std::vector<std::uint32_t>().swap(up_);
        std::vector<std::uint32_t>().swap(down_);
    }

private:
    // The points at left, left + 1, left + 2 of one row, looked for from list position k on.
    void row(std::uint32_t k, std::ptrdiff_t left, std::uint32_t* west, std::uint32_t* mid, std::uint32_t* east) const {
        const std::size_t n = at.size();
        *west = *mid = *east = kNoPoint;
        if (k < n && std::ptrdiff_t(at[k]) == left) *west = k++;
        if (k < n && std::ptrdiff_t(at[k]) == left + 1) *mid = k++;
        if (k < n && std::ptrdiff_t(at[k]) == left + 2) *east = k;
    }

    std::vector<std::uint32_t> up_, down_;  // first list position at or after at[i] -+ stride - 1
};

}  // namespace erd
