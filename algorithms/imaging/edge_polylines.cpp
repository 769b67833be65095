#include "algorithms/imaging/edge_polylines.h"

#include <utility>

namespace erd {

EdgePolylines::EdgePolylines(const Image& image)
    : detector_(image), map_w_(2 * image.width - 1), map_h_(2 * image.height - 1) {}

Status EdgePolylines::detect(const CannyParams& canny) {
    if (have_edges_ && canny.beta == canny_.beta && canny.r == canny_.r && canny.modified == canny_.modified)
        return Status::success();
    canny_ = canny;
    have_edges_ = true;
    have_kept_ = false;
    // The previous detection's points and polylines are dead now: free them before the detector
    // allocates, so they do not add to the peak.
    edges_.clear();
    std::vector<Polyline>().swap(traced_);
    std::vector<Polyline>().swap(kept_);
    // Points, not a map: only the chosen detection's map is ever made (edge_map()).
    Status st = detector_.detect(canny, &edges_, &stats_);  // reuses the gradient pass while it can
    edges_.link_rows();
    traced_ = trace_polylines(edges_);
    return st;
}

const std::vector<Polyline>& EdgePolylines::simplify(int min_length, double epsilon_units, LengthRule rule) {
    if (have_kept_ && min_length == l_ && epsilon_units == eps_ && rule == rule_) return kept_;
    l_ = min_length;
    eps_ = epsilon_units;
    rule_ = rule;
    have_kept_ = true;
    ++generation_;
    kept_ = simplify_polylines(traced_, epsilon_units, min_length, rule);
    return kept_;
}

Grid<std::uint8_t> EdgePolylines::edge_map() const { return erd::edge_map(edges_, map_w_, map_h_); }

Status edge_polylines(const Image& image, const EdgePolylineParams& params, EdgePolylineResult* out) {
    if (params.epsilon < 0 || params.epsilon != params.epsilon)
        return Status::bad_input("polylines: epsilon must be >= 0");
    EdgePolylines chain(image);
    Status st = chain.detect(params.canny);
    if (!st) return st;
    chain.simplify(params.min_length, params.epsilon * kEpsilonUnitsPerPixel, params.length_rule);
    chain.release_detector();
    out->edges = chain.edge_map();
    out->traced = chain.traced().size();
    out->polylines = std::move(chain.kept());
    out->stats = chain.stats();
    return Status::success();
}

}  // namespace erd
