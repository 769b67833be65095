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
// Context of a bit: whether the four corners are cocircular (the Delaunay diagonal was a tie
// there; data-dependent flips rarely take the other one: 3% against 20% elsewhere on lena, bull and
// peppers 1%). Counts, not 1/32 steps, estimate each rate (CountModel). The round and the
// flips next to an edge told nothing. The values would (flips favour the diagonal whose ends have
// the closer values) if they came first, but the values' prediction over the flipped faces saves
// more than that context does (docs/DECISIONS.md, ".erdz").
#include <algorithm>
#include <array>
#include <cstdlib>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"
#include "kernel/predicates.h"

namespace erd::codec {
namespace {

std::uint64_t pair_key(VertInd a, VertInd b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// An edge to visit in the next round: its vertex pair (the order of visits) and the half-edge from
// the smaller vertex as it was then, a hint that a later flip may have made stale.
struct Pending {
    std::uint64_t key;
    EdgeInd hint;
    bool operator<(const Pending& o) const { return key < o.key; }
};

using FlipModels = std::array<CountModel, 2>;  // [cocircular]

class FlipRun {
public:
    explicit FlipRun(Cdt* cdt) : cdt_(*cdt), small_(cdt->max_x() < kSmallCoord && cdt->max_y() < kSmallCoord) {}

    // Runs the rounds; decide(e, cocircular) returns whether to flip e (coding or decoding the
    // bit). Stops with false once more than max_flips flips were made.
    template <class Decide>
    bool run(std::uint64_t max_flips, Decide decide) {
        std::vector<Pending> next;
        for (EdgeInd e = 0; e < 3 * cdt_.face_count(); ++e) {
            const EdgeInd t = cdt_.twin(e);
            if (t == noEdge || t < e) continue;
            if (!visit(e, decide, &next, max_flips)) return false;
        }
        std::vector<Pending> round;
        while (!next.empty()) {
            round.swap(next);
            next.clear();
            std::sort(round.begin(), round.end());
            round.erase(std::unique(round.begin(), round.end(), [](const Pending& a, const Pending& b) { return a.key == b.key; }),
                        round.end());
            for (const Pending& p : round) {
                const VertInd a = VertInd(p.key >> 32), b = VertInd(p.key & 0xFFFFFFFFu);
                // The half-edge a -> b is unique: the hint is it when its ends still say so.
                const EdgeInd e = cdt_.org(p.hint) == a && cdt_.dest(p.hint) == b ? p.hint : cdt_.find_edge(a, b);
                if (e != noEdge && !visit(e, decide, &next, max_flips)) return false;
            }
        }
        return true;
    }

    std::uint64_t flips() const { return flips_; }

private:
    template <class Decide>
    bool visit(EdgeInd e, Decide& decide, std::vector<Pending>* next, std::uint64_t max_flips) {
        if (!cdt_.can_flip(e)) return true;
        const EdgeInd t = cdt_.twin(e);
        const LatticePoint pa = cdt_.point(cdt_.org(e)), pb = cdt_.point(cdt_.org(t)),
                           pc = cdt_.point(cdt_.org(prev_edge(e))), pd = cdt_.point(cdt_.org(prev_edge(t)));
        const bool cocircular = small_ ? incircle_small(pa, pb, pc, pd) == 0 : incircle(pa, pb, pc, pd) == 0;
        if (!decide(e, cocircular)) return true;
        if (++flips_ > max_flips) return false;
        const EdgeInd d = cdt_.flip_edge(e);
        const EdgeInd dt = cdt_.twin(d);
        for (const EdgeInd o : {next_edge(d), prev_edge(d), next_edge(dt), prev_edge(dt)}) {
            const VertInd a = cdt_.org(o), b = cdt_.dest(o);
            // The hint runs from the smaller vertex; a hull edge has no twin, and no visit.
            const EdgeInd h = a < b ? o : cdt_.twin(o);
            if (h != noEdge) next->push_back({pair_key(a, b), h});
        }
        return true;
    }

    Cdt& cdt_;
    const bool small_;  // every coordinate below kSmallCoord: the int64 in-circle test is exact
    std::uint64_t flips_ = 0;
};

}  // namespace

std::string encode_flips(Cdt* cdt, const FlipChoice& choose, std::uint64_t* flips) {
    RangeEncoder rc;
    FlipModels models;
    FlipRun run(cdt);
    const bool ok = run.run(max_flips(cdt->face_count()), [&](EdgeInd e, bool cocircular) {
        const EdgeInd t = cdt->twin(e);
        const bool flip = choose(cdt->org(e), cdt->dest(e), cdt->org(prev_edge(e)), cdt->org(prev_edge(t)));
        rc.bit(models[cocircular], flip);
        return flip;
    });
    if (flips) *flips = run.flips();
    return ok ? rc.finish() : std::string();
}

Status decode_flips(const unsigned char* data, std::size_t size, Cdt* cdt, std::uint64_t* flips) {
    RangeDecoder rc(data, size);
    FlipModels models;
    FlipRun run(cdt);
    const bool ok = run.run(max_flips(cdt->face_count()), [&](EdgeInd, bool cocircular) {
        return rc.good() && rc.bit(models[cocircular]) != 0;
    });
    if (!ok) return Status::bad_input("flips section: more flips than any encoder makes");
    const std::string why = rc.finish();
    if (!why.empty()) return Status::bad_input("flips section " + why);
    if (flips) *flips = run.flips();
    return Status::success();
}

}  // namespace erd::codec
