// The gradient of edge detection's step 1 (canny.h), streamed row by row, and the
// rows of phi_bar it is computed from. Internal to the detector: the streaming pass and its
// sampled bound (canny_pass.cpp) and canny_gradient (canny.cpp).
#pragma once
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/filters.h"

namespace erd {
namespace canny_detail {

inline int round8(int n) { return (n + 7) / 8 * 8; }

// out[x] = sum_k t[k] * in[k][x] for x in [0, n), n a multiple of 8, summed in the order
// k = 0, 1, ..., m-1 (the order fixes the float result). Blocks of 8 so that -O2 vectorises.
inline void weighted_sum_any(const float* const* in, const float* t, int m, float* __restrict out, int n) {
    for (int x = 0; x < n; x += 8) {
        float acc[8];
        for (int j = 0; j < 8; ++j) acc[j] = t[0] * in[0][x + j];
        for (int k = 1; k < m; ++k)
            for (int j = 0; j < 8; ++j) acc[j] += t[k] * in[k][x + j];
        for (int j = 0; j < 8; ++j) out[x + j] = acc[j];
    }
}

// The same with m = sizeof...(K) known, so rows and taps stay in registers.
template <std::size_t... K>
inline void weighted_sum_fixed(const float* const* in, const float* t, float* __restrict out, int n, std::index_sequence<K...>) {
    const float* const p[] = {in[K]...};
    const float c[] = {t[K]...};
    for (int x = 0; x < n; x += 8)
        for (int j = x; j < x + 8; ++j) {
            float acc = c[0] * p[0][j];
            ((K > 0 ? (acc += c[K] * p[K][j], 0) : 0), ...);  // k = 1, 2, ... in order
            out[j] = acc;
        }
}

inline void weighted_sum(const float* const* in, const float* t, int m, float* out, int n) {
    switch (m) {
        case 3: weighted_sum_fixed(in, t, out, n, std::make_index_sequence<3>()); break;
        case 5: weighted_sum_fixed(in, t, out, n, std::make_index_sequence<5>()); break;
        case 7: weighted_sum_fixed(in, t, out, n, std::make_index_sequence<7>()); break;
        default: weighted_sum_any(in, t, m, out, n); break;
    }
}

// gx, gy and gx^2 + gy^2 of one row from three smoothed rows (mid[x] is column x), x in [0, n),
// n a multiple of 8; separate restrict-qualified arrays so that -O2 vectorises all of it.
inline void central_differences(const float* __restrict mid, const float* __restrict up, const float* __restrict down,
                         float* __restrict gx, float* __restrict gy, float* __restrict sq, int n) {
    for (int x = 0; x < n; x += 8)
        for (int j = x; j < x + 8; ++j) {
            const float ax = 0.5f * (mid[j + 1] - mid[j - 1]), ay = 0.5f * (down[j] - up[j]);
            gx[j] = ax;
            gy[j] = ay;
            sq[j] = ax * ax + ay * ay;
        }
}

// The gradient of step 1, streamed one row at a time so that no full-size plane but the caller's
// is ever held: f (w x h, extended by `border`) is smoothed with the binomial along y (a ring of
// taps.size() rows of f), then along x, and the central differences of three smoothed rows give
// row y. This is exactly the composed filter (derivative * binomial) applied to the extended
// signal. Rows are made from y_begin on, one next() each, in increasing y: fill(Y, row) writes
// row Y of f (w floats), asked for once each, in increasing Y, from c + 1 rows above y_begin
// (rows of f are clamped to the image, so a row's values do not depend on where the range
// starts). next() returns gx, gy and gx^2 + gy^2 of the row (valid until the row two further is
// made).
template <class Fill>
class GradientStream {
public:
    GradientStream(int w, int h, int y_begin, const std::vector<double>& taps, Border border, Fill fill)
        : w_(w), h_(h), m_(int(taps.size())), c_(m_ / 2), wf_(round8(w)), ns_(round8(w + 2)), lf_(c_ + 1),
          border_(border), fill_(fill), bt_(taps.begin(), taps.end()),
          ring_(std::size_t(m_) * std::size_t(wf_), 0.0f), zero_(std::size_t(wf_), 0.0f),
          tbuf_(std::size_t(lf_ + ns_ + c_ + 8), 0.0f), sbuf_(std::size_t(3) * std::size_t(ns_ + 8), 0.0f),
          comp_(std::size_t(4) * std::size_t(wf_), 0.0f), sq_(std::size_t(wf_), 0.0f),
          src_(static_cast<std::size_t>(m_), nullptr), made_(std::max(0, y_begin - 1 - c_)) {
        smooth(y_begin - 1);
        smooth(y_begin);
    }

