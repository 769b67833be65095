#include "algorithms/methods/erd_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_set>

#include "algorithms/imaging/bilinear.h"
#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/imaging/valid_region.h"
#include "algorithms/methods/tiles.h"

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
    StepOneCounter(const Image& image, const Image* gradient, ColourGradient colour, LengthRule rule, double eps_unit,
                   bool hard, bool fallback, double budget, StepProgress* progress, int threads)
        : chain_(image, hard, gradient, colour), rule_(rule), eps_unit_(eps_unit), hard_(hard), fallback_(fallback), budget_(budget),
          progress_(progress), threads_(threads) {}

    void detect(double beta, double r) override {
        progress_->selection(0.0);
        if (progress_->cancelled()) return;  // the selection then ends at once (count 0)
        Status st = chain_.detect(params(beta, r));
        if (!st.ok() && status_.ok()) status_ = st;
        progress_->selection(3.0);
    }

    void prepare(double beta, double r) override {
        Status st = chain_.prepare(params(beta, r));
        if (!st.ok() && status_.ok()) status_ = st;
    }
    void narrow(double beta, double r) override { chain_.narrow(params(beta, r)); }
    void set_aside() override { chain_.set_aside(); }

    std::size_t count(int l, double eps) override {
        if (progress_->cancelled()) return 0;
        const PolylineList* kept = &chain_.simplify(l, eps * eps_unit_, rule_);
        // Hard edges: the side-keeping curves when they fit the budget, else plain Douglas-Peucker
        // on the same cracks (docs/DECISIONS.md "Edge kinds").
        if (hard_ && fallback_ && double(distinct_points(*kept)) > budget_) {
            kept = &chain_.simplify(l, eps * eps_unit_, rule_, CrackRule::plain);
            fell_back_ = true;
        }
        if (chain_.generation() != counted_) {
            counted_ = chain_.generation();
            count_ = distinct_points(*kept);
        }
        progress_->selection(1.0);
        return count_;
    }

    const Status& status() const { return status_; }
    bool fell_back() const { return fell_back_; }  // some count took the plain curves
    void release_detector() { chain_.release_detector(); }
    Grid<std::uint8_t> edges() const { return chain_.edge_map(); }
    const PolylineList& kept() const { return chain_.kept(); }

private:
    CannyParams params(double beta, double r) const {
        CannyParams cp;
        cp.beta = beta;
        cp.r = r;
        cp.threads = threads_;
        return cp;
    }
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
    bool fell_back_ = false;
    int threads_;
};

std::uint64_t key_of(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

// The polylines whose step across (InitialMeshOptions::min_step) is at least min_step: at the
// midpoint of each segment, phi_bar at 1.5 and 3.5 pixels to either side of it, and the jump
// between the two sides less what their slopes explain (a ramp has none, a cliff its height); the
// median over the segments.
constexpr double kCliffRatio = 3.0;  // slope across / slope beside

std::vector<Polyline> strong_polylines(const std::vector<Polyline>& lines, const Image& image, double min_step) {
    std::vector<Polyline> out;
    std::vector<double> steps;
    for (const Polyline& pl : lines) {
        steps.clear();
        for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
            const double ax = 0.5 * pl[i].x, ay = 0.5 * pl[i].y, bx = 0.5 * pl[i + 1].x, by = 0.5 * pl[i + 1].y;
            const double dx = bx - ax, dy = by - ay, len = std::sqrt(dx * dx + dy * dy);
            if (len <= 0) continue;
            const double nx = -dy / len, ny = dx / len, mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
            const auto at = [&](double t) { return bilinear(image, mx + t * nx, my + t * ny); };
            const double l1 = at(-1.5), l2 = at(-3.5), r1 = at(1.5), r2 = at(3.5);
            const double slopes = 0.75 * ((r2 - r1) + (l1 - l2));  // 3 pixels at the sides' mean slope
            // A cliff is also much steeper than its sides: a ramp's or a ridge's is not.
            const double side = std::max(std::fabs(r2 - r1), std::fabs(l1 - l2)) / 2.0, across = std::fabs(r1 - l1) / 3.0;
            steps.push_back(across >= kCliffRatio * side ? std::fabs((r1 - l1) - slopes) : 0.0);
        }
        if (steps.empty()) continue;
        std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
        if (steps[steps.size() / 2] >= min_step) out.push_back(pl);
    }
    return out;
}

}  // namespace

std::size_t distinct_points(const PolylineList& polylines) {
    const std::size_t total = polylines.points();
    if (total == 0) return 0;
    std::uint32_t last = 0;  // the largest cell
    polylines.for_each_cell([&](std::uint32_t c) { last = std::max(last, c); });
    // Linear: one bit per cell when that plane is no larger than the sorted cells would be (the
    // parameter loop counts after every detection; sorting was a tenth of step 1 on noise).
    if (std::size_t(last) / 64 <= total) {
        std::vector<std::uint64_t> bits(std::size_t(last) / 64 + 1, 0);
        std::size_t n = 0;
        polylines.for_each_cell([&](std::uint32_t c) {
            const std::uint64_t bit = std::uint64_t(1) << (c & 63u);
            n += (bits[c >> 6] & bit) == 0;
            bits[c >> 6] |= bit;
        });
        return n;
    }
    std::vector<std::uint32_t> cells;
    cells.reserve(total);
    polylines.for_each_cell([&](std::uint32_t c) { cells.push_back(c); });
    std::sort(cells.begin(), cells.end());
    return std::size_t(std::unique(cells.begin(), cells.end()) - cells.begin());
}

