#include "algorithms/imaging/canny.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "algorithms/imaging/canny_pass.h"
#include "algorithms/imaging/float_bins.h"
#include "algorithms/imaging/gradient_rows.h"

namespace erd {

using namespace canny_detail;

namespace {

Status check_params(const CannyParams& params) {
    if (!(params.beta > 0.0 && params.beta <= 1.0)) return Status::bad_input("edge detection: beta must lie in (0, 1]");
    if (!(params.r >= 0.0 && params.r <= 1.0)) return Status::bad_input("edge detection: r must lie in [0, 1]");
    if (params.smoothing_order < 1 || params.smoothing_order % 2 == 0 || params.smoothing_order > 51)
        return Status::bad_input("edge detection: smoothing order must be odd, 1 to 51");
    if (params.max_link < 0 || params.max_link > 250) return Status::bad_input("edge detection: max_link must lie in [0, 250]");
    return Status::success();
}

// Sample: canny_pass.h's GraySample or GridSample.
template <class Sample>
Status detect_once(int width, int height, Sample sample, const CannyParams& params, Grid<std::uint8_t>* edges,
                   CannyStats* stats) {
    if (width <= 0 || height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(params);
    if (!st) return st;
    EdgeDetector::Pass pass;
    pass.run(width, height, sample, params, EdgeDetector::Pass::k_of(params.beta, std::size_t(2 * width - 1) * std::size_t(2 * height - 1)));
    SortedPoints points;
    pass.track(params, true, &points, stats);  // a pass covers the parameters it was made with
    *edges = edge_map(points, 2 * width - 1, 2 * height - 1);
    return Status::success();
}

}  // namespace

std::size_t estimated_kept_points(const Image& im, const CannyParams& params) {
    if (im.width <= 0 || im.height <= 0 || !check_params(params)) return 0;
    EdgeDetector::Pass pass;
    pass.pl = Plane(2 * im.width - 1, 2 * im.height - 1);
    const std::size_t M = std::size_t(pass.pl.w) * std::size_t(pass.pl.h);
    std::size_t expected = 0, at_estimate = M;  // too few rows to sample: the whole grid bounds it
    pass.sampled_bound(im.width, GraySample{&im}, params,
                       EdgeDetector::Pass::k_of(params.beta, M), &expected, &at_estimate);
    return std::min(at_estimate, M);
}

EdgeDetector::EdgeDetector(const Image& im, ColourGradient colour) : im_(im), colour_(colour) {}
EdgeDetector::~EdgeDetector() = default;

Status EdgeDetector::detect(const CannyParams& params, SortedPoints* edges, CannyStats* stats) {
    if (im_.width <= 0 || im_.height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(params);
    if (!st) return st;
    if (pass_ && narrowing_) pass_->narrow(narrow_);
    narrowing_ = false;
    if (pass_ && pass_->track(params, false, edges, stats)) return Status::success();
    make_pass(params);
    pass_->track(params, false, edges, stats);
    return Status::success();
}

Status EdgeDetector::prepare(const CannyParams& widest) {
    if (im_.width <= 0 || im_.height <= 0) return Status::bad_input("edge detection: empty image");
    Status st = check_params(widest);
    if (st && !pass_) make_pass(widest);
    return st;
}

void EdgeDetector::narrow(const CannyParams& widest) {
    narrowing_ = pass_ && widest.smoothing_order == pass_->smoothing_order && widest.border == pass_->border;
    narrow_ = widest;
}

std::size_t EdgeDetector::pass_points() const { return pass_ ? pass_->kept.size() : 0; }

void EdgeDetector::make_pass(const CannyParams& params) {
    pass_.reset();  // the old pass goes before the new one is made
    pass_.reset(new Pass);
    const std::size_t M = std::size_t(2 * im_.width - 1) * std::size_t(2 * im_.height - 1);
    if (im_.channels == 3 && colour_ != ColourGradient::luma)
        pass_->run(im_.width, im_.height, ColourSample{&im_, colour_}, params, Pass::k_of(params.beta, M));
    else
        pass_->run(im_.width, im_.height, GraySample{&im_}, params, Pass::k_of(params.beta, M));
}

Status EdgeDetector::detect(const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    SortedPoints points;
    Status st = detect(params, &points, stats);
    if (st) *edges = edge_map(points, 2 * im_.width - 1, 2 * im_.height - 1);
    return st;
}

Grid<std::uint8_t> edge_map(const SortedPoints& points, int width, int height) {
    Grid<std::uint8_t> map(width, height, 0);
    const std::uint32_t s = std::uint32_t(points.stride);
    for (const std::uint32_t i : points.at) map(int(i % s) - 1, int(i / s) - 1) = 1;
    return map;
}

void EdgeDetector::release() {
    pass_.reset();
    narrowing_ = false;
}

void canny_gradient(const Grid<double>& f, int smoothing_order, Border border, Grid<float>* gx, Grid<float>* gy) {
    std::vector<double> b = binomial_taps(smoothing_order);
    if (b.empty()) b = {1.0};
    if (f.width <= 0 || f.height <= 0) { *gx = Grid<float>(); *gy = Grid<float>(); return; }
    *gx = Grid<float>(f.width, f.height);
    *gy = Grid<float>(f.width, f.height);
    std::vector<float> mag(std::size_t(f.width));
    gradient_rows(
        f.width, f.height, 0, f.height, b, border,
        [&](int y, float* r) {
            for (int x = 0; x < f.width; ++x) r[x] = float(f(x, y));
        },
        [&](int) { return mag.data(); },
        [&](int y, const float* ax, const float* ay) {
            std::copy(ax, ax + f.width, &(*gx)(0, y));
            std::copy(ay, ay + f.width, &(*gy)(0, y));
        });
}

double beta_quantile(const float* values, std::size_t n, double beta) {
    if (n == 0) return 0.0;
    const double kd = std::nearbyint(beta * double(n));
    const std::size_t k = kd < 1.0 ? 1 : (kd > double(n) ? n : std::size_t(kd));
    std::vector<std::size_t> hist(kFloatBins, 0);
    for (std::size_t i = 0; i < n; ++i) ++hist[float_bin(values[i])];
    std::size_t above = 0, count = 0;
    const std::uint32_t bin = kth_bin(hist.data(), hist.size(), k, &above);
    std::vector<float> in_bin;
    for (std::size_t i = 0; i < n; ++i)
        if (float_bin(values[i]) == bin) in_bin.push_back(values[i]);
    return double(select_in_bin(&in_bin, k, above, &count));
}

Status detect_edges(const Image& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    return detect_once(im.width, im.height, GraySample{&im}, params, edges, stats);
}

Status detect_edges(const Grid<double>& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    return detect_once(im.width, im.height, GridSample{&im}, params, edges, stats);
}

}  // namespace erd