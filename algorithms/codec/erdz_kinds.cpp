// The kinds section (version 4): the discontinuity edges of the other kind than the model's
// (Model::kind_exceptions, algorithms/model/edge_kinds.h), one adaptive bit per discontinuity of
// the decoded model, 1 for an edge of the other kind.
//
// Visiting order (the same on both sides, from the rebuilt triangulation and the quantised values
// alone): the half-edges in index order, one per interior edge (the one below its twin), those
// across which the decoded values jump in some channel at either end. Quantisation can only merge
// values, so an edge listed in the model that no longer jumps is no discontinuity of the decoded
// model and has no kind to keep: it is not coded. One count model; the rate of exceptions is
// steady over a picture (0.15 to 0.5 of its discontinuities on the graphics of make eval).
#include <algorithm>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

// Calls visit(e) for each half-edge across which the values jump, in the visiting order.
template <class Visit>
void for_each_jump(const Cdt& cdt, const std::vector<std::uint32_t>& corner_unit, int channels,
                   const std::vector<std::int64_t>& q, Visit visit) {
    const std::size_t C = std::size_t(channels);
    const auto differ = [&](std::uint32_t a, std::uint32_t b) {
        if (a == b) return false;
        for (std::size_t c = 0; c < C; ++c)
            if (q[a * C + c] != q[b * C + c]) return true;
        return false;
    };
    const auto next = [](EdgeInd e) { return e % 3 == 2 ? e - 2 : e + 1; };
    for (EdgeInd e = 0; e < 3 * cdt.face_count(); ++e) {
        const EdgeInd t = cdt.twin(e);
        if (t == noEdge || t < e) continue;
        // e runs u -> w in its face, t runs w -> u in the other: the corners at u are e and
        // next(t), those at w are next(e) and t.
        if (differ(corner_unit[e], corner_unit[next(t)]) || differ(corner_unit[next(e)], corner_unit[t])) visit(e);
    }
}

}  // namespace

std::string encode_kinds(const Cdt& cdt, const std::vector<std::uint32_t>& corner_unit, int channels,
                         const std::vector<std::int64_t>& q, const KindChoice& other_kind, std::size_t* coded) {
    RangeEncoder enc;
    CountModel model;
    std::size_t ones = 0;
    for_each_jump(cdt, corner_unit, channels, q, [&](EdgeInd e) {
        const int b = other_kind(cdt.org(e), cdt.dest(e)) ? 1 : 0;
        ones += std::size_t(b);
        enc.bit(model, b);
    });
    if (coded) *coded = ones;
    return ones ? enc.finish() : std::string();
}

Status decode_kinds(const unsigned char* data, std::size_t size, const Cdt& cdt, const std::vector<std::uint32_t>& corner_unit,
                    int channels, const std::vector<std::int64_t>& q, std::vector<std::array<VertInd, 2>>* out) {
    out->clear();
    RangeDecoder dec(data, size);
    CountModel model;
    for_each_jump(cdt, corner_unit, channels, q, [&](EdgeInd e) {
        if (dec.good() && dec.bit(model)) out->push_back({cdt.org(e), cdt.dest(e)});
    });
    if (!dec.good()) return Status::bad_input("kinds section: ends early");
    if (const char* why = dec.finish(); *why) return Status::bad_input(std::string("kinds section: ") + why);
    if (out->empty()) return Status::bad_input("kinds section: no edge of the other kind (an encoder writes version 3 then)");
    return Status::success();
}

}  // namespace erd::codec
