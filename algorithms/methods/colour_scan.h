// The colour greedy scan of one span of 8-bit RGB pixels (greedy.cpp, Refiner::rescan_colour),
// four pixels at a time: the rounded value of each channel's plane, the squared channel errors,
// their sum over the span and the candidate by the largest channel error.
//
// Why its own code: the three-channel scan in doubles cost ~50 instructions a pixel, against ~12 for
// the gray exact scan, and made colour GPI 3.3x gray GPI (docs/DECISIONS.md "Colour methods"). Here
// a channel's plane is stepped in 16.16 fixed point (integer steps: the same value at every pixel
// whatever the compiler does), each group of four pixels in one vector of 32-bit lanes (GCC/Clang
// vector extensions, no intrinsics: SSE2 on x86-64, NEON or scalar code elsewhere, the same
// results), and the squares come from 16-bit multiplies (|error| <= 255). The samples are read
// from planar 8-bit copies of the channels (ColourPlanes), four consecutive bytes per load.
//
// The rounding is the fixed-point plane's, floor(V / 2^16) with V = round((v + 1/2) * 2^16) at the
// span's first pixel stepped by round(dv * 2^16): within (1 + k) * 2^-17 of the real plane at the
// k-th pixel, so a pixel's rounded value can differ from the double scan's only where the plane
// is that close to a half (the double scan's own running sum lands on either side there too).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace erd {

// The channels of an interleaved 8-bit RGB image as three planes of bytes, each padded by three
// bytes so a four-byte load at the last pixel stays inside the buffer.
class ColourPlanes {
public:
    void build(const std::uint16_t* interleaved, std::size_t pixels) {
        pixels_ = pixels;
        data_.assign(3 * (pixels + 3), 0);
        for (std::size_t c = 0; c < 3; ++c) {
            std::uint8_t* out = data_.data() + c * (pixels + 3);
            for (std::size_t i = 0; i < pixels; ++i) out[i] = std::uint8_t(interleaved[3 * i + c]);
        }
    }
    bool empty() const { return data_.empty(); }
    const std::uint8_t* plane(int c) const { return data_.data() + std::size_t(c) * (pixels_ + 3); }

private:
    std::vector<std::uint8_t> data_;
    std::size_t pixels_ = 0;
};

namespace colour_scan {

typedef std::int32_t I32x4 __attribute__((vector_size(16)));
typedef std::uint32_t U32x4 __attribute__((vector_size(16)));
typedef std::int16_t I16x8 __attribute__((vector_size(16)));
typedef std::uint8_t U8x4 __attribute__((vector_size(4)));

// Four bytes, each into the high half of a 32-bit lane (the low halves zero). A byte shuffle: two
// unpacks against zero on SSE2, where __builtin_convertvector extracts each byte by itself.
inline I16x8 load4_high(const std::uint8_t* p) {
    std::uint32_t word;
    std::memcpy(&word, p, 4);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    typedef std::uint8_t U8x16 __attribute__((vector_size(16)));
    typedef std::uint16_t U16x8 __attribute__((vector_size(16)));
    const U32x4 w = {word, 0, 0, 0};
    const U8x16 zb = {};
    const U16x8 zw = {};
    const U16x8 h = U16x8(__builtin_shufflevector(U8x16(w), zb, 0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23));
    return I16x8(__builtin_shufflevector(zw, h, 0, 8, 1, 9, 2, 10, 3, 11));
#else
    U8x4 b;
    std::memcpy(&b, &word, 4);
    return I16x8(__builtin_convertvector(b, U32x4) << 16);
#endif
}

// The squared errors of four samples s against the rounded values of V (16.16, biased by 1/2, so
// the rounded value is V's high half). Unclamped (V in [0, 2^24) on the span): the high halves
// subtract in 16 bits and square exactly (|error| <= 255), the low halves (the fractions) are
// garbage that the shift drops. Clamped: the rounded value clamped to [0, maxval] first.
// In unsigned 16-bit lanes, which wrap: the square of the wrapped difference is the square of the
// error modulo 2^16, which it is below.
template <bool Clamp>
inline I32x4 squared(const std::uint8_t* s, U32x4 V, std::int32_t maxval) {
    typedef std::uint16_t U16x8 __attribute__((vector_size(16)));
    if (Clamp) {
        I32x4 r = I32x4(V) >> 16;
        r = r < 0 ? 0 : r;
        r = r > maxval ? maxval : r;
        V = U32x4(r) << 16;
    }
    const U16x8 e = U16x8(load4_high(s)) - U16x8(V);
    return I32x4(U32x4(e * e) >> 16);
}

inline bool any(I32x4 m) {
    typedef std::uint64_t U64x2 __attribute__((vector_size(16)));
    const U64x2 q = U64x2(m);
    return (q[0] | q[1]) != 0;
}

// One face's three planes for scan_span: per channel the lane offsets {0, d, 2d, 3d} of a group of
// four pixels and the step 4d of a group (d: the 16.16 step a pixel).
struct Steps {
    U32x4 lanes[3], group[3];
    void set(const std::int32_t dV[3]) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t d = std::uint32_t(dV[c]);
            lanes[c] = U32x4{0, d, 2 * d, 3 * d};
            group[c] = U32x4{4 * d, 4 * d, 4 * d, 4 * d};
        }
    }
};

