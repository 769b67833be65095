// Automatic parameter selection (thesis 3.4.1) on synthetic constraint-point counts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "algorithms/methods/erd_params.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/result.h"
#include "tests/thesis_cases.h"

using namespace erd;

namespace {

// A counter whose count is a given function of (beta, l, eps); it records every call.
struct FakeCounter : ConstraintPointCounter {
    double (*fn)(double beta, int l, double eps);
    double beta = 0;
    std::vector<double> betas;
    std::vector<int> ls;
    std::vector<double> epss;
    explicit FakeCounter(double (*f)(double, int, double)) : fn(f) {}
    void detect(double b, double) override {
        beta = b;
        betas.push_back(b);
    }
    std::size_t count(int l, double eps) override {
        ls.push_back(l);
        epss.push_back(eps);
        return std::size_t(std::lround(fn(beta, l, eps)));
    }
    std::vector<double> prepared;
    std::vector<double> narrowed;  // and how many detections had run then
    std::vector<std::size_t> narrowed_after;
    int asides = 0;
    void prepare(double b, double) override { prepared.push_back(b); }
    void narrow(double b, double) override {
        narrowed.push_back(b);
        narrowed_after.push_back(betas.size());
    }
    void set_aside() override { ++asides; }
};

// The thesis's selection as written: the simple test's detection first.
ErdParamRequest thesis_request() {
    ErdParamRequest r;
    r.shortcut = false;
    return r;
}

// The same parameters chosen, and the same count reached with them.
void check_same_choices(const ErdParams& a, const ErdParams& b) {
    CHECK(a.simple == b.simple);
    CHECK(a.beta == b.beta);
    CHECK(a.l == b.l);
    CHECK(a.eps == b.eps);
    CHECK(a.constrained_points == b.constrained_points);
}

}  // namespace

TEST_CASE("beta tables 3.1 and 3.2", "[erd]") {
    CHECK(erd_beta_table(ErdMethod::erded, 0.0) == 0.0095);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 0.0) == 0.0110);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 0.125) == 0.0110);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 0.20) == 0.0115);
    CHECK(erd_beta_table(ErdMethod::erded, 0.25) == 0.0095);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 0.5) == 0.0118);
    CHECK(erd_beta_table(ErdMethod::erded, 0.75) == 0.0280);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 1.0) == 0.0280);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 2.0) == 0.0550);
    CHECK(erd_beta_table(ErdMethod::erded, 3.0) == 0.0830);
    CHECK(erd_beta_table(ErdMethod::erded, 3.5) == 0.0950);
    CHECK(erd_beta_table(ErdMethod::erdgpi, 12.0) == 0.0950);
}

TEST_CASE("not simple: initial choices from the table, no loop needed", "[erd]") {
    // 1000 x 1000 image, N = 10000 (1%): 0.35N = 3500, 0.7N = 7000; grid threshold ~4.
    FakeCounter c([](double, int, double) { return 5000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, thesis_request(), c);
    CHECK_FALSE(p.simple);
    CHECK(p.simple_test_points == 5000);
    CHECK(p.simple_test_beta == 0.055);
    CHECK(c.betas.front() == 0.055);  // the simple test
    CHECK(c.prepared.empty());
    CHECK(c.ls.front() == 5);
    CHECK(c.epss.front() == 1.0);
    CHECK(p.beta == 0.0280);
    CHECK(p.l == 5);
    CHECK(p.eps == 2.0);  // D = 1% is not > 1%
    CHECK(p.r == 0.4);
    CHECK(p.loop_iterations == 1);
    CHECK(p.constrained_points == 5000);
}

TEST_CASE("density above 1% takes eps = 1", "[erd]") {
    // 100 x 100, N = 300 (3%): counts between 0.35N = 105 and 0.7N = 210 need no loop.
    FakeCounter c([](double, int, double) { return 150.0; });
    ErdParams p = select_erd_params(ErdMethod::erded, 100, 100, 300, {}, c);
    CHECK(p.eps == 1.0);
    CHECK(p.beta == 0.0830);
}

TEST_CASE("too many constrained points: beta shrinks by 0.75 and l doubles", "[erd]") {
    // Count proportional to beta / l: starts at 20000 with beta 0.028, l 5.
    FakeCounter c([](double beta, int l, double) { return 20000.0 * (beta / 0.028) * (5.0 / l); });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, c);
    // 20000 -> 7500 -> 2812.5 (< 3500 but eps already... eps is 2 -> set 1, recount same) -> stop
    REQUIRE(p.loop_iterations == 3);
    CHECK(p.beta == Approx(0.028 * 0.75 * 0.75));
    // The loop is announced once, at its first (widest) beta, before its first detection.
    CHECK(c.narrowed == std::vector<double>{0.028});
    CHECK(c.narrowed_after == std::vector<std::size_t>{1});  // after the simple test's detection
    CHECK(p.l == 20);
    CHECK(p.eps == 1.0);  // the last count fell below 0.35N, so eps was reset to 1
}

