// Reconstruction by scan conversion (see reconstruct.h): the checks and face planes come from
// prepared_model.h, point evaluation is here, 4x4 supersampling in supersampling.cpp.
#include "algorithms/model/reconstruct.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/imaging/real_image.h"
#include "algorithms/model/discontinuity_mean.h"
#include "algorithms/model/edge_kinds.h"
#include "algorithms/model/prepared_model.h"
#include "algorithms/model/supersampling.h"
#include "kernel/raster.h"
#include "kernel/row_parallel.h"

namespace erd {
namespace {

// The exactly rounded plane of face f of a basic model whose corner values are integers in
// [0, maxval] (kernel/raster.h RoundedPlane); false for any other face, which is evaluated in
// doubles. Greedy refinement (algorithms/methods/greedy_rescan.cpp) makes the same choice per face, so
// GPI's errors are exactly those of this reconstruction.
bool exact_plane(const Model& m, std::size_t f, int c, RoundedPlane* rp) {
    if (m.kind != ModelKind::basic) return false;
    const auto& fc = m.faces[f];
    std::int64_t z[3];
    for (int i = 0; i < 3; ++i) {
        const double v = m.values[std::size_t(fc[i]) * std::size_t(m.channels) + std::size_t(c)];
        if (!(v >= 0.0 && v <= double(m.maxval)) || v != std::floor(v)) return false;
        z[i] = std::int64_t(v);
    }
    return rp->set(m.vertices[fc[0]], z[0], m.vertices[fc[1]], z[1], m.vertices[fc[2]], z[2], m.maxval);
}

// Every pixel is written once by its owning face, then overwritten on discontinuity edges and at
// vertices; each write is final, so it is rounded on the spot (no W x H buffer of doubles). A
// face's spans are scanned once for all channels; channel c of pixel x of a row is row[x*C + c].
// Faces in parts of 1024 at least side by side (kernel/row_parallel.h): each pixel is owned by
// one face, so the parts write disjoint pixels and the image is the same for any count; the
// discontinuity and vertex writes over them follow on one thread, in their order.
void point_evaluation(const Model& m, const PreparedModel& p, Image* out, ProgressHook progress, int threads) {
    const std::size_t W = std::size_t(m.width), C = std::size_t(m.channels);
    const double maxval = m.maxval;
    std::uint16_t* px = out->samples.data();
    const Lattice l = Lattice::pixels();
    const RowParts parts(0, m.faces.size(), threads, 1024);
    run_parts(parts, [&](std::size_t part, std::size_t f0, std::size_t f1) {
        std::vector<Span> spans;
        RoundedPlane rp;
        // The spans of one face in one channel; `stride` is C, a constant 1 for gray so that its
        // loops stay as they were.
        const auto fill = [&](std::size_t f, std::size_t c, auto stride) {
            if (exact_plane(m, f, int(c), &rp)) {
                // p stepped from an exact start over each piece, truncated (kernel/raster.h).
                for (const Span& s : spans) {
                    std::uint16_t* row = px + std::size_t(s.y) * W * stride + c;
                    rp.pieces(s.x_begin, s.x_end, s.y, [&](std::int32_t first, std::int32_t last, double v) {
                        for (std::int32_t x = first; x <= last; ++x, v += rp.dp) row[std::size_t(x) * stride] = std::uint16_t(std::int32_t(v));
                    });
                }
                return;
            }
            const SpanPlane& pl = p.planes[f * C + c];
            const double dv = pl.step_x(l);
            for (const Span& s : spans) {
                std::uint16_t* row = px + std::size_t(s.y) * W * stride + c;
                double v = pl.at(l, s.x_begin, s.y);
                for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += dv) row[std::size_t(x) * stride] = to_sample(v, maxval);
            }
        };
        // Progress from the calling thread's part alone (the hook need not be thread-safe).
        const std::size_t n = f1 - f0, every = n / 100 + 1;
        for (std::size_t f = f0; f < f1; ++f) {
            if (part == 0 && progress && (f - f0) % every == 0) progress("reconstruct", double(f - f0) / double(n));
            const auto& fc = m.faces[f];
            scan_triangle(l, p.dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
            if (C == 1) fill(f, 0, std::integral_constant<std::size_t, 1>());
            else
                for (std::size_t c = 0; c < C; ++c) fill(f, c, C);
        }
    });
    fix_discontinuities(m, p, l, [&](std::int32_t i, std::int32_t j, int c, double mean, double) {
        px[(std::size_t(j) * W + std::size_t(i)) * C + std::size_t(c)] = to_sample(mean, maxval);
    });
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if (q.x % 2 == 0 && q.y % 2 == 0)
            for (std::size_t c = 0; c < C; ++c)
                px[(std::size_t(q.y / 2) * W + std::size_t(q.x / 2)) * C + c] = to_sample(p.vertex_value(m, std::uint32_t(v), c), maxval);
    }
}

// A real model (issue 47): every pixel is the plane of the face that owns it, in doubles, no rounding
// and no means on discontinuities or at vertices (the values its method measured); pixels no face
// owns (over nodata) are nodata. The image is real: its range that of the values written.
Status real_point_evaluation(const Model& m, const PreparedModel& p, Image* out, ProgressHook progress, int threads) {
    const std::size_t W = std::size_t(m.width), C = std::size_t(m.channels), n = W * std::size_t(m.height);
    std::vector<double> values(n * C, 0.0);
    std::vector<std::uint8_t> owned(n, 0);
    const Lattice l = Lattice::pixels();
    const RowParts parts(0, m.faces.size(), threads, 1024);
    run_parts(parts, [&](std::size_t part, std::size_t f0, std::size_t f1) {
        std::vector<Span> spans;
        const std::size_t every = (f1 - f0) / 100 + 1;
        for (std::size_t f = f0; f < f1; ++f) {
            if (part == 0 && progress && (f - f0) % every == 0) progress("reconstruct", double(f - f0) / double(f1 - f0));
            const auto& fc = m.faces[f];
            scan_triangle(l, p.dom, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], &spans);
            for (std::size_t c = 0; c < C; ++c) {
                const SpanPlane& pl = p.planes[f * C + c];
                const double dv = pl.step_x(l);
                for (const Span& s : spans) {
                    double v = pl.at(l, s.x_begin, s.y);
                    double* row = values.data() + std::size_t(s.y) * W * C + c;
                    for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += dv) row[std::size_t(x) * C] = v;
                }
            }
            for (const Span& s : spans)
                for (std::int32_t x = s.x_begin; x <= s.x_end; ++x) owned[std::size_t(s.y) * W + std::size_t(x)] = 1;
        }
    });
    RasterMeta meta = m.meta;
    for (std::size_t i = 0; i < n; ++i)
        if (!owned[i])
            for (std::size_t c = 0; c < C; ++c) values[i * C + c] = std::numeric_limits<double>::quiet_NaN();
    return make_real_image(m.width, m.height, m.channels, std::move(values), meta, out);
}