namespace {

Status insert_polylines(const std::vector<Polyline>& polylines, Cdt* cdt, std::size_t* dropped, StepProgress* progress,
                        bool refuse_crossing) {
    // Points first (the kernel orders a batch along a Hilbert curve), then the segments. Nobody
    // reads the batch's change report, so the kernel skips that bookkeeping.
    std::vector<LatticePoint> pts;
    for (const Polyline& pl : polylines) pts.insert(pts.end(), pl.begin(), pl.end());
    std::vector<VertInd> ids;
    Status st = cdt->insert_points(pts, &ids, false);
    if (!st.ok()) return st;
    std::size_t k = 0, done = 0;
    const std::size_t every = polylines.size() / 100 + 1;
    for (std::size_t p = 0; p < polylines.size(); ++p) {
        const Polyline& pl = polylines[p];
        if (progress && done++ % every == 0) {
            progress->insertion(done, polylines.size() + 1);
            if (progress->cancelled()) return Status::failure(kCancelled);
        }
        for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
            ConstraintReport rep;
            st = cdt->insert_constraint(ids[k + i], ids[k + i + 1], &rep);
            if (!st.ok()) return st;
            if (refuse_crossing && rep.dropped_crossing)
                return Status::bad_input("constraints: segment " + std::to_string(i) + " of polyline " + std::to_string(p) +
                                         " crosses another constraint segment (split both at a common point)");
            *dropped += rep.dropped_crossing;
        }
        k += pl.size();
    }
    return Status::success();
}


// Checks the user constraints against the image (doubled coordinates 0..2W-2 x 0..2H-2).
Status check_constraints(const std::vector<Polyline>& user, int width, int height) {
    const std::int64_t mx = 2 * std::int64_t(width) - 2, my = 2 * std::int64_t(height) - 2;
    for (std::size_t i = 0; i < user.size(); ++i)
        for (std::size_t k = 0; k < user[i].size(); ++k) {
            const LatticePoint p = user[i][k];
            if (p.x < 0 || p.x > mx || p.y < 0 || p.y > my)
                return Status::bad_input("constraints: point " + std::to_string(k) + " of polyline " + std::to_string(i) +
                                         " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") lies outside 0.." +
                                         std::to_string(mx) + " x 0.." + std::to_string(my) + " (doubled coordinates)");
        }
    return Status::success();
}

// Marks the lattice points along the user segments in the half-pixel edge map (ERDED zeroes its
// density near edge points): the points nearest the segment, one per step of its longer axis.
void mark_constraints(const std::vector<Polyline>& user, Grid<std::uint8_t>* edges) {
    for (const Polyline& pl : user) {
        for (std::size_t j = 0; j < pl.size(); ++j) {
            const LatticePoint a = pl[j], b = j + 1 < pl.size() ? pl[j + 1] : pl[j];
            const std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
            const std::int64_t steps = std::max(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
            for (std::int64_t t = 0; t <= steps; ++t) {
                // Rounded half away from zero in exact integers: (2 d t + steps) / (2 steps).
                auto at = [&](std::int64_t d) {
                    if (steps == 0) return std::int64_t(0);
                    const std::int64_t num = 2 * d * t, den = 2 * steps;
                    return num >= 0 ? (num + steps) / den : -((-num + steps) / den);
                };
                const std::int64_t x = a.x + at(dx), y = a.y + at(dy);
                if (x >= 0 && y >= 0 && x < edges->width && y < edges->height) (*edges)(int(x), int(y)) = 1;
            }
        }
    }
}

}  // namespace

Status insert_polylines(const std::vector<Polyline>& polylines, Cdt* cdt, std::size_t* dropped, bool refuse_crossing) {
    return insert_polylines(polylines, cdt, dropped, nullptr, refuse_crossing);
}

