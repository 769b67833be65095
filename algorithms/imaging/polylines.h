// Polylines from an edge map (thesis 3.4.1 step 1.2); the whole step 1.1-1.3 chain is in
// algorithms/imaging/edge_polylines.h.
//
// Coordinates are LatticePoints in doubled coordinates, which are exactly the indices of the
// half-pixel grid of canny.h: entry (X, Y) of the edge map is LatticePoint{X, Y}.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/canny.h"
#include "algorithms/imaging/image.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

using Polyline = std::vector<LatticePoint>;

// Polylines in one array of plane cells (cell (Y + 1) * stride + X + 1 for point (X, Y), as in
// SortedPoints): noise traces millions of short lines, and a vector of LatticePoints each would
// cost a heap block and a header a line and 8 bytes a point. Line k is cells k_0 .. k_1 - 1 with
// k_0 = first[k], k_1 = first[k + 1].
class PolylineList {
public:
    PolylineList() = default;
    explicit PolylineList(std::ptrdiff_t stride) : stride_(stride) {}

    std::size_t size() const { return first_.size() - 1; }              // lines
    std::size_t size(std::size_t k) const { return first_[k + 1] - first_[k]; }
    std::size_t points() const { return cells_.size(); }                // in all lines
    // Line k into *out (its points in order).
    void line(std::size_t k, Polyline* out) const {
        out->clear();
        for (std::size_t i = first_[k]; i < first_[k + 1]; ++i) out->push_back(point_at(cells_[i]));
    }
    Polyline operator[](std::size_t k) const {
        Polyline l;
        line(k, &l);
        return l;
    }
    template <class Fn>
    void for_each_point(Fn fn) const {
        for (const std::uint32_t c : cells_) fn(point_at(c));
    }
    // The same points as their cells (one cell per point: distinct cells are distinct points).
    template <class Fn>
    void for_each_cell(Fn fn) const {
        for (const std::uint32_t c : cells_) fn(c);
    }
    std::vector<Polyline> to_vector() const {
        std::vector<Polyline> out(size());
        for (std::size_t k = 0; k < size(); ++k) line(k, &out[k]);
        return out;
    }
    std::ptrdiff_t stride() const { return stride_; }

    void reserve(std::size_t points, std::size_t lines) {
        cells_.reserve(points);
        first_.reserve(lines + 1);
    }
    void push(std::uint32_t cell) { cells_.push_back(cell); }  // to the line being made
    void end_line() { first_.push_back(cells_.size()); }
    // A whole line of points with X, Y >= -1 and X + 1 < stride.
    void add(const LatticePoint* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) push(std::uint32_t((std::ptrdiff_t(p[i].y) + 1) * stride_ + p[i].x + 1));
        end_line();
    }
    void add(const Polyline& l) { add(l.data(), l.size()); }
    void clear() {
        std::vector<std::uint32_t>().swap(cells_);
        std::vector<std::size_t>(1, 0).swap(first_);
    }

private:
    LatticePoint point_at(std::uint32_t c) const {
        const std::uint32_t s = std::uint32_t(stride_);
        return LatticePoint{std::int32_t(c % s) - 1, std::int32_t(c / s) - 1};
    }
    std::vector<std::uint32_t> cells_;
    std::vector<std::size_t> first_{0};
    std::ptrdiff_t stride_ = 0;
};

// Traces the set points of a thinned edge map (nonzero = edge) into polylines. Links join
// 8-neighbours, except a diagonal pair that also shares a set 4-neighbour (the corner of a
// staircase or of a T), so one junction is one point, not a cluster of mutual junctions. Points
// with 1 or >= 3 links are nodes: every polyline runs from a node to a node through points with
// exactly 2 links, so polylines meet only at their ends (split at junctions and
// self-intersections). A closed curve without nodes becomes one polyline whose last point repeats
// its first; so does a run that returns to its start node (a loop on a junction). Isolated points
// give one-point polylines. Deterministic: nodes in row-major order, links in a fixed order
// (E, SE, S, SW, W, NW, N, NE), loops after all node runs. Each link is used by one polyline.
PolylineList trace_polylines(const Grid<std::uint8_t>& edges);
// The same for a set of points as a bit plane (EdgeDetector::detect's points: PointBits::build).
PolylineList trace_polylines(const PointBits& pts);

}  // namespace erd
