#include "algorithms/methods/flips.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>
#ifndef ERD_NO_THREADS
#include <atomic>
#include <thread>
#endif

#include "algorithms/methods/greedy.h"
#include "kernel/raster.h"
#include "kernel/raster_rows.h"
#include "kernel/row_parallel.h"
#include "kernel/step_helper.h"

namespace erd {

namespace {

constexpr std::size_t kMaxChannels = 3;

// Squared error of the plane through (p_i, z_i) over the pixels the triangle owns, summed over
// the channels (planes[c] with values z_i[c]; one scan of the triangle for all of them). With a
// `stop`, the sum ends after the first span where base + sum >= stop: the partial sum says all
// a rejected flip needs (sums of squares only grow, and so does a rounded sum), for a fraction
// of the pixels.
class TriangleError {
public:
    TriangleError(std::vector<const Image*> planes, const Cdt& cdt)
        : planes_(std::move(planes)), domain_{cdt.max_x(), cdt.max_y()} {}

    double operator()(LatticePoint p0, const double* z0, LatticePoint p1, const double* z1, LatticePoint p2,
                      const double* z2, double base = 0.0, double stop = std::numeric_limits<double>::infinity()) const {
        if (planes_[0]->real())
            return planes_.size() == 1 ? walk<1, true>(p0, z0, p1, z1, p2, z2, base, stop) : walk<3, true>(p0, z0, p1, z1, p2, z2, base, stop);
        return planes_.size() == 1 ? walk<1, false>(p0, z0, p1, z1, p2, z2, base, stop) : walk<3, false>(p0, z0, p1, z1, p2, z2, base, stop);
    }
    double operator()(LatticePoint p0, double z0, LatticePoint p1, double z1, LatticePoint p2, double z2) const {
        return (*this)(p0, &z0, p1, &z1, p2, &z2);
    }

private:
    // The rows walked once for all C channels (1 or 3: the planes a model has), each channel's sum in its
    // own pixel order, added as (c0 + c1) + c2; a sum stopped early (after the first row where
    // base + sum >= stop) stops the walk too. A stopped sum is at least `stop`, as the whole one
    // is; an accepted flip has whole sums. Real: the planes' real values, the pixels without data
    // left out (issue 47).
    template <std::size_t C, bool Real>
    double walk(LatticePoint p0, const double* z0, LatticePoint p1, const double* z1, LatticePoint p2, const double* z2,
                double base, double stop) const {
        SpanPlane plane[C];
        double dv[C], sse[C] = {};
        for (std::size_t c = 0; c < C; ++c) {
            plane[c].set(p0, z0[c], p1, z1[c], p2, z2[c]);
            dv[c] = 2.0 * plane[c].gx;
        }
        const std::size_t width = std::size_t(planes_[0]->width);
        const auto total = [&] {
            double t = sse[0];
            for (std::size_t c = 1; c < C; ++c) t += sse[c];
            return t;
        };
        for_each_owned_row(Lattice::pixels(), domain_, p0, p1, p2, [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            for (std::size_t c = 0; c < C; ++c) {
                double v = plane[c].at(double(2 * lo), double(2 * j)), e = sse[c];
                if constexpr (Real) {
                    const double* px = planes_[c]->reals.data() + std::size_t(j) * width;
                    const std::uint8_t* ok = planes_[c]->valid.empty() ? nullptr : planes_[c]->valid.data() + std::size_t(j) * width;
                    for (std::int32_t i = lo; i <= hi; ++i, v += dv[c]) {
                        const double d = v - px[i];
                        if (!ok || ok[i]) e += d * d;
                    }
                } else {
                    const std::uint16_t* px = planes_[c]->samples.data() + std::size_t(j) * width;
                    for (std::int32_t i = lo; i <= hi; ++i, v += dv[c]) {
                        const double d = v - double(px[i]);
                        e += d * d;
                    }
                }
                sse[c] = e;
            }
            return base + total() < stop;
        });
        return total();
    }