Status reconstruct_with(const Model& m, const ModelTopology* given, bool supersample, Image* out, ProgressHook progress,
                        int threads) {
    PreparedModel p;
    if (Status s = prepare_model(m, false, given, &p); !s) return s;
    if (m.real) {
        if (Status s = real_point_evaluation(m, p, out, progress, threads); !s) return s;
        progress("reconstruct", 1.0);
        return Status::success();
    }
    // In *out's memory when it has the size already (a caller measuring models one after the
    // other): a fresh page costs more than zeroing it (DECISIONS "Memory").
    Image im;
    if (out->width == m.width && out->height == m.height && out->channels == m.channels) {
        im = std::move(*out);
        std::fill(im.samples.begin(), im.samples.end(), std::uint16_t(0));
        im.maxval = m.maxval;
    } else {
        im = Image(m.width, m.height, m.maxval, m.channels);
    }
    im.meta = m.meta;  // georeferencing and nodata travel to the image (its samples are not touched)
    if (supersample) supersampling(m, p, &im, progress, threads);
    else point_evaluation(m, p, &im, progress, threads);
    // Per-edge kinds (edge_kinds.h): the pixels the exceptions govern as their kind says.
    if (m.kind == ModelKind::erd && !m.kind_exceptions.empty() && (exception_kind(m) == EdgeKind::soft) != supersample) {
        Image other(m.width, m.height, m.maxval, m.channels);
        if (supersample) point_evaluation(m, p, &other, {}, threads);
        else supersampling(m, p, &other, {}, threads);
        const std::vector<std::uint8_t> governed = exception_pixels(m);
        const std::size_t C = std::size_t(m.channels);
        for (std::size_t i = 0; i < governed.size(); ++i)
            if (governed[i])
                for (std::size_t c = 0; c < C; ++c) im.samples[i * C + c] = other.samples[i * C + c];
    }
    progress("reconstruct", 1.0);
    *out = std::move(im);
    return Status::success();
}

}  // namespace

Status check_triangulation(const Model& m) {
    PreparedModel p;
    return prepare_model(m, true, nullptr, &p);
}

Status reconstruct(const Model& m, const ModelTopology& topo, bool supersample, Image* out, ProgressHook progress,
                   int threads) {
    return reconstruct_with(m, &topo, supersample, out, progress, threads);
}

Status reconstruct(const Model& m, bool supersample, Image* out, ProgressHook progress, int threads) {
    return reconstruct_with(m, nullptr, supersample, out, progress, threads);
}

}  // namespace erd