#include "algorithms/methods/quality_target.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd {

namespace {

// One measured count: the run's result and its quality.
struct Probe {
    std::int64_t n = 0;
    double db = 0, max_error = 0;
    bool meets = false;
    GenerateResult result;
};

// How far a probe is from the target, on a scale the search interpolates on: positive when it
// meets it. PSNR is about linear in log N; the largest error about exponential (its log then).
double margin(const Probe& p, const GenerateOptions& o) {
    double m = INFINITY;
    if (o.psnr > 0) m = std::min(m, std::isinf(p.db) ? 1e3 : p.db - o.psnr);
    if (o.max_error >= 0) m = std::min(m, std::log((o.max_error + 0.5) / (p.max_error + 0.5)));
    return m;
}

}  // namespace

bool wants_quality_search(const Image& image, const GenerateOptions& options) {
    return !image.real() && (options.psnr > 0 || options.max_error >= 0);
}

Status measure_quality(const Image& image, const Model& model, const GenerateOptions& options, double* db,
                       double* max_error) {
    Image rec;
    Status st = reconstruct(model, supersampled(model), &rec, {}, options.threads);
    if (!st) return st;
    if (!(st = psnr(image, rec, db, options.threads))) return st;
    return max_abs_error(image, rec, max_error, options.threads);
}

Status run_method(const MethodInfo& method, const Image& image, const GenerateOptions& options, GenerateResult* result) {
    if (!wants_quality_search(image, options)) return method.run(image, options, result);
    const std::int64_t cap = target_points(options, image.width, image.height);
    Status st = check_target(cap, image.width, image.height);
    if (!st) return st;

    // The first run is the method's own, its stops on: a greedy loop stops at the first count its
    // mesh reaches the target, and where that mesh is the model (GPI: no refit or flips after, the
    // same quality measured) that count is the smallest, as the loop inserts the same points in the
    // same order whatever N is. Else its model, when it reaches the target, is the bracket's top.
    int runs = 1;
    Probe lo, hi, cur;
    bool have_lo = false, have_hi = false;
    if (!(st = method.run(image, options, &cur.result))) return st;
    if (!(st = measure_quality(image, cur.result.model, options, &cur.db, &cur.max_error))) return st;
    cur.n = std::int64_t(cur.result.achieved);
    cur.meets = margin(cur, options) >= 0;
    const RunStats& own = cur.result.stats;
    const bool one_run = !options.count_search;
    const bool exact = own.has_greedy && !own.has_erd && !options.optimize &&
                       (options.psnr <= 0 || std::fabs(own.greedy.psnr - cur.db) <= 1e-9 * std::max(1.0, cur.db)) &&
                       (options.max_error < 0 || own.greedy.max_error == cur.max_error);
    // The ERD methods' simple-image test (a detection at a fixed beta, counted at a fixed l and
    // epsilon) reads the image alone where edges are soft (hard edges' curves depend on N's
    // budget): when the first run made it, the later runs take its count (erd_params.h).
    const ErdParams& first = own.erd.params;
    const bool test_known = own.has_erd && cur.result.model.edges == EdgeKind::soft && options.simple < 0 &&
                            first.simple_test_beta == kSimpleTestBeta;
    const std::int64_t test_points = test_known ? std::int64_t(first.simple_test_points) : -1;
    if (cur.meets) hi = std::move(cur), have_hi = true;
    else lo = std::move(cur), have_lo = true;

    // Then runs that make exactly their count: the methods' own quality stops off.
    GenerateOptions at = options;
    at.psnr = 0;
    at.max_error = -1;
    at.density_given = false;
    at.simple_test_points = test_points;
    auto probe = [&](std::int64_t n, Probe* p) -> Status {
        at.points = n;
        p->n = n;
        p->result = GenerateResult();
        ++runs;
        Status s = method.run(image, at, &p->result);
        if (!s) return s;
        if (!(s = measure_quality(image, p->result.model, options, &p->db, &p->max_error))) return s;
        p->meets = margin(*p, options) >= 0;
        return s;
    };

    // The bracket: lo short of the target, hi reaching it; grown from the first run by factors of 4
    // down (or, when N itself falls short, not at all).
    if (have_hi && !exact && !one_run && hi.n > 4) {
        std::int64_t n = std::max<std::int64_t>(4, hi.n / 4);
        for (;;) {
            if (!(st = probe(n, &cur))) return st;
            if (!cur.meets) {
                lo = std::move(cur), have_lo = true;
                break;
            }
            hi = std::move(cur);
            if (n == 4) break;
            n = std::max<std::int64_t>(4, n / 4);
        }
    }

    // Narrowed in log N until the ends are within the tolerance (or next to each other).
    int same_side = 0;
    bool last_meets = false;
    while (!exact && !one_run && have_lo && have_hi && hi.n > lo.n + 1 && double(hi.n) > kQualityCountTolerance * double(lo.n)) {
        const double a = std::log(double(lo.n)), b = std::log(double(hi.n));
        const double ma = margin(lo, options), mb = margin(hi, options);
        double x = 0.5 * (a + b);
        // Interpolation unless the last two probes fell on one side (then bisection).
        if (same_side < 2 && mb > ma && std::isfinite(ma) && std::isfinite(mb)) x = a + (b - a) * (-ma) / (mb - ma);
        // Kept inside, and a step beyond the estimate so the bracket closes from both sides.
        const double tol = std::log(kQualityCountTolerance);
        x = std::clamp(x + (last_meets ? -0.4 : 0.4) * tol, a + 0.4 * tol, b - 0.4 * tol);
        std::int64_t m = std::llround(std::exp(x));
        m = std::clamp(m, lo.n + 1, hi.n - 1);
        if (!(st = probe(m, &cur))) return st;
        same_side = cur.meets == last_meets ? same_side + 1 : 1;
        last_meets = cur.meets;
        if (cur.meets) hi = std::move(cur);
        else lo = std::move(cur);
    }

    Probe& kept = have_hi ? hi : lo;
    *result = std::move(kept.result);
    if (have_hi) result->requested = std::size_t(kept.n);
    result->stats.has_quality = true;
    QualitySearchStats& q = result->stats.quality;
    q.runs = runs;
    q.points = std::size_t(kept.n);
    q.below = have_lo && have_hi ? std::size_t(lo.n) : 0;
    q.exact = exact && have_hi;
    q.reached = have_hi;
    q.psnr = kept.db;
    q.max_error = kept.max_error;
    return Status::success();
}

}  // namespace erd
