#include "algorithms/methods/greedy.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <type_traits>

#include "algorithms/methods/colour_scan.h"
#include "algorithms/methods/heap.h"
#include "kernel/raster_rows.h"

namespace erd {

const char* to_string(GreedyStop s) {
    switch (s) {
        case GreedyStop::target: return "target";
        case GreedyStop::max_error: return "max_error";
        case GreedyStop::psnr: return "psnr";
        case GreedyStop::triangles: return "triangles";
        case GreedyStop::exhausted: return "exhausted";
    }
    return "?";
}

namespace {

constexpr int kMaxChannels = 3;  // the colour scan's per-channel arrays (RGB)

// Per-face bookkeeping: the face's squared-error sum over the pixels it owns and its candidate.
struct FaceState {
    double sum = 0.0;
    double cand_error = -1.0;  // < 0: no admissible candidate
    LatticePoint cand;
};

std::uint64_t tie_of(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

// The inner loops of the face scan, one span at a time: the value v steps by dv per pixel. Each
// adds the squared errors to *sum and moves the candidate (*best, *bx) to the first pixel of
// larger absolute error that is not banned; returns true when it moved.
//
// Rounded: the approximation as imgsyn makes it (algorithms/model/reconstruct.cpp), so errors are
// integers and sums exact. Two ways to get it (see scan_exact and Refiner::rescan):
//   exact: v is p of kernel/raster.h RoundedPlane, whose truncation IS the rounded value;
//   clamp: v is the real plane, clamped to [0, maxval] and rounded half up as to_sample does.
enum class Rounding { exact, clamp };

template <Rounding R>
inline std::int32_t rounded(double v, double maxval) {
    if (R == Rounding::exact) return std::int32_t(v);
    // Clamp above in double (also keeps the conversion in range), round by truncation, clamp
    // below in integers: any v < 0.5 gives 0 as to_sample does (truncation stands in for
    // std::floor, a libm call without SSE4.1; they agree for v + 0.5 >= 0). Cheaper than a
    // double clamp, which GCC compiles into a 5-instruction blend.
    const double c = v < maxval ? v : maxval;
    const std::int32_t r = std::int32_t(c + 0.5);
    return r < 0 ? 0 : r;
}

// Calls visit(x, v) for x = x0..x1 with the running value v, v + dv, v + dv + dv, ... (the
// serial sum reconstruction steps too). Four pixels per trip; v is updated in place (no copies of
// it are live, which saves a register copy per pixel with two-operand SSE).
template <class Visit>
inline void step_span(std::int32_t x0, std::int32_t x1, double v, double dv, Visit& visit) {
    std::int32_t x = x0;
    for (; x + 3 <= x1; x += 4) {
        visit(x, v);
        v += dv;
        visit(x + 1, v);
        v += dv;
        visit(x + 2, v);
        v += dv;
        visit(x + 3, v);
        v += dv;
    }
    for (; x <= x1; ++x, v += dv) visit(x, v);
}

// The colour scan of one span (Refiner::rescan_colour), C = 3 channels: the sum of the squared
// channel errors and the candidate by their largest (ByMax) or their sum. Round: values rounded
// and clamped as reconstruction writes them.
template <bool Round, bool ByMax>
inline bool scan_colour(const std::uint16_t* s, const std::uint8_t* banned, std::int32_t x0, std::int32_t x1,
                        const double* v, const double* dv, double maxval, double* sum, double* best, std::int32_t* bx) {
    // The running values in locals (not through v, which the stores to *sum could alias).
    double v0 = v[0], v1 = v[1], v2 = v[2];
    const double d0 = dv[0], d1 = dv[1], d2 = dv[2];
    double acc = 0.0, b = *best;
    bool moved = false;
    const auto sq = [maxval](std::uint16_t sample, double a) {
        const double e = Round ? double(std::int32_t(sample) - rounded<Rounding::clamp>(a, maxval)) : double(sample) - a;
        return e * e;
    };
    for (std::int32_t x = x0; x <= x1; ++x, s += 3) {
        const double e0 = sq(s[0], v0), e1 = sq(s[1], v1), e2 = sq(s[2], v2);
        v0 += d0;
        v1 += d1;
        v2 += d2;
        const double t = (e0 + e1) + e2;
        acc += t;
        const double metric = ByMax ? std::max(std::max(e0, e1), e2) : t;
        if (metric > b && !banned[x]) {
            b = metric;
            *bx = x;
            moved = true;
        }
    }
    *sum += acc;
    *best = b;
    return moved;
}

// Squared errors in 32 bits: |sample - r| <= 65535, and 65535^2 < 2^32.
template <Rounding R>
inline bool scan_rounded(const std::uint16_t* samples, const std::uint8_t* banned, std::int32_t x0, std::int32_t x1,
                         double v, double dv, double maxval, std::int64_t* sum, std::int64_t* best_sq,
                         std::int32_t* bx) {
    std::uint64_t acc = 0;
    std::int64_t b = *best_sq;  // the candidate is compared by squared error: no abs
    bool moved = false;
    auto visit = [&](std::int32_t x, double vx) {
        const std::uint32_t e = std::uint32_t(std::int32_t(samples[x]) - rounded<R>(vx, maxval));
        const std::uint32_t e2 = e * e;
        acc += e2;
        if (std::int64_t(e2) > b && !banned[x]) {
            b = e2;
            *bx = x;
            moved = true;
        }
    };
    step_span(x0, x1, v, dv, visit);
    *sum += std::int64_t(acc);
    *best_sq = b;
    return moved;
}

// Exact rounding of row j, columns x0..x1: p stepped from an exact start value over each piece
// of at most plane.run pixels (kernel/raster.h has the error bound), truncated, no clamp (the
// rounded plane of a face stays in [0, maxval] on the pixels it owns).
inline bool scan_exact(const std::uint16_t* samples, const std::uint8_t* banned, std::int32_t j, std::int32_t x0,
                       std::int32_t x1, const RoundedPlane& plane, std::int64_t* sum, std::int64_t* best_sq,
                       std::int32_t* bx) {
    bool moved = false;
    plane.pieces(x0, x1, j, [&](std::int32_t first, std::int32_t last, double p) {
        moved |= scan_rounded<Rounding::exact>(samples, banned, first, last, p, plane.dp, 0.0, sum, best_sq, bx);
    });
    return moved;
}

// Real-valued: errors against the plane itself. The candidate test |e| > best is screened by
// e^2 >= best^2 (*best2 holds the rounded square of *best, or -1 while there is no candidate): the
// rounded square is monotone in |e|, so every pixel that passes the exact test passes the screen,
// and the screen costs nothing because e^2 is needed for the sum anyway. The sum is accumulated
// pixel by pixel in scan order, as before, so it is the same double.
inline bool scan_real(const std::uint16_t* samples, const double* as_double, const std::uint8_t* banned,
                      std::int32_t x0, std::int32_t x1, double v, double dv, double* sum, double* best,
                      double* best2, std::int32_t* bx) {
    double acc = 0.0, b = *best, b2 = *best2;
    bool moved = false;
    auto visit = [&](std::int32_t x, double vx) {
        const double e = as_double[samples[x]] - vx;
        const double e2 = e * e;
        acc += e2;
        if (e2 >= b2 && std::fabs(e) > b && !banned[x]) {
            b = std::fabs(e);
            b2 = e2;
            *bx = x;
            moved = true;
        }
    };
    step_span(x0, x1, v, dv, visit);
    *sum += acc;
    *best = b;
    *best2 = b2;
    return moved;
}

class Refiner {
public:
    Refiner(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options)
        : cdt_(cdt), image_(image), model_(model), options_(options),
          banned_(std::size_t(image.width) * std::size_t(image.height), 0),
          domain_{cdt.max_x(), cdt.max_y()}, channels_(image.channels) {
        peak_ = std::pow(2.0, image.bits()) - 1.0;
        if (!options.round_values)
            for (std::uint32_t s = 0; s <= image.maxval; ++s) as_double_.push_back(double(s));
        track_max_ = options.max_error >= 0.0;
        if (options.supersampled) {
            const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
            sub_.assign(16 * w * h, 0.0f);
            left_.assign(4 * h, 0.0f);
            right_.assign(4 * h, 0.0f);
            top_.assign(4 * w, 0.0f);
            bottom_.assign(4 * w, 0.0f);
            owner_.assign(w * h, 0);
        }
        // Each insertion adds two faces; reserving avoids regrowing the heaps' back-pointer arrays.
        std::size_t faces = 2 * std::max(options.target_vertices, cdt.vertex_count()) + 8;
        by_sum_.reserve(faces);
        if (track_max_) by_max_.reserve(faces);
        faces_.reserve(faces);
        stamp_.reserve(faces);
    }

    Status run(GreedyStats* stats) {
        for (LatticePoint p : cdt_.points()) ban(p);
        grow();
        if (options_.supersampled) {
            for (FaceInd f = 0; f < FaceInd(faces_.size()); ++f) paint(f);
            touched_.clear();
        }
        for (FaceInd f = 0; f < FaceInd(faces_.size()); ++f) rescan(f);

        GreedyStop stop;
        std::vector<FaceInd> dirty;
        const std::size_t start = cdt_.vertex_count();
        const std::size_t todo = options_.target_vertices > start ? options_.target_vertices - start : 0;
        const std::size_t report_every = std::max<std::size_t>(1, todo / 100);
        for (;;) {
            if (options_.progress && stats->insertions % report_every == 0 &&
                options_.progress.report_cancelled("greedy insertion", todo ? double(stats->insertions) / double(todo) : 1.0))
                return Status::failure(kCancelled);
            if (cdt_.vertex_count() >= options_.target_vertices) { stop = GreedyStop::target; break; }
            if (track_max_ && current_max() <= options_.max_error) { stop = GreedyStop::max_error; break; }
            if (options_.psnr > 0.0 && psnr() >= options_.psnr) { stop = GreedyStop::psnr; break; }
            if (options_.max_triangles && cdt_.face_count() >= options_.max_triangles) { stop = GreedyStop::triangles; break; }
            if (by_sum_.empty()) { stop = GreedyStop::exhausted; break; }

            const FaceInd f = by_sum_.top();
            const LatticePoint p = faces_[f].cand;
            if (!model_.admissible(cdt_, p)) {
                ban(p);
                ++stats->banned;
                rescan(f);
                continue;
            }
            const std::size_t before = cdt_.vertex_count();
            VertInd v = noVertex;
            Status st = cdt_.insert_point(p, &v, f);
            if (!st) return st;
            ban(p);
            if (cdt_.vertex_count() == before) {  // already a vertex: cannot happen with p banned
                rescan(f);
                continue;
            }
            ++stats->insertions;
            dirty.clear();
            st = model_.on_vertex_inserted(cdt_, v, &dirty);
            if (!st) return st;
            grow();
            ++generation_;
            if (options_.supersampled) {
                touched_.clear();
                for (FaceInd c : cdt_.changes().created) paint(c);
                for (FaceInd c : cdt_.changes().created) rescan(c);
                for (const Span& t : touched_)
                    for (std::int32_t x = t.x_begin; x <= t.x_end; ++x) {
                        const FaceInd o = owner_[std::size_t(t.y) * std::size_t(image_.width) + std::size_t(x)];
                        if (stamp_[o] != generation_) rescan(o);
                    }
            } else {
                for (FaceInd c : cdt_.changes().created) rescan(c);
            }
            for (FaceInd d : dirty)
                if (d < faces_.size() && stamp_[d] != generation_) rescan(d);
        }
        stats->stop = stop;
        stats->total_squared_error = total_;
        stats->max_error = 0.0;
        for (const FaceState& fs : faces_) stats->max_error = std::max(stats->max_error, fs.cand_error);
        stats->psnr = psnr();
        return Status::success();
    }

private:
    void ban(LatticePoint p) {
        if ((p.x & 1) || (p.y & 1)) return;  // half-pixel points are never candidates anyway
        banned_[std::size_t(p.y / 2) * std::size_t(image_.width) + std::size_t(p.x / 2)] = 1;
    }

    void grow() {
        if (faces_.size() < cdt_.face_count()) {
            faces_.resize(cdt_.face_count());
            stamp_.resize(cdt_.face_count(), 0);
        }
    }

    double current_max() const { return by_max_.empty() ? 0.0 : by_max_.top_key(); }

    double psnr() const {
        if (total_ <= 0.0) return std::numeric_limits<double>::infinity();
        double mse = total_ / (double(image_.width) * double(image_.height) * double(channels_));
        return 10.0 * std::log10(peak_ * peak_ / mse);
    }

    // Supersampled errors: writes the model's plane of face f at the sub-samples it owns (and at
    // the border-line points its clamped border sub-samples take), and appends to touched_ the
    // pixel runs whose values that changed.
    void paint(FaceInd f) {
        const LatticePoint a = cdt_.point(cdt_.face_vertex(f, 0)), b = cdt_.point(cdt_.face_vertex(f, 1)),
                           c = cdt_.point(cdt_.face_vertex(f, 2));
        const SpanPlane plane = model_.face_plane(cdt_, f);
        const Lattice sub = Lattice::supersample();
        const std::size_t sw = 4 * std::size_t(image_.width);
        scan_triangle(sub, domain_, a, b, c, &spans_);
        const double dv = plane.step_x(sub);
        for (const Span& sp : spans_) {
            float* row = &sub_[std::size_t(sp.y) * sw];
            double v = plane.at(sub, sp.x_begin, sp.y);
            for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i, v += dv) row[i] = float(v);
            touched_.push_back({sp.y >> 2, sp.x_begin >> 2, sp.x_end >> 2});
        }
        // The border lines (as algorithms/model/reconstruct.cpp clamps onto them) and the corners.
        const std::int32_t mx = domain_.max_x, my = domain_.max_y;
        const auto touches_x = [&](std::int32_t x) { return a.x == x || b.x == x || c.x == x; };
        const auto touches_y = [&](std::int32_t y) { return a.y == y || b.y == y || c.y == y; };
        const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
        if (touches_x(0) || touches_x(mx)) {
            const Lattice cols{4, 4 * mx, 2, 0, -3};
            scan_triangle(cols, domain_, a, b, c, &spans_);
            for (const Span& sp : spans_)
                for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i) {
                    (i == 0 ? left_ : right_)[std::size_t(sp.y)] = float(plane.at(cols, i, sp.y));
                    const std::int32_t x = i == 0 ? 0 : last_x;
                    touched_.push_back({sp.y >> 2, x, x});
                }
        }
        if (touches_y(0) || touches_y(my)) {
            const Lattice rows{4, 2, 4 * my, -3, 0};
            scan_triangle(rows, domain_, a, b, c, &spans_);
            for (const Span& sp : spans_) {
                float* line = sp.y == 0 ? top_.data() : bottom_.data();
                for (std::int32_t i = sp.x_begin; i <= sp.x_end; ++i) line[i] = float(plane.at(rows, i, sp.y));
                touched_.push_back({sp.y == 0 ? 0 : last_y, sp.x_begin >> 2, sp.x_end >> 2});
            }
        }
        // A corner (always a vertex) takes the plane of the face owning its pixel: its value in
        // that face (reconstruction: the mean of its wedges, which differs only when an edge
        // constraint ends at the corner).
        for (int k = 0; k < 4; ++k) {
            const std::int32_t i = (k & 1) ? last_x : 0, j = (k & 2) ? last_y : 0;
            if (triangle_owns(Lattice::pixels(), domain_, a, b, c, i, j)) {
                corner_[k] = plane.at(double(2 * i), double(2 * j));
                touched_.push_back({j, i, i});
            }
        }
    }

