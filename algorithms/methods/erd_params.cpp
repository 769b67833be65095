#include "algorithms/methods/erd_params.h"

#include <cmath>

namespace erd {

namespace {

struct BetaRow {
    double upto;  // density in percent, row covers [previous upto, upto)
    double erded;
    double erdgpi;
};

constexpr BetaRow kBetaRows[] = {
    {0.20, 0.0095, 0.0110}, {0.35, 0.0095, 0.0115}, {0.75, 0.0118, 0.0118}, {1.20, 0.0280, 0.0280},
    {2.50, 0.0550, 0.0550}, {3.50, 0.0830, 0.0830}, {5.00, 0.0950, 0.0950},
};

// The loop's look-ahead (ours, with req.shortcut), before iteration k = i + 1 while the last
// detection is iteration i's and p holds iteration k's beta and l. A smaller beta finds fewer
// constrained points at the same l and epsilon (what the simple test's shortcut relies on), and
// on one detection a longer l keeps a subset of the polylines. So the detection at iteration k+1's
// beta, counted at l_k, bounds iteration k's count from below: when that is over the budget,
// iteration k cannot stop the loop, and its detection is not made; p moves on to iteration k+1
// (epsilon stays: it moves only at a count below 0.35 N) and true is returned. Otherwise the
// detection is set aside for iteration k+1, which the loop reaches unless k stops it (then it
// was one detection too many). So it is tried only where it is expected to pay: iteration i's
// detection counted at l_k (an upper bound on k's count), times *ratio squared (the count's
// expected change over one step of beta, squared for two), is over the budget. *ratio is then
// measured again from the two counts at l_k.
bool look_ahead(ConstraintPointCounter& counter, double high, double* ratio, ErdParams* p) {
    const double upper = double(counter.count(p->l, p->eps));
    if (upper * *ratio * *ratio <= high) return false;
    const double next = p->beta * 0.75;
    counter.detect(next, p->r);
    const double lower = double(counter.count(p->l, p->eps));
    *ratio = std::sqrt(lower / upper);
    if (lower <= high) {
        counter.set_aside();
        return false;
    }
    p->beta = next;
    p->l *= 2;
    return true;
}

}  // namespace

double erd_beta_table(ErdMethod method, double density_percent) {
    for (const BetaRow& row : kBetaRows)
        if (density_percent < row.upto) return method == ErdMethod::erded ? row.erded : row.erdgpi;
    const BetaRow& last = kBetaRows[sizeof kBetaRows / sizeof kBetaRows[0] - 1];
    return method == ErdMethod::erded ? last.erded : last.erdgpi;
}

ErdParams select_erd_params(ErdMethod method, int width, int height, std::size_t n,
                            const ErdParamRequest& req, ConstraintPointCounter& counter) {
    ErdParams p;
    p.r = req.r >= 0 ? req.r : 0.4;
    const double pixels = double(width) * double(height);
    const double density = pixels > 0 ? double(n) / pixels : 0.0;  // a fraction, not percent

    double ratio = 0.75;  // the look-ahead's guess of one beta step's effect on the count (below)
    if (req.simple >= 0) {
        p.simple = req.simple == 0;
    } else {
        // The test runs with the thesis's fixed choices (and the user's r): an image whose
        // initial mesh has fewer than 0.001 |half-pixel grid| constrained points is simple.
        const double grid = double(2 * std::int64_t(width) - 1) * double(2 * std::int64_t(height) - 1);
        const double first = req.beta >= 0 ? req.beta : erd_beta_table(method, density * 100.0);
        bool decided = false;
        std::size_t first_count = 0;  // at l 5, epsilon 1, when the shortcut counted it
        if (req.shortcut && first < kSimpleTestBeta) {
            if (req.test_points < 0) counter.prepare(kSimpleTestBeta, p.r);  // else no test detection comes
            counter.detect(first, p.r);
            const std::size_t c = counter.count(5, 1.0);
            if (double(c) >= 0.001 * grid) {
                p.simple = false;
                p.simple_test_points = c;
                p.simple_test_beta = first;
                decided = true;
            } else {
                counter.set_aside();
                first_count = c;
            }
        }
        if (!decided) {
            if (req.test_points >= 0) {
                p.simple_test_points = std::size_t(req.test_points);
                p.simple_test_known = true;
            } else {
                counter.detect(kSimpleTestBeta, p.r);
                p.simple_test_points = counter.count(5, 1.0);
            }
            p.simple_test_beta = kSimpleTestBeta;
            p.simple = double(p.simple_test_points) < 0.001 * grid;
            // The look-ahead's first guess of one beta step's effect: the two counts taken as a
            // power of beta.
            if (first_count > 0 && p.simple_test_points > first_count)
                ratio = std::pow(double(first_count) / double(p.simple_test_points),
                                 std::log(0.75) / std::log(first / kSimpleTestBeta));
        }
    }

    if (p.simple) {
        p.beta = 0.03;
        p.l = 1;
        p.eps = 1;
    } else {
        p.l = 5;
        p.eps = density > 0.01 ? 1.0 : 2.0;
        p.beta = erd_beta_table(method, density * 100.0);
    }
    if (req.beta >= 0) p.beta = req.beta;
    if (req.l >= 0) p.l = req.l;
    if (req.eps >= 0) p.eps = req.eps;

    const double low = 0.35 * double(n);
    const double high = 0.7 * double(n);
    counter.narrow(p.beta, p.r);  // the loop only lowers beta: the simple test's wider pass is cut
    for (;;) {
        counter.detect(p.beta, p.r);
        ++p.loop_iterations;
        std::size_t c = counter.count(p.l, p.eps);
        if (double(c) < low && req.eps < 0 && p.eps != 1.0) {
            p.eps = 1.0;
            c = counter.count(p.l, p.eps);
        }
        p.constrained_points = c;
        if (double(c) <= high) break;
        // Without req.lower_beta l alone grows while it can, so one detection serves every
        // iteration; beta then moves only when -l fixes l.
        const bool lengthen = req.l < 0;
        const bool lower = req.beta < 0 && (req.lower_beta || !lengthen);
        if (!(lengthen || lower) || p.loop_iterations >= kErdParamMaxIterations) break;
        if (lower) p.beta *= 0.75;
        if (lengthen) p.l *= 2;
        if (lower && lengthen && req.shortcut && req.look_ahead && p.loop_iterations + 2 <= kErdParamMaxIterations &&
            look_ahead(counter, high, &ratio, &p))
            ++p.loop_iterations;
    }
    return p;
}

}  // namespace erd