// Span x0..x1 of one row: s[c] points at channel c's sample of pixel x0, banned at the row's ban
// flags (indexed by x); V0[c] the fixed-point value at x0. Adds the squared errors of every
// channel to *sum and moves the candidate (*best: a squared channel error, < 0 for none yet; *bx)
// to the first pixel whose largest squared channel error is larger and which is not banned;
// returns true when it moved. Clamp: values may leave [0, maxval] on the span.
template <bool Clamp>
bool scan_span(const std::uint8_t* const s[3], const std::uint8_t* banned, std::int32_t x0, std::int32_t x1,
               const std::int32_t V0[3], const Steps& steps, std::int32_t maxval, std::uint64_t* sum,
               std::int32_t* best, std::int32_t* bx) {
    U32x4 V[3];
    for (int c = 0; c < 3; ++c) V[c] = std::uint32_t(V0[c]) + steps.lanes[c];
    const std::uint8_t *s0 = s[0], *s1 = s[1], *s2 = s[2];
    U32x4 acc = {0, 0, 0, 0};
    std::int32_t b = *best;
    I32x4 B = {b, b, b, b};
    bool moved = false;
    const std::int32_t n = x1 - x0 + 1;
    for (std::int32_t k = 0; k < n; k += 4) {
        I32x4 e0 = squared<Clamp>(s0 + k, V[0], maxval), e1 = squared<Clamp>(s1 + k, V[1], maxval),
              e2 = squared<Clamp>(s2 + k, V[2], maxval);
        if (n - k < 4) {  // the last, partial group: the lanes past the span count nothing
            const I32x4 lane = {0, 1, 2, 3};
            const I32x4 keep = lane < (n - k);
            e0 &= keep;
            e1 &= keep;
            e2 &= keep;
        }
        acc += U32x4(e0 + e1 + e2);
        // Rare once a face's first pixels are scanned. (Screening by the pixel's sum instead, one
        // compare instead of three, costs more: the sum beats the candidate three times as often.)
        if (any((e0 > B) | (e1 > B) | (e2 > B))) {
            I32x4 m = e0 > e1 ? e0 : e1;
            m = m > e2 ? m : e2;
            for (int l = 0; l < 4 && k + l < n; ++l) {
                if (m[l] > b && !banned[x0 + k + l]) {
                    b = m[l];
                    *bx = x0 + k + l;
                    moved = true;
                }
            }
            B = I32x4{b, b, b, b};
        }
        for (int c = 0; c < 3; ++c) V[c] += steps.group[c];
    }
    *sum += std::uint64_t(acc[0]) + acc[1] + acc[2] + acc[3];
    *best = b;
    return moved;
}

}  // namespace colour_scan
}  // namespace erd