    // The supersampled approximation at pixel (x, y), rounded half up and clamped to [0, maxval]:
    // the mean of its 16 sub-samples, those outside the domain clamped onto its border.
    std::int32_t supersampled_value(std::int32_t x, std::int32_t y) const {
        const std::size_t sw = 4 * std::size_t(image_.width);
        const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
        double s = 0;
        if (x > 0 && y > 0 && x < last_x && y < last_y) {  // no clamped sub-samples
            const float* row = &sub_[std::size_t(4 * y) * sw + 4 * std::size_t(x)];
            for (int l = 0; l < 4; ++l, row += sw) s += (double(row[0]) + row[1]) + (double(row[2]) + row[3]);
        } else {
            s = border_sum(x, y);
        }
        const double v = s / 16.0, maxval = double(image_.maxval);
        const double c = v < maxval ? v : maxval;
        const std::int32_t r = std::int32_t(c + 0.5);
        return r < 0 ? 0 : r;
    }

    // The 16 sub-samples' sum at a pixel on the image frame, the outside ones clamped.
    double border_sum(std::int32_t x, std::int32_t y) const {
        const std::size_t sw = 4 * std::size_t(image_.width);
        const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
        double s = 0;
        for (int l = 0; l < 4; ++l) {
            const std::int32_t jy = 4 * y + l;
            const bool out_y = (y == 0 && l < 2) || (y == last_y && l >= 2);
            const float* row = &sub_[std::size_t(jy) * sw + 4 * std::size_t(x)];
            for (int k = 0; k < 4; ++k) {
                const std::int32_t ix = 4 * x + k;
                const bool out_x = (x == 0 && k < 2) || (x == last_x && k >= 2);
                if (out_x && out_y) s += corner_[(x == 0 ? 0 : 1) + (y == 0 ? 0 : 2)];
                else if (out_x) s += (x == 0 ? left_ : right_)[std::size_t(jy)];
                else if (out_y) s += (y == 0 ? top_ : bottom_)[std::size_t(ix)];
                else s += row[k];
            }
        }
        return s;
    }

