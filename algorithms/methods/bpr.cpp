#include "algorithms/methods/bpr.h"

#include <unordered_set>
#include <vector>

namespace erd {

Status bad_point_replacement(Cdt* cdt, const Image& image, RemovalModel& model, bool round_values, int rounds,
                             const ProgressHook& progress, RemovalRunStats* stats) {
    PointRemover r(*cdt, image, model, round_values);
    r.lazy = false;
    r.track_faces();
    r.start();
    // Vertices whose exchange was undone in this round, by point (their index changes when put back).
    std::unordered_set<std::uint64_t> skip;
    const auto key = [](LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); };
    std::vector<VertInd> least;
    std::vector<double> saved;
    const std::size_t n = cdt->live_vertex_count();
    for (int round = 0; round < rounds; ++round) {
        if (progress.report_cancelled("bad-point replacement", double(round) / double(rounds)))
            return Status::failure(kCancelled);
        ++stats->bpr_rounds;
        skip.clear();
        for (std::size_t step = 0; step < n; ++step) {
            // The least significant vertex not tried in vain before.
            VertInd v = noVertex;
            for (std::size_t want = 1; v == noVertex; want *= 2) {
                r.least_significant(want, &least);
                for (VertInd c : least)
                    if (!skip.count(key(cdt->point(c)))) {
                        v = c;
                        break;
                    }
                if (least.size() < want) break;
            }
            if (v == noVertex) break;
            const LatticePoint pv = cdt->point(v);
            const double before = r.total_error();
            model.save_values(*cdt, v, &saved);
            Status st = r.remove(v);
            if (!st) return st;
            ++stats->bpr_tried;
            // The new point; one on a constrained edge would split it and could not be taken
            // out again, so such pixels are passed over.
            LatticePoint p;
            bool found = false;
            while (r.worst_pixel(&p)) {
                const Location loc = cdt->locate(p);
                if (loc.kind == Location::Kind::on_edge && cdt->constrained(loc.edge)) {
                    r.ban(p);
                    continue;
                }
                found = true;
                break;
            }
            VertInd u = noVertex;
            if (found && !(st = r.insert(p, &u))) return st;
            if (found && r.total_error() < before) {
                ++stats->bpr_moves;
                continue;
            }
            // Undo: the mesh and its errors as they were.
            if (found && !(st = r.remove(u))) return st;
            VertInd back;
            if (!(st = r.insert(pv, &back, &saved))) return st;
            skip.insert(key(pv));
        }
    }
    return Status::success();
}

}  // namespace erd
