// Greedy point insertion (greedy.h): the loop. The state of a run and the files of its parts
// are greedy_refiner.h's.
#include "algorithms/methods/greedy.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <vector>

#include "algorithms/imaging/real_image.h"
#include "algorithms/methods/greedy_refiner.h"
#include "kernel/row_parallel.h"

namespace erd {

const char* to_string(GreedyStop s) {
    switch (s) {
        case GreedyStop::target: return "target";
        case GreedyStop::max_error: return "max_error";
        case GreedyStop::psnr: return "psnr";
        case GreedyStop::triangles: return "triangles";
        case GreedyStop::exhausted: return "exhausted";
    }
    return "?";
}

GreedyRefiner::GreedyRefiner(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options)
    : cdt_(cdt), image_(image), model_(model), options_(options),
      banned_(std::size_t(image.width) * std::size_t(image.height), 0),
      domain_{cdt.max_x(), cdt.max_y()}, channels_(image.channels) {
    if (image.real()) {
        // The data's units: the PSNR peak is the valid range, every pixel without data is banned
        // (never a candidate) and left out of every sum (rescan_real).
        real_ = true;
        peak_ = image.hi > image.lo ? image.hi - image.lo : 1.0;
        pixels_ = double(valid_pixels(image));
        for (std::size_t i = 0; i < image.valid.size(); ++i) banned_[i] = image.valid[i] ? 0 : 1;
    } else {
        peak_ = std::pow(2.0, image.bits()) - 1.0;
        pixels_ = double(image.width) * double(image.height);
    }
    if (!options.round_values && !image.real())
        for (std::uint32_t s = 0; s <= image.maxval; ++s) as_double_.push_back(double(s));
    track_max_ = options.max_error >= 0.0;
    max_first_ = track_max_ && options.max_error_first;
    if (options.supersampled) {
        const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
        sub_.assign(16 * w * h, 0.0f);
        left_.assign(4 * h, 0.0f);
        right_.assign(4 * h, 0.0f);
        top_.assign(4 * w, 0.0f);
        bottom_.assign(4 * w, 0.0f);
        owner_.assign(w * h, 0);
    }
    // Each insertion adds two faces; reserving avoids regrowing the heaps' back-pointer arrays.
    std::size_t faces = 2 * std::max(options.target_vertices, cdt.vertex_count()) + 8;
    if (!max_first_) by_sum_.reserve(faces);  // max_first_: the faces by largest error alone
    if (track_max_) by_max_.reserve(faces);
    faces_.reserve(faces);
    stamp_.reserve(faces);
}

Status GreedyRefiner::run(GreedyStats* stats) {
    for (LatticePoint p : cdt_.points()) ban(p);
    if (options_.ban_border) {
        const std::int32_t mx = cdt_.max_x(), my = cdt_.max_y();
        for (std::int32_t x = 0; x <= mx; x += 2) ban({x, 0}), ban({x, my});
        for (std::int32_t y = 0; y <= my; y += 2) ban({0, y}), ban({mx, y});
    }
    grow();
    if (options_.supersampled) {
        for (FaceInd f = 0; f < FaceInd(faces_.size()); ++f) paint(f);
        touched_.clear();
    }
    // A second thread for the re-scans: images without supersampling (its scans stay on one),
    // large enough for the steps to outweigh the hand-over (docs/DECISIONS.md "Threads").
    const bool two = resolve_threads(options_.threads) >= 2 && !options_.supersampled &&
                     std::size_t(image_.width) * std::size_t(image_.height) >= kTwoThreadPixels;
    StepHelper helper(two);
    helper_ = helper.threaded() ? &helper : nullptr;
    if (by_owner()) {
        scan_all_by_owner();
    } else {
        batch_.clear();
        for (FaceInd f = 0; f < FaceInd(faces_.size()); ++f) stamp_[f] = generation_, batch_.push_back(f);
        scan_batch();
    }

    GreedyStop stop;
    std::vector<FaceInd> dirty;
    const std::size_t start = cdt_.vertex_count();
    const std::size_t todo = options_.target_vertices > start ? options_.target_vertices - start : 0;
    const std::size_t report_every = std::max<std::size_t>(1, todo / 100);
    for (;;) {
        if (options_.progress && stats->insertions % report_every == 0 &&
            options_.progress.report_cancelled("greedy insertion", todo ? double(stats->insertions) / double(todo) : 1.0))
            return Status::failure(kCancelled);
        if (cdt_.vertex_count() >= options_.target_vertices) { stop = GreedyStop::target; break; }
        if (track_max_ && current_max() <= options_.max_error) { stop = GreedyStop::max_error; break; }
        if (options_.psnr > 0.0 && psnr() >= options_.psnr) { stop = GreedyStop::psnr; break; }
        if (options_.max_triangles && cdt_.face_count() >= options_.max_triangles) { stop = GreedyStop::triangles; break; }
        if (max_first_ ? by_max_.empty() : by_sum_.empty()) { stop = GreedyStop::exhausted; break; }

        const FaceInd f = max_first_ ? by_max_.top() : by_sum_.top();
        const LatticePoint p = faces_[f].cand;
        if (!model_.admissible(cdt_, p)) {
            ban(p);
            ++stats->banned;
            scan(f);
            continue;
        }
        const std::size_t before = cdt_.vertex_count();
        VertInd v = noVertex;
        Status st = cdt_.insert_point(p, &v, f);
        if (!st) return st;
        ban(p);
        if (cdt_.vertex_count() == before) {  // already a vertex: cannot happen with p banned
            scan(f);
            continue;
        }
        ++stats->insertions;
        dirty.clear();
        st = model_.on_vertex_inserted(cdt_, v, &dirty);
        if (!st) return st;
        grow();
        ++generation_;
        if (options_.supersampled) {
            touched_.clear();
            for (FaceInd c : cdt_.changes().created) paint(c);
            for (FaceInd c : cdt_.changes().created) scan(c);
            for (const Span& t : touched_)
                for (std::int32_t x = t.x_begin; x <= t.x_end; ++x) {
                    const FaceInd o = owner_[std::size_t(t.y) * std::size_t(image_.width) + std::size_t(x)];
                    if (stamp_[o] != generation_) scan(o);
                }
            for (FaceInd d : dirty)
                if (d < faces_.size() && stamp_[d] != generation_) scan(d);
        } else {
            // The new faces, then the model's dirty ones (the stamps skip repeats), in this order.
            batch_.clear();
            for (FaceInd c : cdt_.changes().created) stamp_[c] = generation_, batch_.push_back(c);
            for (FaceInd d : dirty)
                if (d < faces_.size() && stamp_[d] != generation_) stamp_[d] = generation_, batch_.push_back(d);
            scan_batch();
        }
    }
    helper_ = nullptr;
    stats->two_thread_steps = helper.two_thread_steps();
    stats->stop = stop;
    stats->total_squared_error = total_;
    stats->max_error = 0.0;
    for (const FaceState& fs : faces_) stats->max_error = std::max(stats->max_error, fs.cand_error);
    stats->psnr = psnr();
    return Status::success();
}

void GreedyRefiner::scan_batch() {
    const std::size_t n = batch_.size();
    if (n < 2 || !helper_) {
        for (const FaceInd f : batch_) scan(f);
        return;
    }
    scanned_.resize(n);
    // Faces are taken one at a time from a shared counter: their sizes differ by orders of
    // magnitude, and each result has its own slot.
    std::atomic<std::size_t> next{0};
    auto half = [&](int k) {
        std::vector<Span>* const spans = k == 0 ? &spans_ : &helper_spans_;
        for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;)
            scanned_[i] = real_           ? measure_real(batch_[i])
                          : channels_ > 1 ? measure_colour(batch_[i], spans)
                                          : measure(batch_[i]);
    };
    helper_->run(half);
    for (std::size_t i = 0; i < n; ++i) {
        total_ -= faces_[batch_[i]].sum;
        settle(batch_[i], scanned_[i]);
    }
}

Status greedy_refine(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options,
                     GreedyStats* stats) {
    *stats = GreedyStats();
    if (cdt.max_x() != 2 * (image.width - 1) || cdt.max_y() != 2 * (image.height - 1))
        return Status::failure("greedy_refine: triangulation and image sizes differ");
    if (model.channels() != image.channels || (image.channels != 1 && image.channels != GreedyRefiner::kMaxChannels))
        return Status::failure("greedy_refine: the model's and the image's channel counts differ");
    if (image.channels == 1 && !image.real()) {
        GreedyRefiner r(cdt, image, model, options);
        return r.run(stats);
    }
    GreedyOptions other = options;
    other.supersampled = false;  // the colour and the real scans evaluate points
    if (image.real()) {
        other.round_values = false;  // a real image's values are not rounded
        other.max_error_first = true;
    }
    GreedyRefiner r(cdt, image, model, other);
    return r.run(stats);
}

}  // namespace erd
