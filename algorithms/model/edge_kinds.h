// Edge kinds per edge (issue 44): which discontinuity edges of an ERD model are reconstructed as
// the other kind than the model's own (Model::edges), and the pixels each edge governs.
//
// A model's discontinuity edges are all of kind Model::edges, except those Model::kind_exceptions
// lists, which are of the other kind. The kind of an edge says how the pixels it governs become
// samples: soft by 4x4 supersampling, hard by point evaluation (model.h EdgeKind). An edge governs
// the pixels whose sub-sample square it meets,
//
//     [x - 3/8, x + 3/8] x [y - 3/8, y + 3/8]   (pixel units; the 16 sub-samples' extent),
//
// i.e. the pixels whose supersampled and point-evaluated values can differ because of it. Every
// other pixel is evaluated as the model's kind says (reconstruct.h). A pixel governed by an
// exception edge takes the exception's kind, whatever other edges govern it.
//
// Choosing the kinds (choose_edge_kinds): per edge, the kind whose reconstruction fits the image
// better on the pixels the edge governs, measured on the model's two whole reconstructions.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd {

// The kind of the exceptions of m (the other kind than m.edges).
inline EdgeKind exception_kind(const Model& m) { return m.edges == EdgeKind::soft ? EdgeKind::hard : EdgeKind::soft; }

// Calls fn(x, y) once for every pixel of a width x height image whose sub-sample square the closed
// segment u-w (doubled coordinates) meets, row by row. Exact (integer arithmetic in eighths of a
// pixel); the work is proportional to the segment's length.
template <class Fn>
void for_each_governed_pixel(LatticePoint u, LatticePoint w, int width, int height, Fn fn);

// Per pixel (row-major, W x H): 1 where some edge of m.kind_exceptions governs the pixel.
std::vector<std::uint8_t> exception_pixels(const Model& m);

// Checks m.kind_exceptions: sorted pairs (a < b) without repeats, of vertices of m joined by a
// discontinuity edge (topo: build_topology(m)). Code::input naming the first bad pair otherwise.
Status check_kind_exceptions(const Model& m, const ModelTopology& topo);

// Per-edge kinds by fit (issue 44: "measure the kind of each edge from the image"). From m (an ERD
// model; its kinds are replaced) and the image it approximates (same size and channels): the
// model's kind becomes the one whose whole reconstruction has the smaller squared error, then
// every discontinuity edge whose governed pixels have a smaller squared error (summed over them
// and the channels) as the other kind becomes an exception. Edges are decided one by one against
// the model's kind, so a pixel two edges govern counts for both. *psnr receives the PSNR of m's
// own reconstruction afterwards (reconstruct(m, supersampled(m))), computed from the two
// reconstructions made here. threads: as reconstruct().
Status choose_edge_kinds(const Image& image, Model* m, double* psnr, int threads = 1);

// ---------------------------------------------------------------------------------------------

template <class Fn>
void for_each_governed_pixel(LatticePoint u, LatticePoint w, int width, int height, Fn fn) {
    // Eighths of a pixel: pixel (x, y) has its square [8x - 3, 8x + 3] x [8y - 3, 8y + 3].
    const std::int64_t ax = 4 * std::int64_t(u.x), ay = 4 * std::int64_t(u.y);
    const std::int64_t bx = 4 * std::int64_t(w.x), by = 4 * std::int64_t(w.y);
    const std::int64_t dx = bx - ax, dy = by - ay;
    // Floor and ceiling division by 8 of possibly negative numbers.
    const auto fdiv = [](std::int64_t a) { return a >= 0 ? a / 8 : -((-a + 7) / 8); };
    const auto cdiv = [&](std::int64_t a) { return -fdiv(-a); };
    // The square meets the segment when their bounding boxes overlap and the square's corners do
    // not lie strictly on one side of the segment's line.
    const auto meets = [&](std::int64_t x, std::int64_t y) {
        const std::int64_t cx = 8 * x, cy = 8 * y;
        int pos = 0, neg = 0;
        for (int k = 0; k < 4; ++k) {
            const std::int64_t qx = cx + ((k & 1) ? 3 : -3), qy = cy + ((k & 2) ? 3 : -3);
            const std::int64_t s = dx * (qy - ay) - dy * (qx - ax);
            pos += s > 0;
            neg += s < 0;
        }
        return pos < 4 && neg < 4;
    };
    const std::int64_t y_lo = std::max<std::int64_t>(0, cdiv(std::min(ay, by) - 3));
    const std::int64_t y_hi = std::min<std::int64_t>(height - 1, fdiv(std::max(ay, by) + 3));
    const std::int64_t x_min = std::min(ax, bx), x_max = std::max(ax, bx);
    for (std::int64_t y = y_lo; y <= y_hi; ++y) {
        // The segment's x extent within the row's slab [8y - 3, 8y + 3], widened by the square's
        // half side; the exact test decides at its ends (a pixel's slack either side).
        std::int64_t lo = x_min, hi = x_max;
        if (dy != 0) {
            const double t0 = double(8 * y - 3 - ay) / double(dy), t1 = double(8 * y + 3 - ay) / double(dy);
            const double ta = std::max(0.0, std::min(t0, t1)), tb = std::min(1.0, std::max(t0, t1));
            const double xa = double(ax) + ta * double(dx), xb = double(ax) + tb * double(dx);
            lo = std::max(x_min, std::int64_t(std::min(xa, xb)) - 8);
            hi = std::min(x_max, std::int64_t(std::max(xa, xb)) + 8);
        }
        const std::int64_t x0 = std::max<std::int64_t>(0, cdiv(lo - 3)), x1 = std::min<std::int64_t>(width - 1, fdiv(hi + 3));
        for (std::int64_t x = x0; x <= x1; ++x)
            if (meets(x, y)) fn(int(x), int(y));
    }
}

}  // namespace erd