    struct Row {
        const float* gx;
        const float* gy;
        const float* sq;
    };
    Row next(int y) {
        smooth(y + 1);
        const float* mid = s_row(y) + 1;
        const float* up = s_row(y - 1) + 1;
        const float* down = s_row(y + 1) + 1;
        float* gx = comp_.data() + std::size_t(2 * (y & 1)) * std::size_t(wf_);
        float* gy = gx + wf_;
        central_differences(mid, up, down, gx, gy, sq_.data(), wf_);
        return Row{gx, gy, sq_.data()};
    }

private:
    const float* f_row(int Y) {
        if (Y < 0 || Y >= h_) {
            if (border_ == Border::zero) return zero_.data();
            Y = Y < 0 ? 0 : h_ - 1;
        }
        for (; made_ <= Y; ++made_) fill_(made_, ring_.data() + std::size_t(made_ % m_) * std::size_t(wf_));
        return ring_.data() + std::size_t(Y % m_) * std::size_t(wf_);
    }
    float* s_row(int y) { return sbuf_.data() + std::size_t((y + 3) % 3) * std::size_t(ns_ + 8); }
    // Smoothed row y (y = -1 .. h) into s_row(y): column pass into t, extension of t (a column of
    // the extended f repeats column 0 or w-1, or is zero, so t's frame does the same), row pass.
    void smooth(int y) {
        float* const t = tbuf_.data() + lf_;
        for (int k = 0; k < m_; ++k) src_[std::size_t(k)] = f_row(y + c_ - k);  // largest row first
        weighted_sum(src_.data(), bt_.data(), m_, t, wf_);
        for (int i = 1; i <= lf_; ++i) {
            t[-i] = border_ == Border::zero ? 0.0f : t[0];
            t[w_ - 1 + i] = border_ == Border::zero ? 0.0f : t[w_ - 1];
        }
        for (int k = 0; k < m_; ++k) src_[std::size_t(k)] = t - 1 + c_ - k;
        weighted_sum(src_.data(), bt_.data(), m_, s_row(y), ns_);
    }