TEST_CASE("--lower-beta 0: l doubles on the one detection", "[erd]") {
    FakeCounter c([](double beta, int l, double) { return 20000.0 * (beta / 0.028) * (5.0 / l); });
    ErdParamRequest l_alone;
    l_alone.lower_beta = false;
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, l_alone, c);
    // 20000 (l 5) -> 10000 (l 10) -> 5000 (l 20) <= 0.7N: three iterations at beta 0.028.
    REQUIRE(p.loop_iterations == 3);
    CHECK(p.beta == 0.028);
    CHECK(p.l == 20);
    CHECK(p.eps == 2.0);  // 5000 is not below 0.35N
    CHECK(p.constrained_points == 5000);
    // The shortcut's first detection is the loop's: every call asks for the same beta.
    CHECK(c.betas == std::vector<double>(c.betas.size(), 0.028));

    // -l fixed: beta is what moves.
    ErdParamRequest req = l_alone;
    req.l = 5;
    FakeCounter c2([](double beta, int l, double) { return 20000.0 * (beta / 0.028) * (5.0 / l); });
    ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, req, c2);
    CHECK(q.l == 5);
    CHECK(q.beta == Approx(0.028 * 0.75 * 0.75 * 0.75 * 0.75));  // 20000 * 0.75^4 = 6328 <= 7000
}

namespace {
// The distinct betas a counter was asked to detect at (a detection each).
std::size_t distinct_betas(const FakeCounter& c) {
    std::vector<double> b = c.betas;
    std::sort(b.begin(), b.end());
    return std::size_t(std::unique(b.begin(), b.end()) - b.begin());
}
}  // namespace

TEST_CASE("the loop's look-ahead: the loop's choices, an iteration's detection skipped", "[erd]") {
    // Counts that fall steeply with beta: 1e5 at beta 0.028 and l 5, n = 10000 (budget 7000).
    FakeCounter c([](double beta, int l, double) { return 1e5 * std::pow(beta / 0.028, 4.0) * std::sqrt(5.0 / l); });
    ErdParamRequest off;
    off.look_ahead = false;
    FakeCounter d(c.fn);
    const ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, c);
    const ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, off, d);
    check_same_choices(p, q);
    CHECK(p.loop_iterations == q.loop_iterations);
    REQUIRE(q.loop_iterations >= 3);
    // Iteration 1 (beta 0.021, l 10) is over the budget even at iteration 2's beta: not detected.
    CHECK(std::count(d.betas.begin(), d.betas.end(), 0.028 * 0.75) == 1);
    CHECK(std::count(c.betas.begin(), c.betas.end(), 0.028 * 0.75) == 0);
    CHECK(distinct_betas(c) < distinct_betas(d));
}

TEST_CASE("the loop's look-ahead makes the loop's choices, with fewer detections", "[erd]") {
    // Counts that grow with beta and fall with l, steeply or not, over budgets around them. A
    // look-ahead whose detection the loop then does not reach costs one detection; only the last
    // one of a run can (the others' are taken up), so a run makes at most one detection more.
    static double scale = 1.0, a = 1.0, b = 1.0;
    std::size_t with = 0, without = 0;
    auto counts = [](double beta, int l, double eps) {
        return scale * 1e4 * std::pow(beta / 0.011, a) * std::pow(5.0 / l, b) * (eps == 1.0 ? 1.2 : 1.0);
    };
    for (double sa : {0.5, 1.0, 2.0, 4.0})
        for (double sb : {0.3, 1.0, 2.0})
            for (double sc : {0.05, 0.3, 1.0, 3.0, 20.0})
                for (std::size_t n : {300u, 1000u, 3000u}) {
                    scale = sc;
                    a = sa;
                    b = sb;
                    ErdParamRequest off;
                    off.look_ahead = false;
                    FakeCounter on_c(counts), off_c(counts), thesis_c(counts);
                    const ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, n, {}, on_c);
                    const ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, n, off, off_c);
                    const ErdParams t = select_erd_params(ErdMethod::erdgpi, 1000, 1000, n, thesis_request(), thesis_c);
                    INFO("a " << sa << " b " << sb << " scale " << sc << " n " << n);
                    check_same_choices(p, q);
                    check_same_choices(p, t);
                    CHECK(p.loop_iterations == q.loop_iterations);
                    CHECK(distinct_betas(on_c) <= distinct_betas(off_c) + 1);
                    with += distinct_betas(on_c);
                    without += distinct_betas(off_c);
                }
    CHECK(with < without);
}