    std::vector<const Image*> planes_;
    RasterDomain domain_;
};

// The sums of a test measured ahead (TestsAhead): s1 over (c,a,d), s2 over (d,b,c), and which
// are whole (the others were cut short at the limit).
struct AheadSums {
    double s1 = 0.0, s2 = 0.0;
    bool whole1 = false, whole2 = false;
};

#ifndef ERD_NO_THREADS
// The first round's tests measured ahead on a second thread (-j 2; docs/DECISIONS.md "Threads").
// The loop pops the first list's entries from the top down: entry i when the entries below it
// are all that is left of that list (the flips' own entries go above them). Just below the loop,
// in a window of kRing entries, the loop copies each entry with its quadrilateral as the mesh
// then is: the corners a, b, c, d of faces (a,b,c) and (b,a,d), each with its model entry, and
// the limit the two faces' errors give. A helper thread measures the copied entries from the top
// down, kLead below the loop at least, into AheadSums, each sum cut short at the copied limit. It
// reads the copies, the image, the models and the points, none of which a flip changes, never
// the mesh. The loop takes an entry's sums when its edge still has the copied corners: the same
// two triangles with the same values (a corner's value is its vertex's wedge around the face,
// and flips change no wedge), so the same sums. A whole sum is the one-thread loop's, and a cut
// one decides only what the loop's own cut sum would (sums of squares only grow), so the flips
// and every sum they record are the one-thread loop's bits. The helper measures the loop's first
// test first, and the loop starts once it has: that test is always taken (no flip comes before
// it), so a run with a helper takes one test at least, however busy the machine.
class TestsAhead {
public:
    // work: the loop's first list (every edge); face_sse: every face's error (the loop's), or null
    // (then nothing is cut short); skip_below: the loop's skip of small errors (with face_sse).
    TestsAhead(const Cdt& cdt, const std::vector<EdgeInd>& work, const std::vector<const ErdModel*>& models,
               const std::vector<double>* face_sse, double skip_below, const TriangleError& error)
        : cdt_(cdt), models_(models), face_sse_(face_sse), skip_below_(skip_below), error_(error),
          points_(cdt.points().data()), ring_(kRing), filled_(work.size()) {
        passed(work, work.size());
        std::size_t first = work.size();
        while (first > filled_ && !ring_[(first - 1) % kRing].tested) --first;
        first_ = first > filled_ ? first - 1 : kNone;
        thread_ = std::thread([this] { serve(); });
        if (first_ != kNone)
            spin_until([&] { return ring_[first_ % kRing].state.load(std::memory_order_acquire) == kDone; });
    }
    ~TestsAhead() {
        stop_.store(true, std::memory_order_relaxed);
        thread_.join();
    }
    TestsAhead(const TestsAhead&) = delete;
    TestsAhead& operator=(const TestsAhead&) = delete;

    // The loop has popped entry `left` of the first list (work's first left entries are what is
    // left of it; left = its size before the first pop): copies the entries below as the window
    // needs, leaving entry left's own copy.
    void passed(const std::vector<EdgeInd>& work, std::size_t left) {
        left_.store(left, std::memory_order_relaxed);
        if (filled_ == 0 || left - filled_ >= kRing / 2) return;
        const std::size_t bottom = left + 1 > kRing ? left + 1 - kRing : 0;
        for (std::size_t i = filled_; i-- > bottom;) copy(work[i], i);
        filled_ = bottom;
        filled_pub_.store(bottom, std::memory_order_release);
    }

    // Entry i's sums when its quadrilateral is still (a, b, c, d), else null.
    const AheadSums* take(std::size_t i, const VertInd (&v)[4]) const {
        const Slot& s = ring_[i % kRing];
        if (s.state.load(std::memory_order_acquire) != kDone || s.entry != i) return nullptr;
        for (int k = 0; k < 4; ++k)
            if (s.v[k] != v[k]) return nullptr;
        return &s.sums;
    }

private:
    static constexpr std::size_t kRing = 4096;  // entries copied at once at most (a window of 256 KB)
    static constexpr std::size_t kLead = 8;     // the helper stays this far below the loop
    static constexpr std::size_t kNone = ~std::size_t(0);
    enum : std::uint8_t { kFree, kReady, kClaimed, kDone };
    struct Slot {
        std::atomic<std::uint8_t> state{kFree};
        bool tested = false;  // the loop tests it as the mesh was copied (flippable, not skipped)
        std::size_t entry = 0;
        VertInd v[4] = {};
        std::uint32_t at[4] = {};  // the corners' model entries (ErdModel::corner_lookup)
        double limit = 0.0;
        AheadSums sums;
    };

