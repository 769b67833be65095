// The colour greedy scan of one span of 8-bit RGB pixels (greedy_colour.cpp,
// GreedyRefiner::rescan_colour), four pixels at a time: the rounded value of each channel's plane,
// the squared channel errors, their sum over the span and the candidate by the largest channel
// error.
//
// Why its own code: the three-channel scan in doubles cost ~50 instructions a pixel, against ~12 for
// the gray exact scan, and made colour GPI 3.3x gray GPI (docs/DECISIONS.md "Colour methods"). Here
// a channel's plane is stepped in 16.16 fixed point (integer steps: the same value at every pixel
// whatever the compiler does), a group of four pixels' twelve samples in three vectors of 32-bit
// lanes (GCC/Clang vector extensions, no intrinsics: SSE2 on x86-64, NEON or scalar code elsewhere,
// the same results), and the squares come from 16-bit multiplies (|error| <= 255). The lanes keep
// the image's interleaved order (R G B R, G B R G, B R G B), so the samples come straight from the
// image's own 16-bit array by two loads and three unpacks, and each lane steps its own channel's
// plane: no copy of the channels (planar byte copies cost 3 bytes a pixel and made colour GPI's
// peak memory 1.60x gray's, over the 1.5x target).
//
// The rounding is the fixed-point plane's, floor(V / 2^16) with V = round((v + 1/2) * 2^16) at the
// span's first pixel stepped by round(dv * 2^16): within (1 + k) * 2^-17 of the real plane at the
// k-th pixel, so a pixel's rounded value can differ from the double scan's only where the plane
// is that close to a half (the double scan's own running sum lands on either side there too).
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace erd {
namespace colour_scan {

typedef std::int32_t I32x4 __attribute__((vector_size(16)));
typedef std::uint32_t U32x4 __attribute__((vector_size(16)));
typedef std::uint16_t U16x8 __attribute__((vector_size(16)));

// The twelve samples of four consecutive RGB pixels at p (each <= 255), in their interleaved
// order, into the high halves of three vectors' 32-bit lanes (the low halves zero): two 16-byte
// loads (samples 0-7 and 8-15: the next pixel's too, unused) and an unpack against zero per vector.
// Reads no sample at or past `end`: a group that would is copied into zeros first (the image's
// last pixels only); end null: no check (the caller knows).
inline void load4_rgb(const std::uint16_t* p, const std::uint16_t* end, U16x8 out[3]) {
    U16x8 a, b;
    if (!end || end - p >= 16) {
        std::memcpy(&a, p, 16);
        std::memcpy(&b, p + 8, 16);
    } else {
        std::uint16_t tail[16] = {};
        std::memcpy(tail, p, std::size_t(end - p) * sizeof(std::uint16_t));
        std::memcpy(&a, tail, 16);
        std::memcpy(&b, tail + 8, 16);
    }
    const U16x8 z = {};
    out[0] = __builtin_shufflevector(z, a, 0, 8, 1, 9, 2, 10, 3, 11);
    out[1] = __builtin_shufflevector(z, a, 4, 12, 5, 13, 6, 14, 7, 15);
    out[2] = __builtin_shufflevector(z, b, 0, 8, 1, 9, 2, 10, 3, 11);
}

// The squared errors of four samples (in the high halves of s's lanes) against the rounded values
// of V (16.16, biased by 1/2, so the rounded value is V's high half). Unclamped (V in [0, 2^24) on
// the span): the high halves subtract in 16 bits and square exactly (|error| <= 255), the low
// halves (the fractions) are garbage that the shift drops. Clamped: the rounded value clamped to
// [0, maxval] first. In unsigned 16-bit lanes, which wrap: the square of the wrapped difference is
// the square of the error modulo 2^16, which it is below.
template <bool Clamp>
inline I32x4 squared(U16x8 s, U32x4 V, std::int32_t maxval) {
    if (Clamp) {
        I32x4 r = I32x4(V) >> 16;
        r = r < 0 ? 0 : r;
        r = r > maxval ? maxval : r;
        V = U32x4(r) << 16;
    }
    const U16x8 e = s - U16x8(V);
    return I32x4(U32x4(e * e) >> 16);
}

inline bool any(I32x4 m) {
    typedef std::uint64_t U64x2 __attribute__((vector_size(16)));
    const U64x2 q = U64x2(m);
    return (q[0] | q[1]) != 0;
}

// One face's three planes for scan_span, in the lanes' interleaved order: lane i of vector v holds
// sample 4v + i of a group, pixel (4v + i) / 3 of channel (4v + i) % 3. offset: that pixel's
// offset from the group's first, times its channel's 16.16 step a pixel d; group: 4d, a group's
// step.
struct Steps {
    U32x4 offset[3], group[3];
    void set(const std::int32_t dV[3]) {
        for (int v = 0; v < 3; ++v)
            for (int i = 0; i < 4; ++i) {
                const int k = 4 * v + i;
                const std::uint32_t d = std::uint32_t(dV[k % 3]);
                offset[v][i] = std::uint32_t(k / 3) * d;
                group[v][i] = 4 * d;
            }
    }
};

// Span x0..x1 of one row: s points at pixel x0's first sample in the interleaved image, whose
// samples end at `end`; banned at the row's ban flags (indexed by x); V0[c] the fixed-point value
// of channel c at x0. Adds the squared errors of every channel to *sum and moves the candidate
// (*best: a squared channel error, < 0 for none yet; *bx) to the first pixel whose largest squared
// channel error is larger and which is not banned; returns true when it moved. Clamp: values may
// leave [0, maxval] on the span.
template <bool Clamp>
bool scan_span(const std::uint16_t* s, const std::uint16_t* end, const std::uint8_t* banned, std::int32_t x0,
               std::int32_t x1, const std::int32_t V0[3], const Steps& steps, std::int32_t maxval, std::uint64_t* sum,
               std::int32_t* best, std::int32_t* bx) {
    const std::uint32_t r = std::uint32_t(V0[0]), g = std::uint32_t(V0[1]), bl = std::uint32_t(V0[2]);
    U32x4 V0v = U32x4{r, g, bl, r} + steps.offset[0], V1v = U32x4{g, bl, r, g} + steps.offset[1],
          V2v = U32x4{bl, r, g, bl} + steps.offset[2];
    U32x4 acc = {0, 0, 0, 0};
    std::int32_t b = *best;
    I32x4 B = {b, b, b, b};
    bool moved = false;
    const std::int32_t n = x1 - x0 + 1;
    // No group can read past the image's end (all spans but those at its last pixels).
    const bool safe = end - s >= 3 * std::ptrdiff_t(n + 3) + 4;
    for (std::int32_t k = 0; k < n; k += 4) {
        U16x8 in[3];
        load4_rgb(s + 3 * k, safe ? nullptr : end, in);
        I32x4 e0 = squared<Clamp>(in[0], V0v, maxval), e1 = squared<Clamp>(in[1], V1v, maxval),
              e2 = squared<Clamp>(in[2], V2v, maxval);
        if (n - k < 4) {  // the last, partial group: the samples past the span count nothing
            const std::int32_t live = 3 * (n - k);
            e0 &= I32x4{0, 1, 2, 3} < live;
            e1 &= I32x4{4, 5, 6, 7} < live;
            e2 &= I32x4{8, 9, 10, 11} < live;
        }
        acc += U32x4(e0 + e1 + e2);
        // Rare once a face's first pixels are scanned. (Screening by the pixel's sum instead
        // costs more: the sum beats the candidate three times as often.)
        if (any((e0 > B) | (e1 > B) | (e2 > B))) {
            std::int32_t sq[12];
            std::memcpy(sq, &e0, 16);
            std::memcpy(sq + 4, &e1, 16);
            std::memcpy(sq + 8, &e2, 16);
            for (int l = 0; l < 4 && k + l < n; ++l) {
                const std::int32_t m = std::max(sq[3 * l], std::max(sq[3 * l + 1], sq[3 * l + 2]));
                if (m > b && !banned[x0 + k + l]) {
                    b = m;
                    *bx = x0 + k + l;
                    moved = true;
                }
            }
            B = I32x4{b, b, b, b};
        }
        V0v += steps.group[0];
        V1v += steps.group[1];
        V2v += steps.group[2];
    }
    *sum += std::uint64_t(acc[0]) + acc[1] + acc[2] + acc[3];
    *best = b;
    return moved;
}

}  // namespace colour_scan
}  // namespace erd