TEST_CASE("too few constrained points: eps := 1 and recount", "[erd]") {
    FakeCounter c([](double, int, double eps) { return eps == 1.0 ? 6000.0 : 3000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, c);
    CHECK(p.eps == 1.0);
    CHECK(p.constrained_points == 6000);
    CHECK(p.loop_iterations == 1);
}

TEST_CASE("simple image test and -S override", "[erd]") {
    // Threshold 0.001 * 1999 * 1999 = 3996: 3000 points is simple.
    FakeCounter c([](double, int, double) { return 3000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, thesis_request(), c);
    CHECK(p.simple);
    CHECK(p.beta == 0.03);
    CHECK(p.l == 1);
    CHECK(p.eps == 1.0);

    ErdParamRequest req;
    req.simple = 1;  // thesis: -S nonzero means not simple
    FakeCounter c2([](double, int, double) { return 3000.0; });
    ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, req, c2);
    CHECK_FALSE(q.simple);
    CHECK(q.simple_test_points == 0);
    CHECK(c2.betas.front() == 0.0280);  // no simple test ran

    req.simple = 0;
    FakeCounter c3([](double, int, double) { return 100000.0; });
    ErdParams s = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, req, c3);
    CHECK(s.simple);
}

TEST_CASE("manual flags stay fixed", "[erd]") {
    FakeCounter c([](double beta, int, double) { return 20000.0 * beta / 0.028; });
    ErdParamRequest req;
    req.l = 3;
    req.eps = 2.5;
    req.r = 0.3;
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, req, c);
    CHECK(p.l == 3);
    CHECK(p.eps == 2.5);
    CHECK(p.r == 0.3);
    CHECK(p.beta < 0.028 * 0.7 * 0.75);

    req.beta = 0.2;
    FakeCounter c2([](double, int, double) { return 1e9; });
    ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, req, c2);
    CHECK(q.beta == 0.2);
    CHECK(q.loop_iterations == 1);  // nothing it may move
}

