#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

constexpr std::uint32_t kTop = 1u << 24;
constexpr int kProbBits = 11, kAdapt = 5;
constexpr std::uint16_t kWarmBits = 62;  // warm: the mean of the first 62 bits, then steps of 1/64

void adapt(BitModel& m, int b, Adaptation how) {
    if (how == Adaptation::fixed) {
        if (b == 0) m.p = static_cast<std::uint16_t>(m.p + (((1u << kProbBits) - m.p) >> kAdapt));
        else m.p = static_cast<std::uint16_t>(m.p - (m.p >> kAdapt));
        return;
    }
    const int step = m.seen + 2;
    if (m.seen < kWarmBits) ++m.seen;
    const int target = b == 0 ? 1 << kProbBits : 0;
    const int p = int(m.p) + (target - int(m.p)) / step;
    m.p = static_cast<std::uint16_t>(p < 1 ? 1 : p > (1 << kProbBits) - 1 ? (1 << kProbBits) - 1 : p);
}

int bit_length(std::uint64_t n) {
    int k = 0;
    while (n) {
        ++k;
        n >>= 1;
    }
    return k;
}

}  // namespace

void RangeEncoder::shift_low() {
    if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
        const std::uint8_t carry = static_cast<std::uint8_t>(low_ >> 32);
        std::uint8_t temp = cache_;
        do {
            out_.push_back(static_cast<char>(static_cast<std::uint8_t>(temp + carry)));
            temp = 0xFF;
        } while (--cache_size_ != 0);
        cache_ = static_cast<std::uint8_t>(low_ >> 24);
    }
    ++cache_size_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
}

std::uint32_t CountModel::p() const {
    const std::uint32_t p = ((2 * n0 + 1) << kProbBits) / (2 * (n0 + n1) + 2);
    return p < 1 ? 1 : p > (1u << kProbBits) - 1 ? (1u << kProbBits) - 1 : p;
}

void CountModel::update(int b) {
    (b ? n1 : n0) += 1;
    if (n0 + n1 > kHalveAt) {
        n0 = (n0 + 1) / 2;
        n1 = (n1 + 1) / 2;
    }
}

void RangeEncoder::code(std::uint32_t p0, int b) {
    const std::uint32_t bound = (range_ >> kProbBits) * p0;
    if (b == 0) {
        range_ = bound;
    } else {
        low_ += bound;
        range_ -= bound;
    }
    while (range_ < kTop) {
        range_ <<= 8;
        shift_low();
    }
}

void RangeEncoder::bit(BitModel& m, int b) {
    code(m.p, b);
    adapt(m, b, adaptation_);
}

void RangeEncoder::bit(CountModel& m, int b) {
    code(m.p(), b);
    m.update(b);
}

void RangeEncoder::direct_bits(std::uint32_t value, int count) {
    for (int i = count - 1; i >= 0; --i) {
        range_ >>= 1;
        if ((value >> i) & 1u) low_ += range_;
        while (range_ < kTop) {
            range_ <<= 8;
            shift_low();
        }
    }
}

std::string RangeEncoder::finish() {
    for (int i = 0; i < 5; ++i) shift_low();
    return std::move(out_);
}

RangeDecoder::RangeDecoder(const unsigned char* data, std::size_t size, Adaptation adaptation)
    : data_(data), size_(size), adaptation_(adaptation) {
    if (next() != 0) good_ = false;
    for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next();
}

std::uint8_t RangeDecoder::next() {
    if (pos_ < size_) return data_[pos_++];
    good_ = false;
    return 0;
}

int RangeDecoder::code(std::uint32_t p0) {
    const std::uint32_t bound = (range_ >> kProbBits) * p0;
    int b;
    if (code_ < bound) {
        range_ = bound;
        b = 0;
    } else {
        code_ -= bound;
        range_ -= bound;
        b = 1;
    }
    while (range_ < kTop) {
        range_ <<= 8;
        code_ = (code_ << 8) | next();
    }
    return b;
}

int RangeDecoder::bit(BitModel& m) {
    const int b = code(m.p);
    adapt(m, b, adaptation_);
    return b;
}

int RangeDecoder::bit(CountModel& m) {
    const int b = code(m.p());
    m.update(b);
    return b;
}

std::uint32_t RangeDecoder::direct_bits(int count) {
    std::uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
        range_ >>= 1;
        std::uint32_t b = 0;
        if (code_ >= range_) {
            code_ -= range_;
            b = 1;
        }
        v = (v << 1) | b;
        while (range_ < kTop) {
            range_ <<= 8;
            code_ = (code_ << 8) | next();
        }
    }
    return v;
}

const char* RangeDecoder::finish() const {
    if (!good_) return "ends early";
    if (pos_ != size_) return "has bytes after its last symbol";
    return "";
}

void UIntModel::encode(RangeEncoder& e, std::uint64_t n) {
    const std::uint64_t v = n + 1;
    const int k = bit_length(v) - 1;  // bits below the leading one
    for (int i = 0; i < k; ++i) e.bit(length_[static_cast<std::size_t>(i)], 1);
    e.bit(length_[static_cast<std::size_t>(k)], 0);
    for (int i = k - 1, j = 0; i >= 0; --i, ++j) {
        const int b = static_cast<int>((v >> i) & 1u);
        if (j < kModelled) e.bit(mantissa_[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)], b);
        else e.direct_bits(static_cast<std::uint32_t>(b), 1);
    }
}

bool UIntModel::decode(RangeDecoder& d, std::uint64_t* n) {
    int k = 0;
    while (d.bit(length_[static_cast<std::size_t>(k)])) {
        if (++k >= kMaxBits) return false;
    }
    std::uint64_t v = 1;
    for (int j = 0; j < k; ++j) {
        const int b = j < kModelled ? d.bit(mantissa_[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)])
                                    : static_cast<int>(d.direct_bits(1));
        v = (v << 1) | static_cast<std::uint64_t>(b);
    }
    *n = v - 1;
    return true;
}

void SIntModel::encode(RangeEncoder& e, std::int64_t n) {
    e.bit(zero_, n != 0);
    if (n == 0) return;
    e.bit(sign_, n < 0);
    magnitude_.encode(e, static_cast<std::uint64_t>(n < 0 ? -n : n) - 1);
}

bool SIntModel::decode(RangeDecoder& d, std::int64_t* n) {
    if (!d.bit(zero_)) {
        *n = 0;
        return true;
    }
    const bool negative = d.bit(sign_) != 0;
    std::uint64_t m = 0;
    if (!magnitude_.decode(d, &m)) return false;
    *n = negative ? -static_cast<std::int64_t>(m + 1) : static_cast<std::int64_t>(m + 1);
    return true;
}

}  // namespace erd::codec
