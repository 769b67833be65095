#include "algorithms/imaging/edge_polylines.h"

#include <utility>

#include "algorithms/imaging/edge_kind.h"

namespace erd {

EdgePolylines::EdgePolylines(const Image& image, bool hard, const Image* gradient, ColourGradient colour)
    : image_(image), hard_(hard), detector_(gradient ? *gradient : image, colour), map_w_(2 * image.width - 1), map_h_(2 * image.height - 1) {}

namespace {

bool same_detection(const CannyParams& a, const CannyParams& b) {
    return a.beta == b.beta && a.r == b.r && a.modified == b.modified;
}

}  // namespace

Status EdgePolylines::prepare(const CannyParams& widest) {
    return hard_ ? Status::success() : detector_.prepare(widest);
}

void EdgePolylines::set_aside() {
    if (!have_edges_) return;
    aside_ = Detection{canny_, stats_, std::move(traced_)};
    have_edges_ = have_kept_ = false;
    traced_.clear();
    kept_.clear();
}

Status EdgePolylines::detect(const CannyParams& canny) {
    if (have_edges_ && same_detection(canny, canny_)) return Status::success();
    if (aside_ && same_detection(canny, aside_->canny)) {
        canny_ = aside_->canny;
        stats_ = aside_->stats;
        traced_ = std::move(aside_->traced);
        aside_.reset();
        have_edges_ = true;
        have_kept_ = false;
        kept_.clear();
        return Status::success();
    }
    if (have_edges_) aside_.reset();  // a third detection: what was set aside is not wanted back
    canny_ = canny;
    have_edges_ = true;
    have_kept_ = false;
    // The previous detection's polylines are dead now: free them before the detector allocates,
    // so they do not add to the peak.
    traced_.clear();
    kept_.clear();
    if (hard_) {
        if (!(canny.beta > 0 && canny.beta <= 1) || !(canny.r >= 0 && canny.r <= 1))
            return Status::bad_input("crack edges: beta must be in (0, 1] and r in [0, 1]");
        if (!cracker_) cracker_.emplace(image_);  // the steps' histogram, once per image
        cracker_->detect(canny.beta, canny.r, &cracks_);  // into the last detection's map: no fresh pages
        progress_(stage_, from_ + (to_ - from_) * 0.6);
        traced_ = trace_polylines(cracks_);
        progress_(stage_, to_);
        return Status::success();
    }
    // Points, not a map: only the chosen detection's map is ever made (edge_map(), from the traced
    // polylines, which hold every edge point).
    const auto at = [&](double f) { progress_(stage_, from_ + (to_ - from_) * f); };
    SortedPoints edges;
    Status st = detector_.detect(canny, &edges, &stats_);  // reuses the gradient pass while it can
    at(0.6);
    PointBits bits;  // tracing needs the plane alone: the list goes before the lines are made
    bits.build(edges.at.data(), edges.size(), edges.stride);
    edges.clear();
    at(0.75);
    traced_ = trace_polylines(bits);
    at(1.0);
    return st;
}

const PolylineList& EdgePolylines::simplify(int min_length, double epsilon_units, LengthRule rule, CrackRule crack) {
    if (have_kept_ && min_length == l_ && epsilon_units == eps_ && rule == rule_ && (!hard_ || crack == crack_)) return kept_;
    l_ = min_length;
    eps_ = epsilon_units;
    rule_ = rule;
    crack_ = crack;
    have_kept_ = true;
    ++generation_;
    if (!hard_)
        kept_ = simplify_polylines(traced_, epsilon_units, min_length, rule);
    else if (crack == CrackRule::keep_sides)
        kept_ = simplify_crack_polylines(traced_, kHardEpsilonScale * epsilon_units, min_length);
    else
        kept_ = simplify_polylines(traced_, kHardEpsilonScale * epsilon_units, min_length, rule);
    return kept_;
}

Grid<std::uint8_t> EdgePolylines::edge_map() const {
    // Hard edges too: the traced polylines hold every point of their crack map (isolated ones as
    // one-point lines), which may be another detection's than the one in cracks_ now. A map of
    // its own, not cracks_'s memory: ERDED frees it before its density plane, and a hole left
    // low in the heap stays resident where one at the top goes back (synth 2048^2 -d 1: 74.4
    // against 62.4 MB).
    Grid<std::uint8_t> map(map_w_, map_h_, 0);
    traced_.for_each_point([&](LatticePoint p) { map(p.x, p.y) = 1; });
    return map;
}

Status edge_polylines(const Image& image, const EdgePolylineParams& params, EdgePolylineResult* out) {
    if (params.epsilon < 0 || params.epsilon != params.epsilon)
        return Status::bad_input("polylines: epsilon must be >= 0");
    params.progress("edges", 0.0);
    EdgePolylines chain(image);
    chain.set_progress(params.progress, "edges", 0.0, 0.8);
    Status st = chain.detect(params.canny);
    if (!st) return st;
    params.progress("edges", 0.8);
    chain.simplify(params.min_length, params.epsilon * kEpsilonUnitsPerPixel, params.length_rule);
    chain.release_detector();
    params.progress("edges", 1.0);
    out->edges = chain.edge_map();
    out->traced = chain.traced().size();
    out->polylines = chain.kept().to_vector();
    out->stats = chain.stats();
    return Status::success();
}

}  // namespace erd