    // Copies entry i (edge e) into its slot, once the helper is not measuring what the slot held.
    void copy(EdgeInd e, std::size_t i) {
        Slot& s = ring_[i % kRing];
        for (std::uint8_t st = s.state.load(std::memory_order_acquire);;) {
            if (st == kClaimed) {
                spin_pause();
                st = s.state.load(std::memory_order_acquire);
            } else if (s.state.compare_exchange_weak(st, kFree, std::memory_order_acq_rel)) {
                break;
            }
        }
        s.entry = i;
        s.tested = false;
        if (!cdt_.can_flip(e)) return;  // stays free: not measured
        const EdgeInd t = cdt_.twin(e);
        const EdgeInd es[4] = {e, next_edge(e), prev_edge(e), prev_edge(t)};
        for (int k = 0; k < 4; ++k) {
            s.v[k] = cdt_.org(es[k]);
            s.at[k] = models_[0]->corner_lookup(cdt_, es[k]);
        }
        const double before = face_sse_ ? (*face_sse_)[face_of(e)] + (*face_sse_)[face_of(t)] : -1.0;
        s.limit = before >= 0 ? before - 1e-9 * (before + 1.0) : std::numeric_limits<double>::infinity();
        s.tested = !face_sse_ || !(before < skip_below_);
        s.state.store(kReady, std::memory_order_release);
    }

    void serve() {
        if (first_ != kNone) claim(first_);
        std::size_t next = left_.load(std::memory_order_relaxed);  // the entries below are still to measure
        while (!stop_.load(std::memory_order_relaxed)) {
            const std::size_t left = left_.load(std::memory_order_relaxed);
            if (next + kLead > left) next = left > kLead ? left - kLead : 0;
            const std::size_t bottom = filled_pub_.load(std::memory_order_acquire);
            if (next <= bottom) {
                if (next == 0) return;
                spin_pause();  // the loop copies more when it nears the window's bottom
                continue;
            }
            claim(--next);
        }
    }

    // Measures the entry in entry i's slot when it is copied and not claimed yet (take checks
    // which entry the slot holds).
    void claim(std::size_t i) {
        Slot& s = ring_[i % kRing];
        std::uint8_t st = kReady;
        if (!s.state.compare_exchange_strong(st, kClaimed, std::memory_order_acq_rel)) return;
        measure(&s);
        s.state.store(kDone, std::memory_order_release);
    }

    void measure(Slot* s) const {
        double z[4][kMaxChannels];
        for (int k = 0; k < 4; ++k)
            for (std::size_t c = 0; c < models_.size(); ++c) z[k][c] = models_[c]->looked_up_value(s->v[k], s->at[k]);
        const LatticePoint a = points_[s->v[0]], b = points_[s->v[1]], c = points_[s->v[2]], d = points_[s->v[3]];
        AheadSums& r = s->sums;
        r.s1 = error_(c, z[2], a, z[0], d, z[3], 0.0, s->limit);
        r.whole1 = r.s1 < s->limit;
        r.whole2 = false;
        if (r.whole1) {
            r.s2 = error_(d, z[3], b, z[1], c, z[2], r.s1, s->limit);
            r.whole2 = r.s1 + r.s2 < s->limit;
        }
    }

