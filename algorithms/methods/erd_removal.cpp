#include "algorithms/methods/erd_removal.h"

#include <utility>

namespace erd {

Status erd_remove_to(Cdt* cdt, const Image& image, RemovalModel& model, std::size_t n, bool lazy,
                     const ProgressHook& progress, RemovalRunStats* stats, MeshSystems* systems) {
    {
        PointRemover remover(*cdt, image, model, false, systems);
        if (systems) *systems = MeshSystems();  // read: their memory back before the removals
        remover.lazy = lazy;
        if (stats->start == 0) stats->start = cdt->live_vertex_count();
        remover.start();
        Status st = remover.run_to(n, progress);
        if (!st) return st;
        stats->removed += remover.stats().removed;
        stats->evaluations += remover.stats().evaluations;
    }
    Cdt compact;
    Status st = compact_cdt(*cdt, &compact);
    if (!st) return st;
    *cdt = std::move(compact);
    return Status::success();
}

}  // namespace erd
