// The flips section: the edges flipped away from the rebuilt constrained Delaunay triangulation
// (the ERD methods' data-dependent flips), one adaptive bit per edge the decoder visits.
//
// Visiting order (the same on both sides, from the triangulation alone): round 0 visits the
// half-edges in index order, one per edge (the one below its twin); each later round visits the
// outer edges of the quadrilaterals flipped in the round before, sorted by their vertex pair. An
// edge is visited when it can flip (unconstrained, interior, convex quadrilateral). The rounds end
// when a round flips nothing. A decision depends on the edge's quadrilateral alone, and an edge is
// visited again exactly when a flip changed its quadrilateral, so the encoder can reach every
// triangulation its rule leads to.
//
// Context of a bit: the round (0 or later), how many of the quadrilateral's outer edges came from
// flips (flips run along the image's features, next to each other), and the values at its four
// corners (decoded before this section): data-dependent flips favour the diagonal whose two ends
// have the closer values, the one along the image's level lines.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <unordered_set>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

std::uint64_t pair_key(VertInd a, VertInd b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

constexpr std::size_t kValueContexts = 5;
using FlipModels = std::array<std::array<BitModel, kValueContexts>, 6>;  // [3 * later + near][value]

// The value context of flipping a-b into c-d: how much closer c and d are than a and b, summed
// over the channels, in the values' own units.
std::size_t value_context(const FlipValues& v, const std::uint32_t u[4]) {
    std::int64_t gain = 0;
    for (int c = 0; c < v.channels; ++c) {
        const auto z = [&](int i) { return (*v.q)[std::size_t(u[i]) * std::size_t(v.channels) + std::size_t(c)]; };
        gain += std::llabs(z(0) - z(1)) - std::llabs(z(2) - z(3));
    }
    const double g = double(gain) * v.step;
    if (g <= -8.0) return 0;
    if (g < 0.0) return 1;
    if (g == 0.0) return 2;
    if (g < 8.0) return 3;
    return 4;
}

class FlipRun {
public:
    FlipRun(Cdt* cdt, std::vector<std::uint32_t>* corner_unit) : cdt_(*cdt), unit_(*corner_unit) {}

    // Runs the rounds; decide(e, units, context) returns whether to flip e (coding or decoding
    // the bit), units being those of a, b, c, d for edge a-b and other diagonal c-d, and context
    // 3 * (later round) + (flipped outer edges, at most 2). Stops with false once more than
    // max_flips flips were made.
    template <class Decide>
    bool run(std::uint64_t max_flips, Decide decide) {
        std::vector<std::uint64_t> next;
        for (EdgeInd e = 0; e < 3 * cdt_.face_count(); ++e) {
            const EdgeInd t = cdt_.twin(e);
            if (t == noEdge || t < e) continue;
            if (!visit(e, 0, decide, &next, max_flips)) return false;
        }
        std::vector<std::uint64_t> round;
        while (!next.empty()) {
            round.swap(next);
            next.clear();
            std::sort(round.begin(), round.end());
            round.erase(std::unique(round.begin(), round.end()), round.end());
            for (const std::uint64_t k : round) {
                const EdgeInd e = cdt_.find_edge(VertInd(k >> 32), VertInd(k & 0xFFFFFFFFu));
                if (e == noEdge) continue;
                if (!visit(e, 3, decide, &next, max_flips)) return false;
            }
        }
        return true;
    }

    std::uint64_t flips() const { return flips_; }

private:
    bool made(EdgeInd e) const { return !made_.empty() && made_.count(pair_key(cdt_.org(e), cdt_.dest(e))) != 0; }

    template <class Decide>
    bool visit(EdgeInd e, int later, Decide& decide, std::vector<std::uint64_t>* next, std::uint64_t max_flips) {
        if (!cdt_.can_flip(e)) return true;
        const EdgeInd t = cdt_.twin(e);
        const EdgeInd outer[4] = {next_edge(e), prev_edge(e), next_edge(t), prev_edge(t)};
        int near = 0;
        for (const EdgeInd o : outer) near += made(o);
        // a = org(e), b = org(t), c = org(prev(e)), d = org(prev(t)); an unconstrained edge
        // separates no wedges, so a and b have one unit on both faces.
        const std::uint32_t u[4] = {unit_[e], unit_[t], unit_[prev_edge(e)], unit_[prev_edge(t)]};
        const VertInd v[4] = {cdt_.org(e), cdt_.org(t), cdt_.org(prev_edge(e)), cdt_.org(prev_edge(t))};
        if (!decide(e, u, later + std::min(near, 2))) return true;
        if (++flips_ > max_flips) return false;
        const EdgeInd d = cdt_.flip_edge(e);
        const EdgeInd dt = cdt_.twin(d);
        // The flipped faces' corners keep their vertices' units.
        for (const FaceInd f : {face_of(d), face_of(dt)})
            for (EdgeInd h = 3 * f; h < 3 * f + 3; ++h)
                for (int i = 0; i < 4; ++i)
                    if (cdt_.org(h) == v[i]) unit_[h] = u[i];
        made_.insert(pair_key(cdt_.org(d), cdt_.dest(d)));
        for (const EdgeInd o : {next_edge(d), prev_edge(d), next_edge(dt), prev_edge(dt)})
            next->push_back(pair_key(cdt_.org(o), cdt_.dest(o)));
        return true;
    }

    Cdt& cdt_;
    std::vector<std::uint32_t>& unit_;
    std::unordered_set<std::uint64_t> made_;  // edges made by flips (vertex pairs)
    std::uint64_t flips_ = 0;
};

}  // namespace

bool plan_flips(Cdt* cdt, std::vector<std::uint32_t>* corner_unit, const FlipChoice& choose,
                std::vector<FlipRecord>* out) {
    out->clear();
    FlipRun run(cdt, corner_unit);
    return run.run(max_flips(cdt->face_count()), [&](EdgeInd e, const std::uint32_t u[4], int context) {
        const EdgeInd t = cdt->twin(e);
        FlipRecord r;
        r.flip = choose(cdt->org(e), cdt->dest(e), cdt->org(prev_edge(e)), cdt->org(prev_edge(t)));
        r.context = std::uint8_t(context);
        std::copy(u, u + 4, r.units);
        out->push_back(r);
        return r.flip;
    });
}

std::string encode_flips(const std::vector<FlipRecord>& plan, const FlipValues& values) {
    RangeEncoder rc;
    FlipModels models;
    for (const FlipRecord& r : plan) rc.bit(models[r.context][value_context(values, r.units)], r.flip);
    return rc.finish();
}

Status decode_flips(const unsigned char* data, std::size_t size, Cdt* cdt, std::vector<std::uint32_t>* corner_unit,
                    const FlipValues& values, std::uint64_t* flips) {
    RangeDecoder rc(data, size);
    FlipRun run(cdt, corner_unit);
    FlipModels models;
    const bool ok = run.run(max_flips(cdt->face_count()), [&](EdgeInd, const std::uint32_t u[4], int context) {
        return rc.good() && rc.bit(models[std::size_t(context)][value_context(values, u)]) != 0;
    });
    if (!ok) return Status::bad_input("flips section: more flips than any encoder makes");
    const std::string why = rc.finish();
    if (!why.empty()) return Status::bad_input("flips section " + why);
    if (flips) *flips = run.flips();
    return Status::success();
}

}  // namespace erd::codec
