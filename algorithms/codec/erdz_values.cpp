// The values section: quantised values predicted from already-coded neighbours.
//
// Unit u (a vertex of a basic model, a wedge of an ERD model) predicts channel c as the rounded
// mean of its neighbours below u (ValueGraph), or as unit u - 1 when it has none; channels 1 and 2
// add channel 0's residual (colour edges move all three channels together). The residual is coded
// with one of five models per channel: a unit with one known neighbour has its own (version 3
// on: its residuals are as large as a busy neighbourhood's, bull 0.5%: mean 11.5 against 0.1
// for a flat one of three or more); the others by the spread (max - min) of the neighbours'
// channel values, as a flat neighbourhood predicts better than a busy one.
#include <algorithm>
#include <array>
#include <cmath>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

constexpr int kMaxChannels = 3;

struct Models {
    std::array<std::array<SIntModel, 5>, kMaxChannels> residual;
};

std::size_t spread_context(std::int64_t spread) {
    if (spread <= 0) return 0;
    if (spread <= 2) return 1;
    if (spread <= 8) return 2;
    return 3;
}

// Prediction and context of channel c of unit u from the units already known (q below u).
void predict(const ValueGraph& g, int channels, int version, const std::vector<std::int64_t>& q, std::size_t u, int c,
             std::int64_t* pred, std::size_t* ctx) {
    std::int64_t sum = 0, lo = 0, hi = 0, n = 0;
    for (std::uint32_t i = g.begin[u]; i < g.begin[u + 1]; ++i) {
        const std::uint32_t w = g.neighbour[i];
        if (w >= u) continue;
        const std::int64_t v = q[std::size_t(w) * std::size_t(channels) + std::size_t(c)];
        lo = n == 0 ? v : std::min(lo, v);
        hi = n == 0 ? v : std::max(hi, v);
        sum += v;
        ++n;
    }
    if (n == 0) {
        *pred = u == 0 ? 0 : q[(u - 1) * std::size_t(channels) + std::size_t(c)];
        *ctx = 3;
        return;
    }
    *pred = std::int64_t(std::llround(double(sum) / double(n)));
    *ctx = n == 1 && version >= 3 ? 4 : spread_context(hi - lo);
}

}  // namespace

std::string encode_values(const ValueGraph& g, int channels, const std::vector<std::int64_t>& q) {
    RangeEncoder rc;
    Models m;
    for (std::size_t u = 0; u < g.units(); ++u) {
        std::int64_t r0 = 0;
        for (int c = 0; c < channels; ++c) {
            std::int64_t pred = 0;
            std::size_t ctx = 0;
            predict(g, channels, kErdzVersion, q, u, c, &pred, &ctx);
            if (c > 0) pred += r0;
            const std::int64_t r = q[u * std::size_t(channels) + std::size_t(c)] - pred;
            if (c == 0) r0 = r;
            m.residual[std::size_t(c)][ctx].encode(rc, r);
        }
    }
    return rc.finish();
}

Status decode_values(const unsigned char* data, std::size_t size, const ValueGraph& g, int channels, int version,
                     std::vector<std::int64_t>* q) {
    RangeDecoder rc(data, size, adaptation(version));
    Models m;
    q->assign(g.units() * std::size_t(channels), 0);
    for (std::size_t u = 0; u < g.units() && rc.good(); ++u) {
        std::int64_t r0 = 0;
        for (int c = 0; c < channels; ++c) {
            std::int64_t pred = 0, r = 0;
            std::size_t ctx = 0;
            predict(g, channels, version, *q, u, c, &pred, &ctx);
            if (c > 0) pred += r0;
            if (!m.residual[std::size_t(c)][ctx].decode(rc, &r)) return Status::bad_input("values section: bad residual");
            if (c == 0) r0 = r;
            const std::int64_t v = pred + r;
            if (v > kMaxQuantised || v < -kMaxQuantised)
                return Status::bad_input("values section: value " + std::to_string(u) + " out of range");
            (*q)[u * std::size_t(channels) + std::size_t(c)] = v;
        }
    }
    const std::string why = rc.finish();
    if (!why.empty()) return Status::bad_input("values section " + why);
    return Status::success();
}

}  // namespace erd::codec
