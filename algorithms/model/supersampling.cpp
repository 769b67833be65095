// 4x4 supersampling (see reconstruct.h).
//
// Supersampling without a supersampled buffer: the 4x4 sub-samples are the lattice
// Lattice::supersample(), whose column index i = 4x + k names pixel x directly, so a span is cut
// into runs of at most four sub-samples of one pixel and each run adds n*v + dv*n(n-1)/2 to that
// pixel's sum (one multiply-add per run, no per-sample work). Sub-samples outside Gamma are
// clamped onto its border; they are the values of the function on the border lines at the
// sub-sample rows (columns), which are themselves lattices of kernel/raster.h:
//     x = 0 and x = W-1 at the sub-sample rows   (weight 2: two sub-samples clamp to each)
//     y = 0 and y = H-1 at the sub-sample columns (weight 2)
//     the four corners                            (weight 4; always vertices)
// Points on discontinuity edges were first evaluated on their owning face; a second pass over
// those edges moves them to the mean of the two faces. Vertices never lie on the sub-sample
// lattice (odd fine coordinates), except the corners, which the border pass takes care of.
// The sums live for one band of pixel rows at a time (cache-sized), each pixel's additions made
// in the same order as in one whole-image pass, so banding changes no bit (see supersampling()).
#include "algorithms/model/supersampling.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "algorithms/model/discontinuity_mean.h"
#include "kernel/raster.h"
#include "kernel/raster_rows.h"
#include "kernel/row_parallel.h"

namespace erd {
namespace {

// A face's plane along the sub-sample rows: dv per sub-sample; a partial pixel of n = 1..3
// sub-samples starting at value v adds n*v + tri[n] and moves v on by step[n] (the products
// dv * n(n-1)/2 and dv * n, taken once per face: the same doubles).
struct RowPlane {
    double dv, four, six;  // 4 dv and 6 dv: a whole pixel adds 4v + 6dv and moves v on by 4dv
    double tri[4], step[4];
    explicit RowPlane(double d) : dv(d), four(4.0 * d), six(6.0 * d), tri{0.0, d * 0.0, d * 1.0, d * 3.0}, step{0.0, d * 1.0, d * 2.0, d * 3.0} {}
};

// One span of sub-samples on Lattice::supersample() being added to its pixel row's sums: sub-sample
// i (column index; pixel i / 4) has value v. A span covers a partial pixel at each end and whole
// pixels between.
struct SubRow {
    double* row;
    double v;
    std::int32_t i, end;  // next and last sub-sample