    const Cdt& cdt_;
    const std::vector<const ErdModel*>& models_;
    const std::vector<double>* face_sse_;
    double skip_below_;
    const TriangleError& error_;
    const LatticePoint* points_;
    std::vector<Slot> ring_;
    std::size_t filled_;  // the loop's: entries from filled_ up are copied (or popped)
    std::size_t first_ = kNone;  // the entry the loop tests first
    std::atomic<std::size_t> filled_pub_{~std::size_t(0)}, left_{0};
    std::atomic<bool> stop_{false};
    std::thread thread_;
};
#endif

// The flip loop of one or C channels: channel c's corner values from models[c] on planes[c].
// systems (one channel only) as in flips.h.
void flip_channels(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                   std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces,
                   MeshSystems* systems, double min_share, int threads) {
    FlipStats st;
    if (systems && (models.size() != 1 || !systems->matches(*cdt))) systems = nullptr;
    TriangleError triangle_error(planes, *cdt);
    const std::size_t C = models.size();
    const std::size_t nf = cdt->face_count();
    std::vector<double> face_sse(nf, -1.0);  // < 0: not computed yet
    auto corner = [&](EdgeInd e) { return models[0]->corner_value(*cdt, e); };
    // The squared error over the triangle of the corners at the origins of e0, e1, e2.
    auto tri_error = [&](EdgeInd e0, EdgeInd e1, EdgeInd e2, double base, double stop) {
        double z[3][kMaxChannels];
        const EdgeInd e[3] = {e0, e1, e2};
        for (int i = 0; i < 3; ++i) {
            if (C == 1) {
                z[i][0] = models[0]->corner_value(*cdt, e[i]);
                continue;
            }
            // The channels share their wedges (flips.h): corner e[i]'s entry is looked up once.
            const std::uint32_t at = models[0]->corner_lookup(*cdt, e[i]);
            const VertInd v = cdt->org(e[i]);
            for (std::size_t c = 0; c < C; ++c) z[i][c] = models[c]->looked_up_value(v, at);
        }
        return triangle_error(cdt->point(cdt->org(e0)), z[0], cdt->point(cdt->org(e1)), z[1], cdt->point(cdt->org(e2)),
                              z[2], base, stop);
    };
    auto sse_of = [&](FaceInd f) {
        if (face_sse[f] < 0) {
            const EdgeInd e = 3 * f;
            if (systems) {
                face_sse[f] = systems->get(*cdt, *planes[0], f).sse(corner(e), corner(e + 1), corner(e + 2));
                if (face_sse[f] < 0) face_sse[f] = 0;  // an exact fit's rounding residue
                return face_sse[f];
            }
            face_sse[f] = tri_error(e, e + 1, e + 2, 0.0, std::numeric_limits<double>::infinity());
        }
        return face_sse[f];
    };
    // Quadrilaterals whose error is below min_share of the mean of two faces cannot gain much.
    double skip_below = 0;
    if (systems && min_share > 0) {
        double total = 0;
        for (FaceInd f = 0; f < nf; ++f) total += sse_of(f);
        skip_below = min_share * 2.0 * total / double(nf);
    }
    std::vector<EdgeInd> work;
    std::vector<std::uint8_t> queued(3 * nf, 0);
    auto enqueue = [&](EdgeInd k) {
        const EdgeInd tk = cdt->twin(k);
        if (tk == noEdge || cdt->constrained(k)) return;
        const EdgeInd key = k < tk ? k : tk;
        if (!queued[key]) {
            queued[key] = 1;
            work.push_back(key);
        }
    };
    if (seed_faces) {
        for (FaceInd f : *seed_faces)
            for (EdgeInd k = 3 * f; k < 3 * f + 3; ++k) enqueue(k);
    } else {
        for (EdgeInd e = 3 * EdgeInd(nf); e-- > 0;) enqueue(e);
    }
    // Every edge's first test measured ahead on a second thread, on images large enough for it
    // to pay (greedy.h's kTwoThreadPixels, as the greedy's re-scans).
    std::size_t first_left = work.size();  // what is left of the first list: work's first entries
#ifndef ERD_NO_THREADS
    std::unique_ptr<TestsAhead> ahead;
    if (!seed_faces && resolve_threads(threads) >= 2 &&
        std::size_t(planes[0]->width) * std::size_t(planes[0]->height) >= kTwoThreadPixels)
        ahead.reset(new TestsAhead(*cdt, work, models, skip_below > 0 ? &face_sse : nullptr, skip_below, triangle_error));
#else
    (void)threads;
#endif
    while (!work.empty() && st.flips < max_flips) {
        const EdgeInd e = work.back();
        work.pop_back();
        queued[e] = 0;
        const bool first = work.size() < first_left;  // an entry of the first list
        if (first) first_left = work.size();
#ifndef ERD_NO_THREADS
        if (ahead && first) ahead->passed(work, first_left);
#endif
        if (!cdt->can_flip(e)) continue;
        const EdgeInd t = cdt->twin(e);
        // Faces (a,b,c) and (b,a,d) -> (c,a,d) and (d,b,c) (kernel/cdt.h).
        const EdgeInd ea = e, eb = next_edge(e), ec = prev_edge(e), ed = prev_edge(t);
        const double before = sse_of(face_of(e)) + sse_of(face_of(t));
        if (before < skip_below) continue;
        // A flip must win by more than rounding: the squared error then falls at every flip and
        // no edge flips back and forth. A sum cut short at the limit is at least the limit, and
        // so is the whole one: the same verdict; an accepted flip has both sums whole. A sum
        // measured ahead stands for the loop's own when it is whole or already decides.
        const double limit = before - 1e-9 * (before + 1.0);
        ++st.tested;
        const AheadSums* m = nullptr;
#ifndef ERD_NO_THREADS
        if (ahead && first) {
            const VertInd v[4] = {cdt->org(ea), cdt->org(eb), cdt->org(ec), cdt->org(ed)};
            m = ahead->take(first_left, v);
            st.ahead += m != nullptr;
        }
#endif
        const double s1 = m && (m->whole1 || !(m->s1 < limit)) ? m->s1 : tri_error(ec, ea, ed, 0.0, limit);
        if (!(s1 < limit)) continue;
        const double s2 = m && m->whole1 && (m->whole2 || !(s1 + m->s2 < limit)) ? m->s2 : tri_error(ed, eb, ec, s1, limit);
        if (!(s1 + s2 < limit)) continue;
        const EdgeInd diag = cdt->flip_edge(e);
        if (diag == noEdge) continue;
        ++st.flips;
        st.sse_before += before;
        st.sse_after += s1 + s2;
        const FaceInd f1 = face_of(diag), f2 = face_of(cdt->twin(diag));
        face_sse[f1] = s1;  // f1 = (c,a,d), f2 = (d,b,c)
        face_sse[f2] = s2;
        st.changed.push_back(f1);
        st.changed.push_back(f2);
        if (systems) systems->mark(f1), systems->mark(f2);
        for (FaceInd f : {f1, f2})
            for (EdgeInd k = 3 * f; k < 3 * f + 3; ++k)
                if (k != diag && cdt->twin(k) != diag) enqueue(k);
    }
    if (stats) *stats = st;
}

}  // namespace

void improve_by_flips(Cdt* cdt, const Image& image, const ErdModel& model, std::size_t max_flips, FlipStats* stats,
                      const std::vector<FaceInd>* seed_faces, MeshSystems* systems, double min_share, int threads) {
    flip_channels(cdt, {&image}, {&model}, max_flips, stats, seed_faces, systems, min_share, threads);
}

void improve_by_flips(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                      std::size_t max_flips, FlipStats* stats, const std::vector<FaceInd>* seed_faces, int threads) {
    flip_channels(cdt, planes, models, max_flips, stats, seed_faces, nullptr, 0.0, threads);
}

namespace {

// The moves of C channels (1 or 3, improve_by_moves): channel c's values from models[c] on
// planes[c], its face systems in *systems[c]; the gradient and the errors summed over the channels.
template <std::size_t C>
void move_channels(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                   std::int32_t step, double min_gain, const std::vector<MeshSystems*>& systems, MoveStats* stats) {
    MoveStats st;
    for (MeshSystems* s : systems)
        if (!s || !s->matches(*cdt)) return;
    TriangleError tri_error(planes, *cdt);
    const RasterDomain domain{cdt->max_x(), cdt->max_y()};
    const bool fuse = C == 3 && !planes[0]->real() && planes[1]->width == planes[0]->width &&
                      planes[2]->width == planes[0]->width;
    (void)domain;
    (void)fuse;
    std::vector<EdgeInd> star;
    std::vector<double> zs;  // per star corner and channel: (z_a, z_b) of the face (v, a, b)
    for (VertInd v = 4; v < cdt->vertex_count(); ++v) {
        const LatticePoint p0 = cdt->point(v);
        if (cdt->on_boundary(v)) continue;
        cdt->corners_around(v, &star);
        bool free = true;
        for (EdgeInd e : star) free = free && !cdt->constrained(e);
        if (!free) continue;
        // The gradient of the faces' squared error in v's position (values kept): a pixel's
        // approximation moves by -w_v grad(plane) . delta, so d SSE_f = -2 grad(plane_f) . r_f,v
        // with r_f,v = sum e w_v = (G z - h)_v of the face's system; pixels changing faces
        // across v's edges add nothing at first order (the planes agree there).
        double zv[C] = {}, current = 0, gx = 0, gy = 0;
        zs.clear();
        for (EdgeInd e : star) {
            const FaceInd f = face_of(e);
            const EdgeInd k = 3 * f;
            const int i = int(e - k);
            std::uint32_t at[3] = {0, 0, 0};
            if constexpr (C == 3) {
                // The channels share their wedges (flips.h): each corner's entry looked up once, and
                // the three channels' systems of a stale face made in one pass over its pixels.
                for (int j = 0; j < 3; ++j) at[j] = models[0]->corner_lookup(*cdt, k + EdgeInd(j));
                if (fuse && systems[0]->stale[f] && systems[1]->stale[f] && systems[2]->stale[f]) {
                    FaceSystem fs3[3];
                    face_systems3(planes.data(), domain, cdt->point(cdt->org(k)), cdt->point(cdt->org(k + 1)),
                                  cdt->point(cdt->org(k + 2)), fs3);
                    for (std::size_t c = 0; c < 3; ++c) {
                        systems[c]->faces[f] = fs3[c];
                        systems[c]->stale[f] = 0;
                    }
                }
            }
            for (std::size_t c = 0; c < C; ++c) {
                const ErdModel& model = *models[c];
                double z[3];
                if constexpr (C == 3) {
                    for (int j = 0; j < 3; ++j) z[j] = model.looked_up_value(cdt->org(k + EdgeInd(j)), at[j]);
                } else {
                    for (int j = 0; j < 3; ++j) z[j] = model.corner_value(*cdt, k + EdgeInd(j));
                }
                const FaceSystem& fs = systems[c]->get(*cdt, *planes[c], f);
                double gz[3];
                fs.gram_times(z[0], z[1], z[2], gz);
                zv[c] = z[i];
                zs.push_back(z[(i + 1) % 3]);
                zs.push_back(z[(i + 2) % 3]);
                const double s = (z[0] * gz[0] + z[1] * gz[1] + z[2] * gz[2]) -
                                 2.0 * (z[0] * fs.h[0] + z[1] * fs.h[1] + z[2] * fs.h[2]) + fs.bb;
                current += s > 0 ? s : 0;
                SpanPlane plane;
                plane.set(cdt->point(cdt->org(k)), z[0], cdt->point(cdt->org(k + 1)), z[1], cdt->point(cdt->org(k + 2)), z[2]);
                const double r = gz[i] - fs.h[i];
                gx -= 2.0 * r * plane.gx;
                gy -= 2.0 * r * plane.gy;
            }
        }
        // The lattice step most against the gradient, and its first-order gain.
        const std::int32_t dx = gx < -0.4142 * std::abs(gy) ? step : (gx > 0.4142 * std::abs(gy) ? -step : 0);
        const std::int32_t dy = gy < -0.4142 * std::abs(gx) ? step : (gy > 0.4142 * std::abs(gx) ? -step : 0);
        const double predicted = -(gx * dx + gy * dy);
        if ((dx == 0 && dy == 0) || predicted <= min_gain * current) continue;
        const LatticePoint p{p0.x + dx, p0.y + dy};
        if (!cdt->can_move(v, p)) continue;
        ++st.tested;
        const double bound = current - 1e-9 * (current + 1.0);
        double s = 0;
        for (std::size_t i = 0; i < star.size() && s < bound; ++i) {
            const EdgeInd e = star[i];
            double za[C], zb[C];
            for (std::size_t c = 0; c < C; ++c) {
                za[c] = zs[(2 * i) * C + 2 * c];
                zb[c] = zs[(2 * i) * C + 2 * c + 1];
            }
            s += tri_error(p, zv, cdt->point(cdt->dest(e)), za, cdt->point(cdt->org(prev_edge(e))), zb, s, bound);
        }
        if (!(s < bound) || !cdt->move_vertex(v, p)) continue;
        ++st.moves;
        for (EdgeInd e : star)
            for (MeshSystems* sys : systems) sys->mark(face_of(e));
    }
    if (stats) *stats = st;
}

}  // namespace

void improve_by_moves(Cdt* cdt, const Image& image, const ErdModel& model, std::int32_t step, double min_gain,
                      MeshSystems* systems, MoveStats* stats) {
    if (stats) *stats = MoveStats();
    move_channels<1>(cdt, {&image}, {&model}, step, min_gain, {systems}, stats);
}

void improve_by_moves(Cdt* cdt, const std::vector<const Image*>& planes, const std::vector<const ErdModel*>& models,
                      std::int32_t step, double min_gain, MoveStats* stats, const ColourSystems* kept) {
    if (stats) *stats = MoveStats();
    // Each channel's systems made as the moves first need them (a face's pass over the pixels).
    std::vector<MeshSystems> own(models.size());
    std::vector<MeshSystems*> systems;
    for (MeshSystems& s : own) {
        s.faces.resize(cdt->face_count());
        s.stale.assign(cdt->face_count(), 1);
        systems.push_back(&s);
    }
    if (kept && models.size() == 3) {
        for (FaceInd f = 0; f < cdt->face_count(); ++f) {
            FaceSystem fs[3];
            if (!kept->find(*cdt, f, fs)) continue;
            for (std::size_t c = 0; c < 3; ++c) {
                own[c].faces[f] = fs[c];
                own[c].stale[f] = 0;
            }
        }
    }
    if (models.size() == 1) move_channels<1>(cdt, planes, models, step, min_gain, systems, stats);
    else if (models.size() == 3) move_channels<3>(cdt, planes, models, step, min_gain, systems, stats);
}

}  // namespace erd