Status build_initial_mesh(const Image& image, const InitialMeshOptions& options, Cdt* cdt, InitialMesh* out) {
    static const std::vector<Polyline> kNone;
    const std::vector<Polyline>& user = options.constraints ? *options.constraints : kNone;
    Status st = check_constraints(user, image.width, image.height);
    if (!st.ok()) return st;
    const std::size_t budget = options.target > 4 ? options.target - 4 : 0;
    // The user's points and the valid region's outline, which every mesh keeps.
    std::unordered_set<std::uint64_t> seen;
    for (const Polyline& pl : user)
        for (LatticePoint p : pl) seen.insert(key_of(p));
    static const std::vector<Polyline> kNoOutline;
    const std::vector<Polyline>& outline = options.outline ? *options.outline : kNoOutline;
    for (const Polyline& pl : outline)
        for (LatticePoint p : pl) seen.insert(key_of(p));
    if (seen.size() > budget)
        return Status::bad_input(std::string(outline.empty() ? "constraints" : "the outline of the valid region (nodata)") + ": " +
                                 std::to_string(seen.size()) + " distinct points, more than the " +
                                 std::to_string(budget) + " the mesh of N = " + std::to_string(options.target) +
                                 " points has beside its corners");

    StepProgress progress(options.progress, options.request.simple >= 0 ? 1 : 2);
    if (options.detect) {
        StepOneCounter counter(image, options.colour, options.colour_gradient, options.length_rule, options.eps_unit, options.hard_edges, options.hard_fallback,
                               0.7 * double(options.target), &progress, options.threads);
        // Crack curves' counts depend on N's budget (so an earlier run's simple-test count does
        // not carry over) and were not shown to shrink with beta as Canny's do (no look-ahead).
        ErdParamRequest request = options.request;
        if (options.hard_edges) {
            request.test_points = -1;
            request.look_ahead = false;
        }
        out->params = select_erd_params(options.method, image.width, image.height, options.target, request, counter);
        counter.release_detector();
        if (!counter.status().ok()) return counter.status();
        if (progress.cancelled()) return Status::failure(kCancelled);
        out->edges = counter.edges();
        out->polylines = counter.kept().to_vector();
        if (options.near_nodata) out->polylines = clip_polylines(out->polylines, *options.near_nodata, image.width);
        if (options.min_step > 0) out->polylines = strong_polylines(out->polylines, image, options.min_step);
        out->plain_fallback = counter.fell_back();
        out->constraint_points = out->params.constrained_points;
    } else {
        out->params = ErdParams();
        out->edges = Grid<std::uint8_t>(2 * image.width - 1, 2 * image.height - 1, 0);
        out->polylines.clear();
        out->constraint_points = 0;
    }
    if (options.side_crossings && !options.side_crossings->empty()) {
        out->polylines = join_crossings(std::move(out->polylines), *options.side_crossings, image.width, image.height, &out->joined_crossings);
        out->constraint_points += 2 * options.side_crossings->size();  // the stubs (a joined end may be one)
    }
    if (!user.empty() || !outline.empty()) {
        for (const Polyline& pl : out->polylines)
            for (LatticePoint p : pl) seen.insert(key_of(p));
        out->constraint_points = seen.size();
    }

    // Only for tiny N: keep whole polylines, longest first, while the mesh stays within N (the
    // user's are always kept).
    if (out->constraint_points > budget) {
        std::vector<std::size_t> order(out->polylines.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return out->polylines[a].size() > out->polylines[b].size();
        });
        // The kept points in a hash set, so each polyline costs its own size (not the kept ones').
        std::vector<Polyline> kept;
        seen.clear();
        for (const Polyline& pl : user)
            for (LatticePoint p : pl) seen.insert(key_of(p));
        for (const Polyline& pl : outline)
            for (LatticePoint p : pl) seen.insert(key_of(p));
        std::vector<std::uint64_t> fresh;
        for (std::size_t i : order) {
            fresh.clear();
            for (LatticePoint p : out->polylines[i])
                if (seen.insert(key_of(p)).second) fresh.push_back(key_of(p));
            if (seen.size() > budget) {
                for (std::uint64_t k : fresh) seen.erase(k);
                ++out->dropped_polylines;
            } else {
                kept.push_back(std::move(out->polylines[i]));
            }
        }
        out->polylines = std::move(kept);
        out->constraint_points = seen.size();
    }

    st = cdt->reset(2 * image.width - 2, 2 * image.height - 2);
    if (!st.ok()) return st;
    cdt->reserve(options.target + 4);
    out->dropped_crossing = 0;
    if (!outline.empty()) {
        // The outline first: nothing crosses it (a user segment across it is dropped there).
        std::size_t none = 0;
        if (!(st = insert_polylines(outline, cdt, &none, nullptr, true)).ok()) return st;
    }
    if (!user.empty()) {
        // User segments first: a detected piece crossing one is the one dropped.
        // A crossing has no lattice point to split at, and keeping either segment would depend on
        // the file's order: refused.
        std::size_t none = 0;
        if (!(st = insert_polylines(user, cdt, &none, nullptr, true)).ok()) return st;
        if (out->edges.width == 2 * image.width - 1 && out->edges.height == 2 * image.height - 1)
            mark_constraints(user, &out->edges);
    }
    st = insert_polylines(out->polylines, cdt, &out->dropped_crossing, &progress, false);
    if (!st.ok()) return st;
    progress.insertion(1, 1);
    out->polylines.insert(out->polylines.end(), user.begin(), user.end());
    out->n0 = cdt->vertex_count();
    return Status::success();
}

}  // namespace erd