    std::int32_t first_whole() const { return (i + 3) >> 2; }  // first pixel covered whole (before head())
    std::int32_t end_whole() const { return (end + 1) >> 2; }  // one past the last one
    void partial(std::int32_t e, const RowPlane& rp) {
        const std::int32_t n = e - i + 1;  // 1..3
        row[i >> 2] += double(n) * v + rp.tri[n];
        v += rp.step[n];
        i = e + 1;
    }
    void head(const RowPlane& rp) {
        if ((i & 3) != 0) partial(std::min(end, i | 3), rp);
    }
    // Whole pixels up to `stop` (exclusive); i is then a pixel's first sub-sample.
    void wholes(std::int32_t stop, const RowPlane& rp) {
        for (std::int32_t x = i >> 2; x < stop; ++x, v += rp.four) row[x] += 4.0 * v + rp.six;
        i = std::max(i, stop << 2);
    }
    void tail(const RowPlane& rp) {
        if (i <= end) partial(end, rp);
    }
};

// One face's plane on Lattice::supersample() in fine units (scale 4 is a power of two: no
// rounding is added), taken once per face and channel.
struct FinePlane {
    double z0, gx, gy, x0, y0;
    RowPlane rp;
    explicit FinePlane(const SpanPlane& pl)
        : z0(pl.z0), gx(pl.gx / Lattice::supersample().scale), gy(pl.gy / Lattice::supersample().scale),
          x0(pl.x0 * Lattice::supersample().scale), y0(pl.y0 * Lattice::supersample().scale),
          rp(gx * Lattice::supersample().step_x) {}
};

// Adds the sub-samples of one pixel row of a face, its n = 1..4 sub-row spans in order, to the
// pixel sums `acc`, whose row 0 is pixel row `row0`. Each pixel gets its additions sub-row by
// sub-row, as a plain span-by-span pass would; where all four sub-rows cover pixels whole, those
// pixels take their four terms in one pass (one load and store, four independent chains of v).
void add_pixel_row(const FinePlane& fp, const Span* spans, int n, double* acc, std::size_t W, std::size_t row0) {
    const Lattice l = Lattice::supersample();
    const RowPlane& rp = fp.rp;
    const auto start = [&](const Span& s) {
        double* row = acc + (std::size_t(s.y >> 2) - row0) * W;
        const double v = fp.z0 + fp.gx * (double(l.fine_x(s.x_begin)) - fp.x0) + fp.gy * (double(l.fine_y(s.y)) - fp.y0);
        return SubRow{row, v, s.x_begin, s.x_end};
    };
    if (n == 4) {  // sub-rows 0..3 of the pixel row
        SubRow r[4] = {start(spans[0]), start(spans[1]), start(spans[2]), start(spans[3])};
        const std::int32_t p0 = std::max({r[0].first_whole(), r[1].first_whole(), r[2].first_whole(), r[3].first_whole()});
        const std::int32_t p1 = std::min({r[0].end_whole(), r[1].end_whole(), r[2].end_whole(), r[3].end_whole()});
        if (p0 < p1) {
            for (SubRow& s : r) {
                s.head(rp);
                s.wholes(p0, rp);
            }
            double* row = r[0].row;
            double v0 = r[0].v, v1 = r[1].v, v2 = r[2].v, v3 = r[3].v;
            for (std::int32_t x = p0; x < p1; ++x, v0 += rp.four, v1 += rp.four, v2 += rp.four, v3 += rp.four)
                row[x] = row[x] + (4.0 * v0 + rp.six) + (4.0 * v1 + rp.six) + (4.0 * v2 + rp.six) + (4.0 * v3 + rp.six);
            r[0].v = v0, r[1].v = v1, r[2].v = v2, r[3].v = v3;
            for (SubRow& s : r) {
                s.i = p1 << 2;
                s.wholes(s.end_whole(), rp);
                s.tail(rp);
            }
            return;
        }
    }
    for (int k = 0; k < n; ++k) {
        SubRow s = start(spans[k]);
        s.head(rp);
        s.wholes(s.end_whole(), rp);
        s.tail(rp);
    }
}

// Adds the sub-samples face (a, b, c) owns in sub-rows j_begin..j_end to the sums of its C
// channels (plane c of `acc` for channel c, plane samples apart), walking the face's rows
// (kernel/raster_rows.h) and handing each pixel row's sub-row spans on as soon as the row is
// complete: no list of spans, one walk for all channels. The additions are those of scanning the
// face's spans and adding them span by span, in the same order (pixel rows are disjoint sums).
void add_face(const FinePlane* fp, std::size_t C, LatticePoint a, LatticePoint b, LatticePoint c, RasterDomain dom,
              std::int32_t j_begin, std::int32_t j_end, double* acc, std::size_t plane, std::size_t W, std::size_t row0) {
    Span g[4];
    int n = 0;
    const auto flush = [&] {
        if (C == 1) add_pixel_row(fp[0], g, n, acc, W, row0);
        else
            for (std::size_t k = 0; k < C; ++k) add_pixel_row(fp[k], g, n, acc + k * plane, W, row0);
        n = 0;
    };
    for_each_owned_row(
        Lattice::supersample(), dom, a, b, c,
        [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            if (n > 0 && (j >> 2) != (g[0].y >> 2)) flush();
            g[n++] = Span{j, lo, hi};
        },
        j_begin, j_end);
    if (n > 0) flush();
}

// One addition to a pixel's sum made after all faces' interior sub-samples; `sample` is the
// pixel's index times C plus the channel (the index of its sample in the image).
struct LateTerm {
    std::size_t sample;
    double add;
};

// The clamped border sub-samples and the discontinuity corrections, in the order the sums take them.
std::vector<LateTerm> late_terms(const Model& m, const PreparedModel& p) {
    const std::size_t W = std::size_t(m.width), H = std::size_t(m.height), C = std::size_t(m.channels);
    std::vector<LateTerm> late;
    std::vector<Span> spans;
    const std::int32_t mx = p.dom.max_x, my = p.dom.max_y;
    const Lattice cols{4, 4 * mx, 2, 0, -3}, rows{4, 2, 4 * my, -3, 0};
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& fc = m.faces[f];
        const LatticePoint a = m.vertices[fc[0]], b = m.vertices[fc[1]], c = m.vertices[fc[2]];
        const auto touches_x = [&](std::int32_t x) { return a.x == x || b.x == x || c.x == x; };
        const auto touches_y = [&](std::int32_t y) { return a.y == y || b.y == y || c.y == y; };
        if (touches_x(0) || touches_x(mx)) {
            scan_triangle(cols, p.dom, a, b, c, &spans);
            for (const Span& s : spans)
                for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                    for (std::size_t k = 0; k < C; ++k)
                        late.push_back({(std::size_t(s.y >> 2) * W + (i == 0 ? 0 : W - 1)) * C + k, 2.0 * p.planes[f * C + k].at(cols, i, s.y)});
        }
        if (touches_y(0) || touches_y(my)) {
            scan_triangle(rows, p.dom, a, b, c, &spans);
            for (const Span& s : spans)
                for (std::int32_t i = s.x_begin; i <= s.x_end; ++i)
                    for (std::size_t k = 0; k < C; ++k)
                        late.push_back({((s.y == 0 ? 0 : H - 1) * W + std::size_t(i >> 2)) * C + k, 2.0 * p.planes[f * C + k].at(rows, i, s.y)});
        }
    }
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const LatticePoint q = m.vertices[v];
        if ((q.x == 0 || q.x == mx) && (q.y == 0 || q.y == my))
            for (std::size_t c = 0; c < C; ++c)
                late.push_back({((q.y == 0 ? 0 : H - 1) * W + (q.x == 0 ? 0 : W - 1)) * C + c, 4.0 * p.vertex_value(m, std::uint32_t(v), c)});
    }
    fix_discontinuities(m, p, Lattice::supersample(), [&](std::int32_t i, std::int32_t j, int c, double mean, double owner) {
        late.push_back({(std::size_t(j >> 2) * W + std::size_t(i >> 2)) * C + std::size_t(c), mean - owner});
    });
    return late;
}