TEST_CASE("the simple test's shortcut: the loop's first detection decides when it reaches the threshold", "[erd]") {
    // 1000 x 1000, N = 10000 (1%): the loop starts at 0.028; the test's threshold is 3996.
    FakeCounter c([](double, int, double) { return 5000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, c);
    CHECK_FALSE(p.simple);
    CHECK(p.simple_test_beta == 0.028);
    CHECK(p.simple_test_points == 5000);
    CHECK(c.prepared == std::vector<double>{0.055});  // the pass is made wide enough for the test
    CHECK(c.betas == std::vector<double>{0.028, 0.028});  // the second is the loop's (a counter skips it)
    CHECK(c.asides == 0);
    CHECK(p.beta == 0.028);
    CHECK(p.loop_iterations == 1);
}

TEST_CASE("the simple test's shortcut: below the threshold the test runs, the first detection set aside", "[erd]") {
    // Fewer points at 0.028 than the threshold, more at 0.055: not simple, as the thesis decides.
    FakeCounter c([](double beta, int, double) { return beta >= 0.055 ? 5000.0 : 3000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, c);
    CHECK_FALSE(p.simple);
    CHECK(p.simple_test_beta == 0.055);
    CHECK(p.simple_test_points == 5000);
    CHECK(c.betas == std::vector<double>{0.028, 0.055, 0.028});
    CHECK(c.asides == 1);
    CHECK(c.narrowed == std::vector<double>{0.028});  // the test's wider pass is cut after it
    CHECK(c.narrowed_after == std::vector<std::size_t>{2});
    // A simple image: the loop then starts at 0.03.
    FakeCounter s([](double, int, double) { return 3000.0; });
    ErdParams q = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 10000, {}, s);
    CHECK(q.simple);
    CHECK(s.betas == std::vector<double>{0.028, 0.055, 0.03});
    CHECK(s.narrowed == std::vector<double>{0.03});
}

TEST_CASE("the simple test's shortcut: at 2.5% and above the loop starts at or above 0.055, no shortcut", "[erd]") {
    FakeCounter c([](double, int, double) { return 200000.0; });
    ErdParams p = select_erd_params(ErdMethod::erdgpi, 1000, 1000, 30000, {}, c);
    CHECK(c.betas.front() == 0.055);
    CHECK(c.prepared.empty());
    CHECK(p.simple_test_beta == 0.055);
}

TEST_CASE("a known simple-test count: the same choices without the test's detection", "[erd]") {
    // Counts that grow with beta; over densities and thresholds around them, with the shortcut and
    // without (--thesis), the count given instead of detected at 0.055 changes no choice.
    static double scale = 1.0;
    auto counts = [](double beta, int l, double eps) { return scale * 1e5 * beta * (5.0 / l) / eps; };
    for (double sc : {0.1, 0.5, 0.73, 1.0, 2.0})
        for (std::size_t n : {1000u, 10000u, 30000u})
            for (bool shortcut : {true, false}) {
                scale = sc;
                ErdParamRequest req;
                req.shortcut = shortcut;
                FakeCounter a(counts), b(counts);
                const ErdParams pa = select_erd_params(ErdMethod::erdgpi, 1000, 1000, n, req, a);
                req.test_points = std::int64_t(std::lround(counts(kSimpleTestBeta, 5, 1.0)));
                const ErdParams pb = select_erd_params(ErdMethod::erdgpi, 1000, 1000, n, req, b);
                INFO("scale " << sc << " n " << n << " shortcut " << shortcut);
                check_same_choices(pa, pb);
                CHECK(pa.simple_test_points == pb.simple_test_points);
                // No detection at the test's beta unless the loop itself asks for it, and no pass
                // widened for it.
                const bool loop_at_test = pa.beta == kSimpleTestBeta;
                CHECK((std::count(b.betas.begin(), b.betas.end(), kSimpleTestBeta) > 0) == loop_at_test);
                CHECK(b.prepared.empty());
                CHECK(pb.simple_test_known == (pb.simple_test_beta == kSimpleTestBeta));
            }
}

TEST_CASE("the simple test's shortcut decides as the test does when counts grow with beta", "[erd]") {
    // Counts that grow with beta (as measured on every test image): over thresholds around the
    // counts, densities and both methods, the shortcut's verdict and parameters are the thesis's.
    static double scale = 1.0;
    auto counts = [](double beta, int l, double eps) { return scale * 1e5 * beta * (5.0 / l) / eps; };
    for (double sc : {0.1, 0.5, 0.7, 0.73, 0.75, 1.0, 2.0, 10.0})
        for (std::size_t n : {1000u, 5000u, 10000u, 20000u})
            for (ErdMethod m : {ErdMethod::erdgpi, ErdMethod::erded}) {
                scale = sc;
                FakeCounter a(counts), b(counts);
                const ErdParams pa = select_erd_params(m, 1000, 1000, n, {}, a);
                const ErdParams pb = select_erd_params(m, 1000, 1000, n, thesis_request(), b);
                INFO("scale " << sc << " n " << n);
                check_same_choices(pa, pb);
            }
}

TEST_CASE("--lower-beta 0 on lena at 311 points: the table's beta, a longer l, one detection", "[erd]") {
    Image im;
    if (!test::read_thesis_image("lena", &im)) return;
    GenerateOptions o;
    o.points = 311;
    o.density_given = false;
    GenerateResult thesis_loop, l_alone;
    REQUIRE(find_method("erdgpi")->run(im, o, &thesis_loop).ok());
    o.lower_beta = false;
    REQUIRE(find_method("erdgpi")->run(im, o, &l_alone).ok());
    const ErdParams& a = thesis_loop.stats.erd.params;
    const ErdParams& b = l_alone.stats.erd.params;
    // The thesis's loop runs there: beta 0.011 -> 0.00825 -> 0.0061875 as l goes 5 -> 40.
    REQUIRE(a.loop_iterations > 1);
    CHECK(a.beta < 0.011);
    CHECK(b.beta == 0.011);
    CHECK(b.l > a.l);
    CHECK(b.constrained_points <= std::size_t(0.7 * 311));
    CHECK(l_alone.model.vertices.size() == 311);
}
