#include "algorithms/methods/erd_mesh.h"

#include <algorithm>
#include <numeric>

#include "algorithms/imaging/edge_polylines.h"

namespace erd {

namespace {

// "initial mesh" progress counted in work units, not time: an edge detection 3, a count 1, the
// insertion into the mesh 2 (by polylines). The plan is one detection and count per detection the
// selection is expected to make; when it loops further the plan stretches, so the fraction only
// grows (the selection's part stays below 0.9 of its share until it ends).
class StepProgress {
public:
    StepProgress(ProgressHook hook, int planned_detections) : hook_(hook), planned_(4.0 * planned_detections) {}
    bool cancelled() const { return cancelled_; }
    void selection(double units) {
        done_ += units;
        if (done_ > 0.9 * planned_) planned_ = done_ / 0.9;
        report(kSelection * done_ / planned_);
    }
    void insertion(std::size_t done, std::size_t total) {
        report(kSelection + (1.0 - kSelection) * (total ? double(done) / double(total) : 1.0));
    }

private:
    static constexpr double kSelection = 4.0 / 6.0;  // 4 units of selection before 2 of insertion
    void report(double f) {
        if (hook_ && !cancelled_ && hook_.report_cancelled("initial mesh", f)) cancelled_ = true;
    }
    ProgressHook hook_;
    double planned_, done_ = 0;
    bool cancelled_ = false;
};

// Step 1.1-1.3 (algorithms/imaging/edge_polylines.h) as the parameter selection's counter. The
// chain skips a detection with the same (beta, r) as the last one (the simple test and the first
// loop iteration often coincide), and a count with the same (l, eps) on the same detection.
class StepOneCounter : public ConstraintPointCounter {
public:
    // budget: the most constrained points the parameter selection accepts (0.7 N there).
    StepOneCounter(const Image& image, LengthRule rule, double eps_unit, bool hard, bool fallback, double budget,
                   StepProgress* progress)
        : chain_(image, hard), rule_(rule), eps_unit_(eps_unit), hard_(hard), fallback_(fallback), budget_(budget),
          progress_(progress) {}

    void detect(double beta, double r) override {
        progress_->selection(0.0);
        if (progress_->cancelled()) return;  // the selection then ends at once (count 0)
        CannyParams cp;
        cp.beta = beta;
        cp.r = r;
        Status st = chain_.detect(cp);
        if (!st.ok() && status_.ok()) status_ = st;
        progress_->selection(3.0);
    }

    std::size_t count(int l, double eps) override {
        if (progress_->cancelled()) return 0;
        const std::vector<Polyline>* kept = &chain_.simplify(l, eps * eps_unit_, rule_);
        // Hard edges: the side-keeping curves when they fit the budget, else plain Douglas-Peucker
        // on the same cracks (docs/DECISIONS.md "Hard edges").
        if (hard_ && fallback_ && double(distinct_points(*kept)) > budget_)
            kept = &chain_.simplify(l, eps * eps_unit_, rule_, CrackRule::plain);
        if (chain_.generation() != counted_) {
            counted_ = chain_.generation();
            count_ = distinct_points(*kept);
        }
        progress_->selection(1.0);
        return count_;
    }

    const Status& status() const { return status_; }
    void release_detector() { chain_.release_detector(); }
    Grid<std::uint8_t> edges() const { return chain_.edge_map(); }
    std::vector<Polyline>& kept() { return chain_.kept(); }

private:
    // On the image, not a double copy of it: the ERD methods make their double phi only after
    // step 1, so it is not alive beside the detector's planes (the peak of the whole run).
    EdgePolylines chain_;
    LengthRule rule_;
    double eps_unit_;
    bool hard_, fallback_;
    double budget_;
    StepProgress* progress_;
    Status status_;
    std::size_t counted_ = 0, count_ = 0;  // distinct points of simplification number counted_
};

std::uint64_t key_of(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

}  // namespace

std::size_t distinct_points(const std::vector<Polyline>& polylines) {
    std::vector<std::uint64_t> keys;
    std::size_t total = 0;
    for (const Polyline& pl : polylines) total += pl.size();
    keys.reserve(total);
    for (const Polyline& pl : polylines)
        for (LatticePoint p : pl) keys.push_back(key_of(p));
    std::sort(keys.begin(), keys.end());
    return std::size_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

namespace {

Status insert_polylines(const std::vector<Polyline>& polylines, Cdt* cdt, std::size_t* dropped, StepProgress* progress) {
    // Points first (the kernel orders a batch along a Hilbert curve), then the segments. Nobody
    // reads the batch's change report, so the kernel skips that bookkeeping.
    std::vector<LatticePoint> pts;
    for (const Polyline& pl : polylines) pts.insert(pts.end(), pl.begin(), pl.end());
    std::vector<VertInd> ids;
    Status st = cdt->insert_points(pts, &ids, false);
    if (!st.ok()) return st;
    std::size_t k = 0, done = 0;
    const std::size_t every = polylines.size() / 100 + 1;
    for (const Polyline& pl : polylines) {
        if (progress && done++ % every == 0) {
            progress->insertion(done, polylines.size() + 1);
            if (progress->cancelled()) return Status::failure(kCancelled);
        }
        for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
            ConstraintReport rep;
            st = cdt->insert_constraint(ids[k + i], ids[k + i + 1], &rep);
            if (!st.ok()) return st;
            *dropped += rep.dropped_crossing;
        }
        k += pl.size();
    }
    return Status::success();
}

}  // namespace

Status insert_polylines(const std::vector<Polyline>& polylines, Cdt* cdt, std::size_t* dropped) {
    return insert_polylines(polylines, cdt, dropped, nullptr);
}

Status build_initial_mesh(const Image& image, const InitialMeshOptions& options, Cdt* cdt, InitialMesh* out) {
    StepProgress progress(options.progress, options.request.simple >= 0 ? 1 : 2);
    StepOneCounter counter(image, options.length_rule, options.eps_unit, options.hard_edges, options.hard_fallback,
                           0.7 * double(options.target), &progress);
    out->params = select_erd_params(options.method, image.width, image.height, options.target, options.request,
                                    counter);
    counter.release_detector();
    if (!counter.status().ok()) return counter.status();
    if (progress.cancelled()) return Status::failure(kCancelled);
    out->edges = counter.edges();
    out->polylines = std::move(counter.kept());
    out->constraint_points = out->params.constrained_points;

    // Only for tiny N: keep whole polylines, longest first, while the mesh stays within N.
    const std::size_t budget = options.target > 4 ? options.target - 4 : 0;
    if (out->constraint_points > budget) {
        std::vector<std::size_t> order(out->polylines.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return out->polylines[a].size() > out->polylines[b].size();
        });
        std::vector<Polyline> kept;
        for (std::size_t i : order) {
            kept.push_back(out->polylines[i]);
            if (distinct_points(kept) > budget) {
                kept.pop_back();
                ++out->dropped_polylines;
            }
        }
        out->polylines = std::move(kept);
        out->constraint_points = distinct_points(out->polylines);
    }

    Status st = cdt->reset(2 * image.width - 2, 2 * image.height - 2);
    if (!st.ok()) return st;
    cdt->reserve(options.target + 4);
    out->dropped_crossing = 0;
    st = insert_polylines(out->polylines, cdt, &out->dropped_crossing, &progress);
    if (!st.ok()) return st;
    progress.insertion(1, 1);
    out->n0 = cdt->vertex_count();
    return Status::success();
}

}  // namespace erd