// Pixel sums are doubles of about this many bytes per band of rows: the band stays in the L2
// cache while its faces are rasterised in any order.
constexpr std::size_t kBandBytes = std::size_t(256) << 10;

// Items 0..n-1 grouped by band, keeping their order within each band (a counting sort):
// bands(i, fn) calls fn(b) for each band b item i belongs to. Returns item lists per band in
// (*first)[b] .. (*first)[b + 1].
template <class Bands>
std::vector<std::uint32_t> group_by_band(std::size_t n, std::size_t nb, Bands bands, std::vector<std::uint32_t>* first) {
    first->assign(nb + 1, 0);
    for (std::size_t i = 0; i < n; ++i) bands(i, [&](std::size_t b) { ++(*first)[b + 1]; });
    for (std::size_t b = 0; b < nb; ++b) (*first)[b + 1] += (*first)[b];
    std::vector<std::uint32_t> items((*first)[nb]);
    std::vector<std::uint32_t> fill(first->begin(), first->end() - 1);
    for (std::size_t i = 0; i < n; ++i) bands(i, [&](std::size_t b) { items[fill[b]++] = std::uint32_t(i); });
    return items;
}

}  // namespace

// Supersampling band by band. Each pixel's sum takes exactly the additions, in exactly the order,
// of a whole-image pass (faces in face order, then the late terms), so banding changes no bit.
// The sums of channel c are plane c of the band's buffer; a face is scanned once for all of them.
void supersampling(const Model& m, const PreparedModel& p, Image* out, ProgressHook progress, int threads) {
    const std::size_t W = std::size_t(m.width), H = std::size_t(m.height), C = std::size_t(m.channels);
    const std::size_t band = std::max<std::size_t>(1, kBandBytes / (W * C * sizeof(double)));
    const std::size_t nb = (H + band - 1) / band;
    const Lattice l = Lattice::supersample();
    // The bands of the sub-sample rows j (pixel row j / 4) a face can own: fine y = phase + step * j
    // within its extent.
    const auto face_bands = [&](std::size_t f, auto fn) {
        const auto& fc = m.faces[f];
        const std::int64_t ylo = std::min({m.vertices[fc[0]].y, m.vertices[fc[1]].y, m.vertices[fc[2]].y});
        const std::int64_t yhi = std::max({m.vertices[fc[0]].y, m.vertices[fc[1]].y, m.vertices[fc[2]].y});
        const std::int64_t j0 = (ylo * l.scale - l.phase_y + l.step_y - 1) / l.step_y;  // numerators >= 0
        const std::int64_t j1 = (yhi * l.scale - l.phase_y) / l.step_y;
        const std::size_t r0 = std::size_t(j0 >> 2), r1 = std::min(H - 1, std::size_t(j1 >> 2));
        for (std::size_t b = r0 / band; b <= r1 / band; ++b) fn(b);
    };
    std::vector<std::uint32_t> face_first, late_first;
    const std::vector<std::uint32_t> band_faces = group_by_band(m.faces.size(), nb, face_bands, &face_first);
    const std::vector<LateTerm> late = late_terms(m, p);
    const std::vector<std::uint32_t> band_late =
        group_by_band(late.size(), nb, [&](std::size_t i, auto fn) { fn((C == 1 ? late[i].sample : late[i].sample / C) / W / band); }, &late_first);
    const std::size_t plane = band * W;
    const double maxval = m.maxval;
    // Threads for 2^15 samples at least each (kernel/row_parallel.h), each with sums of its own:
    // a band is finished from its own faces and late terms, so the image is the same whichever
    // thread takes it. They take the next band as they get free, not runs of bands: a thread can
    // start milliseconds late on this 2-core machine (1.8-3.9 ms on lena 3%, where the bands
    // take 9.5 ms), and halves of the image differ (7,411 and 10,016 faces there).
    const RowParts parts(0, nb, threads, rows_for(std::size_t(1) << 15, band * W * C));
    std::atomic<std::size_t> next{0};
    run_parts(parts, [&](std::size_t part, std::size_t, std::size_t) {
        std::vector<double> acc(plane * C);
        for (std::size_t b = next.fetch_add(1); b < nb; b = next.fetch_add(1)) {
            // Progress from the calling thread's part alone (the hook need not be thread-safe).
            if (part == 0) progress("reconstruct", double(b) / double(nb));
            const std::size_t row0 = b * band, rows = std::min(H, row0 + band) - row0;
            for (std::uint32_t k = face_first[b]; k < face_first[b + 1]; ++k) {
                const std::uint32_t f = band_faces[k];
                const auto& fc = m.faces[f];
                // Channel 0's plane stands in for the channels a gray model lacks (never read).
                const FinePlane fp[3] = {FinePlane(p.planes[f * C]), FinePlane(p.planes[f * C + (C > 1 ? 1 : 0)]),
                                         FinePlane(p.planes[f * C + (C > 1 ? 2 : 0)])};
                // The band's sub-rows only: a face spanning several bands is walked in pieces.
                add_face(fp, C, m.vertices[fc[0]], m.vertices[fc[1]], m.vertices[fc[2]], p.dom, std::int32_t(4 * row0),
                         std::int32_t(4 * (row0 + rows) - 1), acc.data(), plane, W, row0);
            }
            for (std::uint32_t k = late_first[b]; k < late_first[b + 1]; ++k) {
                const LateTerm& t = late[band_late[k]];
                if (C == 1) acc[t.sample - row0 * W] += t.add;
                else acc[(t.sample % C) * plane + t.sample / C - row0 * W] += t.add;
            }
            std::uint16_t* dst = out->samples.data() + row0 * W * C;
            const auto finish = [&](std::size_t c, auto stride) {
                double* sums = acc.data() + c * plane;
                for (std::size_t i = 0; i < rows * W; ++i) {
                    dst[i * stride + c] = to_sample(sums[i] * (1.0 / 16.0), maxval);
                    sums[i] = 0.0;  // ready for the next band (no separate clearing pass)
                }
            };
            if (C == 1) finish(0, std::integral_constant<std::size_t, 1>());  // a plain, vectorisable loop
            else
                for (std::size_t c = 0; c < C; ++c) finish(c, C);
        }
    });
}

}  // namespace erd
