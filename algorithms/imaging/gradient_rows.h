// The gradient of edge detection's step 1 (canny.h), streamed row by row, and the
// rows of phi_bar it is computed from. Internal to canny.cpp (its streaming pass, its sampled
// bound, canny_gradient); kept apart so that canny.cpp holds the detection itself.
#pragma once
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

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
// signal. Rows y_begin .. y_end - 1 are made (0, h: all): fill(Y, row) writes row Y of f (w
// floats), asked for once each, in increasing Y, from c + 1 rows above y_begin (rows of f are
// clamped to the image, so a row's values do not depend on where the range starts).
// mag_row(y) is where the magnitudes of row y go (w floats); then emit(y, gx, gy) with the
// components of row y, whose buffers stay valid until row y + 2 is emitted.
template <class Fill, class MagRow, class Emit>
void gradient_rows(int w, int h, int y_begin, int y_end, const std::vector<double>& taps, Border border, Fill fill,
                   MagRow mag_row, Emit emit) {
    const int m = int(taps.size()), c = m / 2;
    const std::vector<float> bt(taps.begin(), taps.end());
    const int wf = round8(w);      // f rows and gradient rows, zero past w
    const int ns = round8(w + 2);  // smoothed rows: columns -1 .. ns - 2
    const int lf = c + 1;          // frame of t on the left (the extension rule fills it)
    std::vector<float> ring(std::size_t(m) * std::size_t(wf), 0.0f), zero(std::size_t(wf), 0.0f);
    std::vector<float> tbuf(std::size_t(lf + ns + c + 8), 0.0f), sbuf(std::size_t(3) * std::size_t(ns + 8), 0.0f);
    std::vector<float> comp(std::size_t(4) * std::size_t(wf), 0.0f);  // gx, gy for two rows
    std::vector<float> sq(std::size_t(wf), 0.0f);                      // gx^2 + gy^2
    std::vector<const float*> src(static_cast<std::size_t>(m), nullptr);
    float* const t = tbuf.data() + lf;
    int made = std::max(0, y_begin - 1 - c);  // next row of f to generate
    auto f_row = [&](int Y) -> const float* {
        if (Y < 0 || Y >= h) {
            if (border == Border::zero) return zero.data();
            Y = Y < 0 ? 0 : h - 1;
        }
        for (; made <= Y; ++made) fill(made, ring.data() + std::size_t(made % m) * std::size_t(wf));
        return ring.data() + std::size_t(Y % m) * std::size_t(wf);
    };
    auto s_row = [&](int y) { return sbuf.data() + std::size_t((y + 3) % 3) * std::size_t(ns + 8); };
    // Smoothed row y (y = -1 .. h) into s_row(y): column pass into t, extension of t (a column of
    // the extended f repeats column 0 or w-1, or is zero, so t's frame does the same), row pass.
    auto smooth = [&](int y) {
        for (int k = 0; k < m; ++k) src[std::size_t(k)] = f_row(y + c - k);  // largest row first
        weighted_sum(src.data(), bt.data(), m, t, wf);
        for (int i = 1; i <= lf; ++i) {
            t[-i] = border == Border::zero ? 0.0f : t[0];
            t[w - 1 + i] = border == Border::zero ? 0.0f : t[w - 1];
        }
        for (int k = 0; k < m; ++k) src[std::size_t(k)] = t - 1 + c - k;
        weighted_sum(src.data(), bt.data(), m, s_row(y), ns);
    };
    smooth(y_begin - 1);
    smooth(y_begin);
    for (int y = y_begin; y < y_end; ++y) {
        smooth(y + 1);
        const float* mid = s_row(y) + 1;
        const float* up = s_row(y - 1) + 1;
        const float* down = s_row(y + 1) + 1;
        float* gx = comp.data() + std::size_t(2 * (y & 1)) * std::size_t(wf);
        float* gy = gx + wf;
        central_differences(mid, up, down, gx, gy, sq.data(), wf);
        float* __restrict mag = mag_row(y);
        for (int x = 0; x < w; ++x) mag[x] = std::sqrt(sq[std::size_t(x)]);
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
