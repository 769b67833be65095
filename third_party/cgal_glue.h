// Glue to CGAL (Debian's libcgal-dev), the independent triangulator erd's kernel is checked and
// timed against: the differential tests (tests/cgal/), the fuzz target fuzz/fuzz_cgal_diff.cpp
// and bench/kernel_bench_cgal.cpp. Never linked into erd or liberd.
//
// CGAL's headers take long to compile, so they are included by one translation unit only,
// third_party/cgal_glue.cpp; this header names no CGAL type. Kernel: Epick (exact predicates;
// lattice points below 2^24 are exact doubles, and no construction is ever needed because the
// callers insert non-crossing constraints only).
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "kernel/lattice.h"

namespace cgal_glue {

using Point = erd::LatticePoint;

// A triangulation as coordinates: finite faces counter-clockwise, constrained edges once each.
struct Mesh {
    std::vector<Point> vertices;
    std::vector<std::array<Point, 3>> faces;
    std::vector<std::array<Point, 2>> constrained;
};

// CGAL::Constrained_Delaunay_triangulation_2 with Exact_predicates_tag.
class ConstrainedDelaunay {
public:
    ConstrainedDelaunay();
    ~ConstrainedDelaunay();
    ConstrainedDelaunay(const ConstrainedDelaunay&) = delete;
    ConstrainedDelaunay& operator=(const ConstrainedDelaunay&) = delete;
    void insert(Point p);
    // a-b must cross no constrained edge (CGAL would throw): the callers apply erd's policy first.
    void insert_constraint(Point a, Point b);
    // Removes the vertex at p. False (nothing done) when p is no vertex or has a constrained edge.
    bool remove(Point p);
    Mesh mesh() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// CGAL::Delaunay_triangulation_2, for timing: insert a point set (CGAL's spatially sorted range
// insertion), then remove vertices by the index of their point.
class Delaunay {
public:
    Delaunay();
    ~Delaunay();
    Delaunay(const Delaunay&) = delete;
    Delaunay& operator=(const Delaunay&) = delete;
    void insert(const std::vector<Point>& points);  // distinct points
    void remove(std::size_t index);                 // the vertex of points[index]
    std::size_t face_count() const;
    bool valid() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace cgal_glue