    int w_, h_, m_, c_;
    int wf_;  // f rows and gradient rows, zero past w
    int ns_;  // smoothed rows: columns -1 .. ns - 2
    int lf_;  // frame of t on the left (the extension rule fills it)
    Border border_;
    Fill fill_;
    std::vector<float> bt_, ring_, zero_, tbuf_, sbuf_;
    std::vector<float> comp_;  // gx, gy for two rows
    std::vector<float> sq_;    // gx^2 + gy^2
    std::vector<const float*> src_;
    int made_;  // next row of f to generate
};

// Rows y_begin .. y_end - 1 of the gradient of f (GradientStream; 0, h: all): mag_row(y) is where
// the magnitudes of row y go (w floats); then emit(y, gx, gy) with the components of row y, whose
// buffers stay valid until row y + 2 is emitted.
template <class Fill, class MagRow, class Emit>
void gradient_rows(int w, int h, int y_begin, int y_end, const std::vector<double>& taps, Border border, Fill fill,
                   MagRow mag_row, Emit emit) {
    GradientStream<Fill> g(w, h, y_begin, taps, border, fill);
    for (int y = y_begin; y < y_end; ++y) {
        const auto r = g.next(y);
        float* __restrict mag = mag_row(y);
        for (int x = 0; x < w; ++x) mag[x] = std::sqrt(r.sq[std::size_t(x)]);
        emit(y, r.gx, r.gy);
    }
}

// The gradient of a colour image's three channels combined into one (ColourGradient), row by row
// as gradient_rows: fill(c, Y, row) writes row Y of channel c's f.
//   dizenzo: the largest eigenvalue of the structure tensor sum_c (gx_c, gy_c)^T (gx_c, gy_c) is
//            the squared magnitude, its eigenvector the direction (Di Zenzo 1986);
//   max:     the gradient of the channel with the largest magnitude.
template <class Fill, class MagRow, class Emit>
void colour_gradient_rows(int w, int h, int y_begin, int y_end, const std::vector<double>& taps, Border border,
                          ColourGradient how, Fill fill, MagRow mag_row, Emit emit) {
    auto channel = [&](int c) { return [&fill, c](int Y, float* r) { fill(c, Y, r); }; };
    using Channel = decltype(channel(0));
    GradientStream<Channel> g0(w, h, y_begin, taps, border, channel(0)), g1(w, h, y_begin, taps, border, channel(1)),
        g2(w, h, y_begin, taps, border, channel(2));
    std::vector<float> comp(std::size_t(4) * std::size_t(w), 0.0f);  // gx, gy for two rows
    for (int y = y_begin; y < y_end; ++y) {
        const auto a = g0.next(y), b = g1.next(y), c = g2.next(y);
        float* gx = comp.data() + std::size_t(2 * (y & 1)) * std::size_t(w);
        float* gy = gx + w;
        float* __restrict mag = mag_row(y);
        for (std::size_t x = 0; x < std::size_t(w); ++x) {
            if (how == ColourGradient::max) {
                const auto& p = a.sq[x] >= b.sq[x] ? (a.sq[x] >= c.sq[x] ? a : c) : (b.sq[x] >= c.sq[x] ? b : c);
                gx[x] = p.gx[x];
                gy[x] = p.gy[x];
                mag[x] = std::sqrt(p.sq[x]);
                continue;
            }
            const double xx = double(a.gx[x]) * a.gx[x] + double(b.gx[x]) * b.gx[x] + double(c.gx[x]) * c.gx[x];
            const double yy = double(a.gy[x]) * a.gy[x] + double(b.gy[x]) * b.gy[x] + double(c.gy[x]) * c.gy[x];
            const double xy = double(a.gx[x]) * a.gy[x] + double(b.gx[x]) * b.gy[x] + double(c.gx[x]) * c.gy[x];
            const double lambda = 0.5 * (xx + yy + std::sqrt((xx - yy) * (xx - yy) + 4.0 * xy * xy));
            // The eigenvector of lambda, from the better conditioned of the two rows of the tensor.
            double ex = xx >= yy ? lambda - yy : xy, ey = xx >= yy ? xy : lambda - xx;
            const double len = std::sqrt(ex * ex + ey * ey), g = std::sqrt(lambda);
            if (len > 0.0) {
                ex *= g / len;
                ey *= g / len;
            }
            gx[x] = float(ex);
            gy[x] = float(ey);
            mag[x] = float(g);
        }
        emit(y, static_cast<const float*>(gx), static_cast<const float*>(gy));
    }
}

// Row Y of phi_bar on the half-pixel grid (step 1's f): even entries are samples, odd ones means.
template <class Sample>
void half_pixel_row(int width, int Y, Sample sample, float* r) {
    const int y0 = Y >> 1;
    // Even rows are sample rows, odd rows the means of two; written apart so that an even row
    // reads each sample once.
    float prev = (Y & 1) ? 0.5f * (float(sample(0, y0)) + float(sample(0, y0 + 1))) : float(sample(0, y0));
    r[0] = prev;
    if (Y & 1) {
        for (int x = 1; x < width; ++x) {
            const float v = 0.5f * (float(sample(x, y0)) + float(sample(x, y0 + 1)));
            r[2 * x] = v;
            r[2 * x - 1] = 0.5f * (prev + v);
            prev = v;
        }
    } else {
        for (int x = 1; x < width; ++x) {
            const float v = float(sample(x, y0));
            r[2 * x] = v;
            r[2 * x - 1] = 0.5f * (prev + v);
            prev = v;
        }
    }
}

}  // namespace canny_detail
}  // namespace erd
