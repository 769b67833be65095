// The state of one greedy refinement run (greedy.h) and the parts of its work, one file each:
//   greedy.cpp               the loop: the stop rules, insertion, which faces are re-scanned
//   greedy_rescan.cpp        a gray face's re-scan: its owned pixels against the model's plane
//   greedy_colour.cpp        a colour face's re-scan (colour_scan.h: the 8-bit RGB fixed-point scan)
//   greedy_supersampled.cpp  the 4x4-supersampled approximation the thesis's ERDGPI measures against
// The span scans all of them use are greedy_scan.h's. Private to those files.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "algorithms/methods/greedy.h"
#include "algorithms/methods/heap.h"
#include "kernel/step_helper.h"

namespace erd {

class GreedyRefiner {
public:
    static constexpr int kMaxChannels = 3;  // the colour scan's per-channel arrays (RGB)

    GreedyRefiner(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options);

    Status run(GreedyStats* stats);

private:
    // Per-face bookkeeping: the face's squared-error sum over the pixels it owns and its candidate.
    struct FaceState {
        double sum = 0.0;
        double cand_error = -1.0;  // < 0: no admissible candidate
        LatticePoint cand;
    };

    static std::uint64_t tie_of(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

    void ban(LatticePoint p) {
        if ((p.x & 1) || (p.y & 1)) return;  // half-pixel points are never candidates anyway
        banned_[std::size_t(p.y / 2) * std::size_t(image_.width) + std::size_t(p.x / 2)] = 1;
    }

    void grow() {
        if (faces_.size() < cdt_.face_count()) {
            faces_.resize(cdt_.face_count());
            stamp_.resize(cdt_.face_count(), 0);
        }
    }

    double current_max() const { return by_max_.empty() ? 0.0 : by_max_.top_key(); }

    double psnr() const {
        if (total_ <= 0.0) return std::numeric_limits<double>::infinity();
        double mse = total_ / (pixels_ * double(channels_));
        return 10.0 * std::log10(peak_ * peak_ / mse);
    }

    // Supersampled errors: writes the model's plane of face f at the sub-samples it owns (and at
    // the border-line points its clamped border sub-samples take), and appends to touched_ the
    // pixel runs whose values that changed (greedy_supersampled.cpp).
    void paint(FaceInd f);

    // The supersampled approximation at pixel (x, y), rounded half up and clamped to [0, maxval]:
    // the mean of its 16 sub-samples, those outside the domain clamped onto its border.
    std::int32_t supersampled_value(std::int32_t x, std::int32_t y) const {
        const std::size_t sw = 4 * std::size_t(image_.width);
        const std::int32_t last_x = image_.width - 1, last_y = image_.height - 1;
        double s = 0;
        if (x > 0 && y > 0 && x < last_x && y < last_y) {  // no clamped sub-samples
            const float* row = &sub_[std::size_t(4 * y) * sw + 4 * std::size_t(x)];
            for (int l = 0; l < 4; ++l, row += sw) s += (double(row[0]) + row[1]) + (double(row[2]) + row[3]);
        } else {
            s = border_sum(x, y);
        }
        const double v = s / 16.0, maxval = double(image_.maxval);
        const double c = v < maxval ? v : maxval;
        const std::int32_t r = std::int32_t(c + 0.5);
        return r < 0 ? 0 : r;
    }

    // The 16 sub-samples' sum at a pixel on the image frame, the outside ones clamped.
    double border_sum(std::int32_t x, std::int32_t y) const;

    // Scans the pixels face f owns against the model's plane: new sum and candidate
    // (greedy_rescan.cpp). The loop calls scan(), which takes a real image to rescan_real: the
    // integer scan's code stays as it was (a test in it cost GPI 1% of its instructions).
    void rescan(FaceInd f);
    // rescan's measurement of a gray face: its error sum, candidate error (< 0: none) and
    // candidate. Reads the mesh, the model and the image only, so that faces can be measured on
    // two threads at once.
    struct Scanned {
        double sum, best;
        LatticePoint cand;
        bool has_cand;  // cand is to be stored (best may still say "no candidate")
    };
    Scanned measure(FaceInd f);
    // The same for a real image (rescan_real's measurement; in gray it also fills the owner
    // map's entries of f's pixels when the run keeps one).
    Scanned measure_real(FaceInd f);
    // The same for a colour image (rescan_colour's; spans: the caller's scratch).
    Scanned measure_colour(FaceInd f, std::vector<Span>* spans);
    // Re-scans faces batch_[0..) as scan() would one after the other: measured on both threads
    // of helper_ when the run has one (GreedyOptions::threads, images without supersampling),
    // the results then settled in batch_ order, so the sums, the heaps and the candidates are
    // the same bits as with one thread (greedy.cpp).
    void scan_batch();
    void scan(FaceInd f) {
        if (real_) rescan_real(f);
        else rescan(f);
    }

    // rescan for a real image (gray or colour): real-valued errors against the real plane, the
    // pixels without data left out (greedy_real.cpp).
    [[gnu::noinline]] void rescan_real(FaceInd f);

    // Every face scanned as rescan_real would, face after face, from GreedyOptions::owners: one
    // sweep of the rows, each span on its face's plane (greedy_real.cpp).
    void scan_all_by_owner();
    bool by_owner() const {
        return real_ && channels_ == 1 && options_.owners &&
               options_.owners->size() == std::size_t(image_.width) * std::size_t(image_.height);
    }

    // rescan for a colour image: every channel's plane by point evaluation, stepped along each
    // span (rounded and clamped as reconstruction writes it when round_values). The candidate
    // metric is the sum of squared channel errors or the largest squared channel error.
    // Kept out of rescan: inlined, it costs the gray scan registers.
    [[gnu::noinline]] void rescan_colour(FaceInd f);

    // The colour scan of 8-bit RGB in fixed point (colour_scan.h) over the pixels the face p0 p1 p2
    // owns: *sum, *best (the largest squared channel error of the candidate, -1 for none) and the
    // candidate (*bx, *by). Each channel's plane is held in 32.32 fixed point from pixel p0, and
    // each span starts from it exactly (a span's 16.16 start is within 2^-16 of the plane). False,
    // touching nothing, for a face whose planes are too steep for the lanes (more than 2^14 a pixel:
    // slivers; the double scan takes those).
    bool fixed_scan(const SpanPlane* planes, LatticePoint p0, LatticePoint p1, LatticePoint p2, double* sum,
                    double* best, std::int32_t* bx, std::int32_t* by);

    // Stores face f's new error sum and candidate error (the candidate point is in faces_[f])
    // and updates the heaps.
    void settle(FaceInd f, const Scanned& s) {
        if (s.has_cand) faces_[f].cand = s.cand;
        settle(f, s.sum, s.best);
    }
    void settle(FaceInd f, double sum, double best) {
        FaceState& fs = faces_[f];
        fs.sum = sum;
        total_ += sum;
        if (best > 0.0) {
            fs.cand_error = best;
            if (!max_first_) by_sum_.set(f, sum, tie_of(fs.cand));
            if (track_max_) by_max_.set(f, best, tie_of(fs.cand));
        } else {
            fs.cand_error = -1.0;
            if (!max_first_) by_sum_.remove(f);
            if (track_max_) by_max_.remove(f);
        }
    }

    Cdt& cdt_;
    const Image& image_;
    GreedyModel& model_;
    const GreedyOptions& options_;
    std::vector<std::uint8_t> banned_;  // per pixel: vertex already, or refused by the model
    // Sample value -> double, for the real-valued scan: a load instead of a conversion (which
    // also needs a register cleared first).
    std::vector<double> as_double_;
    RasterDomain domain_;
    std::vector<FaceState> faces_;
    std::vector<std::uint32_t> stamp_;  // generation in which the face was last scanned
    std::uint32_t generation_ = 1;
    IndexedMaxHeap by_sum_;  // faces with a candidate, keyed on squared-error sum (empty when max_first_)
    IndexedMaxHeap by_max_;  // the same faces keyed on candidate error (only for --max-error)
    bool track_max_ = false;
    bool max_first_ = false;  // GreedyOptions::max_error_first
    // Supersampled errors (GreedyOptions::supersampled): the sub-samples of the current
    // approximation (index (4y + l) * 4W + 4x + k as Lattice::supersample()), the border lines'
    // values at the sub-sample rows / columns and the corners; the face owning each pixel; the
    // pixel runs whose values the last paints changed (Span: row y, columns x_begin..x_end).
    std::vector<float> sub_, left_, right_, top_, bottom_;
    double corner_[4] = {0, 0, 0, 0};
    std::vector<FaceInd> owner_;
    std::vector<Span> spans_, touched_;
    std::vector<Span> helper_spans_;  // the helper thread's scratch for measure_colour
    std::vector<FaceInd> batch_;    // the faces scan_batch re-scans, in scan order
    std::vector<Scanned> scanned_;  // and their measurements
    StepHelper* helper_ = nullptr;  // the second thread of scan_batch (null: one thread)
    double total_ = 0.0;  // whole-image squared error (sum of the face sums)
    double peak_ = 255.0;
    double pixels_ = 0.0;  // the pixels the PSNR is over: all, or a real image's valid ones
    int channels_ = 1;
    bool real_ = false;    // a real image (Image::reals): rescan_real
};

}  // namespace erd
