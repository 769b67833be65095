// Scan conversion with the exact ownership rule of kernel/raster.h; the row walk itself is
// kernel/raster_rows.h.
#include "kernel/raster.h"

#include <algorithm>
#include <climits>
#include <initializer_list>

#include "kernel/predicates.h"
#include "kernel/raster_rows.h"

namespace erd {

std::int64_t scan_triangle(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                           std::vector<Span>* out) {
    return scan_triangle(l, d, a, b, c, out, INT32_MIN, INT32_MAX);
}

std::int64_t scan_triangle(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c,
                           std::vector<Span>* out, std::int32_t j_begin, std::int32_t j_end) {
    out->clear();
    OwnedRows rows(l, d, a, b, c, j_begin, j_end);
    out->reserve(rows.max_rows());  // push_back below then never reallocates
    std::int64_t count = 0;
    for (RowRun part; rows.next(&part);) {
        for (RowRun run = part; run.j <= run.j_end; run.step()) {
            std::int64_t lo, hi;
            run.columns(&lo, &hi);
            if (lo > hi) continue;
            out->push_back(Span{std::int32_t(run.j), std::int32_t(lo), std::int32_t(hi)});
            count += hi - lo + 1;
        }
    }
    return count;
}

bool triangle_owns(const Lattice& l, RasterDomain d, LatticePoint a, LatticePoint b, LatticePoint c, std::int32_t i,
                   std::int32_t j) {
    raster_detail::Setup s;
    if (!raster_detail::setup(l, d, a, b, c, &s)) return false;
    return raster_detail::owns_point(s, l.fine_x(i), l.fine_y(j));
}

bool SpanPlane::set(LatticePoint p0, double z0v, LatticePoint p1, double z1v, LatticePoint p2, double z2v) {
    x0 = p0.x;
    y0 = p0.y;
    z0 = z0v;
    gx = gy = 0.0;
    const std::int64_t D = orient2d(p0, p1, p2);
    if (D == 0) return false;
    const double dx1 = double(p1.x) - x0, dy1 = double(p1.y) - y0;
    const double dx2 = double(p2.x) - x0, dy2 = double(p2.y) - y0;
    const double dz1 = z1v - z0v, dz2 = z2v - z0v;
    const double inv = 1.0 / double(D);
    gx = (dz1 * dy2 - dz2 * dy1) * inv;
    gy = (dz2 * dx1 - dz1 * dx2) * inv;
    return true;
}

bool RoundedPlane::set(LatticePoint p0, std::int64_t z0v, LatticePoint p1, std::int64_t z1v, LatticePoint p2,
                       std::int64_t z2v, std::int64_t maxval) {
    if (maxval < 1 || maxval > 65535) return false;
    for (std::int64_t z : {z0v, z1v, z2v})
        if (z < 0 || z > maxval) return false;
    std::int64_t D = orient2d(p0, p1, p2);
    if (D == 0) return false;
    const std::int64_t dx1 = std::int64_t(p1.x) - p0.x, dy1 = std::int64_t(p1.y) - p0.y;
    const std::int64_t dx2 = std::int64_t(p2.x) - p0.x, dy2 = std::int64_t(p2.y) - p0.y;
    const std::int64_t dz1 = z1v - z0v, dz2 = z2v - z0v;
    std::int64_t a = dz1 * dy2 - dz2 * dy1, b = dz2 * dx1 - dz1 * dx2;
    if (D < 0) D = -D, a = -a, b = -b;
    // t = 4N + 2D + 1 with N = z0*D + a*(X - x0) + b*(Y - y0) at doubled (X, Y) = (2i, 2j).
    tx = 8 * a;
    ty = 8 * b;
    t00 = 4 * z0v * D + 2 * D + 1 - 4 * a * p0.x - 4 * b * p0.y;
    inv = 1.0 / double(4 * D);
    dp = double(tx) * inv;
    // (k + 5) * (maxval + 1) * D <= 2^51 for k < run (raster.h); at least one pixel per start.
    const std::int64_t k_max = ((std::int64_t(1) << 51) / ((maxval + 1) * D)) - 5;
    run = std::int32_t(std::clamp<std::int64_t>(k_max + 1, 1, INT32_MAX));
    return true;
}

}  // namespace erd