    // Scans the pixels face f owns against the model's plane: new sum and candidate.
    void rescan(FaceInd f) {
        if (channels_ > 1) return rescan_colour(f);
        stamp_[f] = generation_;
        FaceState& fs = faces_[f];
        total_ -= fs.sum;
        const LatticePoint p[3] = {cdt_.point(cdt_.face_vertex(f, 0)), cdt_.point(cdt_.face_vertex(f, 1)),
                                   cdt_.point(cdt_.face_vertex(f, 2))};
        // Rounded scans of a face with integer corner values in [0, maxval] round exactly (as
        // reconstruction does for such a face); the others step the model's plane.
        std::int64_t z[3];
        RoundedPlane exact;
        const bool is_exact = options_.round_values && !options_.supersampled && model_.integer_values(cdt_, f, z) &&
                              exact.set(p[0], z[0], p[1], z[1], p[2], z[2], image_.maxval);
        const SpanPlane plane = is_exact ? SpanPlane() : model_.face_plane(cdt_, f);
        const double dv = 2.0 * plane.gx;
        // Row j of the pixel lattice, columns lo..hi: the row's samples and ban flags, and the
        // plane at its first pixel (with_value; the exact scan does not need it).
        // Pixel (i, j) is doubled point (2i, 2j): the same values as
        // plane.at(Lattice::pixels(), i, j) and step_x (which divide by the lattice's scale 1)
        // without two divisions per row.
        const std::uint16_t* const samples = image_.samples.data();
        const std::uint8_t* const banned = banned_.data();
        const std::size_t width = std::size_t(image_.width);
        auto walk = [&](auto with_value, auto&& scan_row) {
            OwnedRows rows(Lattice::pixels(), domain_, p[0], p[1], p[2]);
            for (RowRun part; rows.next(&part);) {
                for (RowRun run = part; run.j <= run.j_end; run.step()) {
                    std::int64_t lo64, hi64;
                    run.columns(&lo64, &hi64);
                    if (lo64 > hi64) continue;
                    const std::int32_t j = std::int32_t(run.j), lo = std::int32_t(lo64), hi = std::int32_t(hi64);
                    const std::size_t row = std::size_t(j) * width;
                    if constexpr (decltype(with_value)::value)
                        scan_row(samples + row, banned + row, j, lo, hi, plane.at(double(2 * lo), double(2 * j)));
                    else
                        scan_row(samples + row, banned + row, j, lo, hi);
                }
            }
        };
        double sum = 0.0, best = -1.0;
        std::int32_t bx = 0, by = 0;
        if (options_.supersampled) {
            std::int64_t isum = 0, ibest_sq = -1;
            walk(std::false_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                        std::int32_t lo, std::int32_t hi) {
                FaceInd* own = &owner_[std::size_t(j) * width];
                for (std::int32_t x = lo; x <= hi; ++x) {
                    own[x] = f;
                    const std::int64_t e = std::int64_t(srow[x]) - supersampled_value(x, j);
                    isum += e * e;
                    if (e * e > ibest_sq && !brow[x]) {
                        ibest_sq = e * e;
                        bx = x;
                        by = j;
                    }
                }
            });
            sum = double(isum);
            best = ibest_sq < 0 ? -1.0 : std::sqrt(double(ibest_sq));
        } else if (options_.round_values) {
            std::int64_t isum = 0, ibest_sq = -1;
            if (is_exact) {
                walk(std::false_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                            std::int32_t lo, std::int32_t hi) {
                    if (scan_exact(srow, brow, j, lo, hi, exact, &isum, &ibest_sq, &bx)) by = j;
                });
            } else {
                const double maxval = double(image_.maxval);
                walk(std::true_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                           std::int32_t lo, std::int32_t hi, double v) {
                    if (scan_rounded<Rounding::clamp>(srow, brow, lo, hi, v, dv, maxval, &isum, &ibest_sq, &bx)) by = j;
                });
            }
            sum = double(isum);
            best = ibest_sq < 0 ? -1.0 : std::sqrt(double(ibest_sq));  // exact: a perfect square
        } else {
            double best2 = -1.0;
            walk(std::true_type(), [&](const std::uint16_t* srow, const std::uint8_t* brow, std::int32_t j,
                                       std::int32_t lo, std::int32_t hi, double v) {
                if (scan_real(srow, as_double_.data(), brow, lo, hi, v, dv, &sum, &best, &best2, &bx)) by = j;
            });
        }
        if (best > 0.0) fs.cand = LatticePoint{2 * bx, 2 * by};
        settle(f, sum, best);
    }

    // rescan for a colour image: every channel's plane by point evaluation, stepped along each
    // span (rounded and clamped as reconstruction writes it when round_values). The candidate
    // metric is the sum of squared channel errors or the largest squared channel error.
    // Kept out of rescan: inlined, it costs the gray scan registers.
    [[gnu::noinline]] void rescan_colour(FaceInd f) {
        stamp_[f] = generation_;
        total_ -= faces_[f].sum;
        const int C = channels_;
        SpanPlane planes[kMaxChannels];
        for (int c = 0; c < C; ++c) planes[c] = model_.channel_face_plane(cdt_, f, c);
        const LatticePoint p0 = cdt_.point(cdt_.face_vertex(f, 0)), p1 = cdt_.point(cdt_.face_vertex(f, 1)),
                           p2 = cdt_.point(cdt_.face_vertex(f, 2));
        const bool round = options_.round_values, by_max = options_.max_channel_error;
        const double maxval = double(image_.maxval);
        const std::size_t width = std::size_t(image_.width);
        double sum = 0.0, best = -1.0;
        std::int32_t bx = 0, by = 0;
        // 8-bit images, rounded, by the largest channel error (the default): the fixed-point scan.
        if (round && by_max && image_.maxval <= 255 && fixed_scan(planes, p0, p1, p2, &sum, &best, &bx, &by)) {
            if (best >= 0.0) faces_[f].cand = LatticePoint{2 * bx, 2 * by};
            settle(f, sum, best > 0.0 ? std::sqrt(best) : -1.0);
            return;
        }
        // The owned pixels as spans (the ownership rule of OwnedRows, which the gray scan walks).
        scan_triangle(Lattice::pixels(), domain_, p0, p1, p2, &spans_);
        for (const Span& sp : spans_) {
            const std::int32_t j = sp.y, lo = sp.x_begin, hi = sp.x_end;
            double v[kMaxChannels], dv[kMaxChannels];
            for (int c = 0; c < C; ++c) {
                v[c] = planes[c].at(double(2 * lo), double(2 * j));
                dv[c] = 2.0 * planes[c].gx;
            }
            const std::uint16_t* s = &image_.samples[(std::size_t(j) * width + std::size_t(lo)) * std::size_t(C)];
            const std::uint8_t* banned = &banned_[std::size_t(j) * width];
            const auto scan = round ? (by_max ? scan_colour<true, true> : scan_colour<true, false>)
                                    : (by_max ? scan_colour<false, true> : scan_colour<false, false>);
            if (scan(s, banned, lo, hi, v, dv, maxval, &sum, &best, &bx)) by = j;
        }
        if (best > 0.0) faces_[f].cand = LatticePoint{2 * bx, 2 * by};
        settle(f, sum, best > 0.0 ? std::sqrt(best) : -1.0);
    }

    // The colour scan of 8-bit RGB in fixed point (colour_scan.h) over the pixels the face p0 p1 p2
    // owns: *sum, *best (the largest squared channel error of the candidate, -1 for none) and the
    // candidate (*bx, *by). Each channel's plane is held in 32.32 fixed point from pixel p0, and
    // each span starts from it exactly (a span's 16.16 start is within 2^-16 of the plane). False,
    // touching nothing, for a face whose planes are too steep for the lanes (more than 2^14 a pixel:
    // slivers; the double scan takes those).
    bool fixed_scan(const SpanPlane* planes, LatticePoint p0, LatticePoint p1, LatticePoint p2, double* sum,
                    double* best, std::int32_t* bx, std::int32_t* by) {
        constexpr double one = 4294967296.0, offset = 4611686018427387904.0;  // 2^32, 2^62
        // round(x * 2^32) without a libm call: the offset keeps the truncation a floor.
        const auto fixed = [&](double x) { return std::int64_t(std::uint64_t(x * one + offset + 0.5) - std::uint64_t(offset)); };
        constexpr double steep = 16384.0;
        std::int64_t Z[3], GX[3], GY[3];
        std::int32_t dV[3];
        for (int c = 0; c < 3; ++c) {
            const SpanPlane& q = planes[c];
            const double gx = 2.0 * q.gx, gy = 2.0 * q.gy, z = q.at(double(p0.x), double(p0.y)) + 0.5;
            if (!(gx > -steep && gx < steep && gy > -steep && gy < steep && z > -steep && z < steep)) return false;
            Z[c] = fixed(z);
            GX[c] = fixed(gx);
            GY[c] = fixed(gy);
            dV[c] = std::int32_t((GX[c] + 32768) >> 16);
        }
        const std::int64_t i0 = p0.x / 2, j0 = p0.y / 2, top = (std::int64_t(image_.maxval) + 1) << 16, lim = 1 << 30;
        const std::int32_t maxval = std::int32_t(image_.maxval);
        const std::size_t width = std::size_t(image_.width);
        const std::uint16_t *samples = image_.samples.data(), *end = samples + image_.samples.size();
        colour_scan::Steps steps;
        steps.set(dV);
        std::uint64_t isum = 0;
        std::int32_t ibest = -1, cx = 0, cy = 0;
        OwnedRows rows(Lattice::pixels(), domain_, p0, p1, p2);
        for (RowRun part; rows.next(&part);) {
            for (RowRun run = part; run.j <= run.j_end; run.step()) {
                std::int64_t lo, hi;
                run.columns(&lo, &hi);
                if (lo > hi) continue;
                const std::int64_t j = run.j, n = hi - lo;
                std::int32_t V0[3];
                bool clamp = false;
                for (int c = 0; c < 3; ++c) {
                    const std::int64_t a = (Z[c] + (lo - i0) * GX[c] + (j - j0) * GY[c]) >> 16, e = a + n * dV[c];
                    if (std::min(a, e) < 0 || std::max(a, e) >= top) {
                        // Cannot happen on a basic model's faces (their planes stay within the
                        // corner values); kept so that the lanes hold every value exactly.
                        if (a < -lim || a > lim || e < -lim || e > lim) return false;
                        clamp = true;
                    }
                    V0[c] = std::int32_t(a);
                }
                const std::size_t at = std::size_t(j) * width;
                const std::uint16_t* s = samples + 3 * (at + std::size_t(lo));
                if (run.j < run.j_end) {  // the next row's samples (the interleaved image is 6 bytes a pixel)
                    __builtin_prefetch(s + 3 * width);
                    __builtin_prefetch(s + 3 * width + 3 * (hi - lo));
                }
                const std::int32_t x0 = std::int32_t(lo), x1 = std::int32_t(hi);
                const bool moved =
                    clamp ? colour_scan::scan_span<true>(s, end, banned_.data() + at, x0, x1, V0, steps, maxval, &isum, &ibest, &cx)
                          : colour_scan::scan_span<false>(s, end, banned_.data() + at, x0, x1, V0, steps, maxval, &isum, &ibest, &cx);
                if (moved) cy = std::int32_t(j);
            }
        }
        *sum = double(isum);
        *best = double(ibest);
        *bx = cx;
        *by = cy;
        return true;
    }

    // Stores face f's new error sum and candidate error (the candidate point is in faces_[f])
    // and updates the heaps.
    void settle(FaceInd f, double sum, double best) {
        FaceState& fs = faces_[f];
        fs.sum = sum;
        total_ += sum;
        if (best > 0.0) {
            fs.cand_error = best;
            by_sum_.set(f, sum, tie_of(fs.cand));
            if (track_max_) by_max_.set(f, best, tie_of(fs.cand));
        } else {
            fs.cand_error = -1.0;
            by_sum_.remove(f);
            if (track_max_) by_max_.remove(f);
        }
    }

    Cdt& cdt_;
    const Image& image_;
    GreedyModel& model_;
    const GreedyOptions& options_;
    std::vector<std::uint8_t> banned_;  // per pixel: vertex already, or refused by the model
    // Sample value -> double, for the real-valued scan: a load instead of a conversion (which
    // also needs a register cleared first).
    std::vector<double> as_double_;
    RasterDomain domain_;
    std::vector<FaceState> faces_;
    std::vector<std::uint32_t> stamp_;  // generation in which the face was last scanned
    std::uint32_t generation_ = 1;
    IndexedMaxHeap by_sum_;  // faces with a candidate, keyed on squared-error sum
    IndexedMaxHeap by_max_;  // the same faces keyed on candidate error (only for --max-error)
    bool track_max_ = false;
    // Supersampled errors (GreedyOptions::supersampled): the sub-samples of the current
    // approximation (index (4y + l) * 4W + 4x + k as Lattice::supersample()), the border lines'
    // values at the sub-sample rows / columns and the corners; the face owning each pixel; the
    // pixel runs whose values the last paints changed (Span: row y, columns x_begin..x_end).
    std::vector<float> sub_, left_, right_, top_, bottom_;
    double corner_[4] = {0, 0, 0, 0};
    std::vector<FaceInd> owner_;
    std::vector<Span> spans_, touched_;
    double total_ = 0.0;  // whole-image squared error (sum of the face sums)
    double peak_ = 255.0;
    int channels_ = 1;
};

}  // namespace

Status greedy_refine(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options,
                     GreedyStats* stats) {
    *stats = GreedyStats();
    if (cdt.max_x() != 2 * (image.width - 1) || cdt.max_y() != 2 * (image.height - 1))
        return Status::failure("greedy_refine: triangulation and image sizes differ");
    if (model.channels() != image.channels || (image.channels != 1 && image.channels != kMaxChannels))
        return Status::failure("greedy_refine: the model's and the image's channel counts differ");
    if (image.channels == 1) {
        Refiner r(cdt, image, model, options);
        return r.run(stats);
    }
    GreedyOptions colour = options;
    colour.supersampled = false;  // the colour scan evaluates points
    Refiner r(cdt, image, model, colour);
    return r.run(stats);
}

}  // namespace erd
