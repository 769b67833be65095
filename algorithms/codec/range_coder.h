// An adaptive binary range coder (the carry-less scheme of LZMA's rc: 32-bit range, 11-bit
// probabilities) and the integer codes the .erdz sections build on it.
//
// The encoder's flush writes exactly the bytes the decoder reads (5 at the start, one per
// renormalisation), so a decoder that ends with bytes left over, or that had to read past the
// end, was given a stream no encoder wrote: RangeDecoder::finish() says which.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace erd::codec {

// The probability that the next bit is 0, in 1/2048ths, adapted towards each bit coded with it
// as the coder's Adaptation says.
struct BitModel {
    std::uint16_t p = 1024;
    std::uint16_t seen = 0;  // bits coded with it (warm adaptation; stops counting at its limit)
};

// How a BitModel learns. fixed (.erdz versions 1 and 2): steps of 1/32 of the way towards each
// bit. warm (version 3 on): the running mean of its first bits (steps 1/2, 1/3, ...), then steps
// of 1/64: a model that sees few bits learns them at once, one that sees many holds its rate
// closer (-0.7% of the codec table's bits, docs/DECISIONS.md ".erdz coding").
enum class Adaptation { fixed, warm };

// A bit whose rate is steady over a section: the probability is the count estimate
// (n0 + 1/2) / (n + 1), halved counts past kHalveAt keep it loosely adaptive. It learns a skewed
// rate faster and holds it closer than BitModel's fixed 1/32 steps.
struct CountModel {
    static constexpr std::uint32_t kHalveAt = 1024;
    std::uint32_t n0 = 0, n1 = 0;
    std::uint32_t p() const;  // of a 0, in 1/2048ths, within [1, 2047]
    void update(int b);
};

class RangeEncoder {
public:
    explicit RangeEncoder(Adaptation adaptation = Adaptation::warm) : adaptation_(adaptation) {}
    void bit(BitModel& m, int b);
    void bit(CountModel& m, int b);
    void direct_bits(std::uint32_t value, int count);  // equiprobable, most significant first
    // Flushes and returns the coded bytes (the encoder is spent afterwards).
    std::string finish();

private:
    void code(std::uint32_t p0, int b);
    void shift_low();
    std::uint64_t low_ = 0;
    std::uint32_t range_ = 0xFFFFFFFFu;
    std::uint8_t cache_ = 0;
    std::uint64_t cache_size_ = 1;
    std::string out_;
    Adaptation adaptation_;
};

class RangeDecoder {
public:
    RangeDecoder(const unsigned char* data, std::size_t size, Adaptation adaptation = Adaptation::warm);
    int bit(BitModel& m);
    int bit(CountModel& m);
    std::uint32_t direct_bits(int count);
    // True when the stream was well formed so far: it started with the 0 byte every encoder
    // writes and the decoder never read past its end.
    bool good() const { return good_; }
    // After the last symbol: "" when the stream ended exactly there, else what is wrong.
    const char* finish() const;

private:
    int code(std::uint32_t p0);
    std::uint8_t next();
    const unsigned char* data_;
    std::size_t size_, pos_ = 0;
    std::uint32_t range_ = 0xFFFFFFFFu, code_ = 0;
    bool good_ = true;
    Adaptation adaptation_;
};

// Unsigned integers by an adaptive Elias-gamma code: the bit length of n + 1 in unary (one model
// per position), then its bits below the leading one (one model per length and position for the
// top kModelled bits, equiprobable below). Small numbers cost about their entropy once adapted.
class UIntModel {
public:
    static constexpr int kMaxBits = 40;  // values below 2^40 - 1
    void encode(RangeEncoder& e, std::uint64_t n);
    // Returns false (and leaves *n undefined) when the length prefix runs past kMaxBits.
    bool decode(RangeDecoder& d, std::uint64_t* n);

private:
    static constexpr int kModelled = 3;
    std::array<BitModel, kMaxBits + 1> length_;
    std::array<std::array<BitModel, kModelled>, kMaxBits + 1> mantissa_;
};

// Signed integers: zero or not, the sign, then |n| - 1 with a UIntModel.
class SIntModel {
public:
    void encode(RangeEncoder& e, std::int64_t n);
    bool decode(RangeDecoder& d, std::int64_t* n);

private:
    BitModel zero_, sign_;
    UIntModel magnitude_;
};

}  // namespace erd::codec
