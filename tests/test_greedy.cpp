// greedy_refine against a straightforward reference: the same greedy rule (thesis 3.2.2) written
// the slow, obvious way, rescanning every face from scratch after every insertion with plain
// per-pixel loops (span list from scan_triangle; rounded values by exact integer division when
// the model has integer corner values in [0, maxval], else the plane stepped as reconstruction
// steps it with std::floor rounding; the candidate test on |e|). The fast loop (row walk fused
// with the scan, RoundedPlane's stepped truncation, the e^2 screen of the candidate test) must
// insert the same points in the same order, so the meshes agree point for point.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "algorithms/methods/gpi.h"
#include "algorithms/methods/greedy.h"
#include "kernel/cdt.h"
#include "kernel/raster.h"
#include "tests/test_greedy_util.h"
#include "tests/test_rounding_util.h"

using namespace erd;

namespace {

// Planes through the samples plus a per-vertex offset (so vertex pixels have errors, values leave
// [0, maxval] and the clamps act), or exactly GPI's planes when `offset` is 0. Flat: each face
// takes the value at its first vertex everywhere, so errors are integers and ties abound. An
// integral offset gives integer corner values (integer_values), some of them outside [0, maxval]
// (those faces take the real-valued rounding, the others the exact one).
class OffsetModel : public GreedyModel {
public:
    OffsetModel(const Image& im, double offset, bool flat) : im_(im), offset_(offset), flat_(flat) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override {
        LatticePoint p[3];
        double z[3];
        values(cdt, f, p, z);
        SpanPlane pl;
        pl.set(p[0], z[0], p[1], z[1], p[2], z[2]);
        return pl;
    }
    bool integer_values(const Cdt& cdt, FaceInd f, std::int64_t zi[3]) const override {
        if (offset_ != std::floor(offset_)) return false;
        LatticePoint p[3];
        double z[3];
        values(cdt, f, p, z);
        for (int i = 0; i < 3; ++i) zi[i] = std::int64_t(z[i]);
        return true;
    }
    Status on_vertex_inserted(const Cdt&, VertInd, std::vector<FaceInd>*) override { return Status::success(); }

private:
    void values(const Cdt& cdt, FaceInd f, LatticePoint p[3], double z[3]) const {
        for (int i = 0; i < 3; ++i) {
            p[i] = cdt.point(cdt.face_vertex(f, i));
            z[i] = double(im_.at(p[i].x / 2, p[i].y / 2)) + offset_ * double((p[i].x / 2 + 3 * (p[i].y / 2)) % 5 - 2);
        }
        if (flat_) z[1] = z[2] = z[0];
    }

    const Image& im_;
    double offset_;
    bool flat_;
};

struct RefFace {
    double sum = 0.0;
    double best = -1.0;  // largest |e| over non-vertex pixels, -1 when none
    LatticePoint cand;
};

// The model's integer corner values when all lie in [0, maxval]: the faces greedy_refine rounds
// exactly.
bool integer_values_in_range(const Cdt& cdt, FaceInd f, const Image& im, const GreedyModel& model, std::int64_t z[3]) {
    if (!model.integer_values(cdt, f, z)) return false;
    for (int i = 0; i < 3; ++i)
        if (z[i] < 0 || z[i] > std::int64_t(im.maxval)) return false;
    return true;
}

// One face, scanned the obvious way.
RefFace scan_face(const Cdt& cdt, FaceInd f, const Image& im, const GreedyModel& model, bool rounded,
                  const std::vector<char>& vertex) {
    const Lattice lat = Lattice::pixels();
    const SpanPlane pl = model.face_plane(cdt, f);
    const LatticePoint p[3] = {cdt.point(cdt.face_vertex(f, 0)), cdt.point(cdt.face_vertex(f, 1)),
                               cdt.point(cdt.face_vertex(f, 2))};
    std::int64_t z[3] = {0, 0, 0};
    const bool integers = integer_values_in_range(cdt, f, im, model, z);
    std::vector<Span> spans;
    scan_triangle(lat, RasterDomain{cdt.max_x(), cdt.max_y()}, p[0], p[1], p[2], &spans);
    RefFace r;
    std::int64_t isum = 0;
    for (const Span& s : spans) {
        double v = pl.at(lat, s.x_begin, s.y), acc = 0.0;
        for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += pl.step_x(lat)) {
            const double approx = rounded ? erd_test::reference_rounded(integers, p, z, x, s.y, v, im.maxval) : v;
            const double e = double(im.at(x, s.y)) - approx;
            if (rounded) isum += std::llround(e * e);
            else acc += e * e;
            if (std::fabs(e) > r.best && !vertex[std::size_t(s.y) * std::size_t(im.width) + std::size_t(x)]) {
                r.best = std::fabs(e);
                r.cand = LatticePoint{2 * x, 2 * s.y};
            }
        }
        r.sum += acc;
    }
    if (rounded) r.sum = double(isum);
    return r;
}

// The reference loop: the face of largest sum (ties: the candidate first in (Y, X) order) gives
// its candidate; faces without a candidate of nonzero error take no part.
std::vector<LatticePoint> reference_greedy(const Image& im, const GreedyModel& model, bool rounded,
                                           std::size_t target) {
    Cdt cdt;
    REQUIRE(cdt.reset(2 * (im.width - 1), 2 * (im.height - 1)).ok());
    std::vector<char> vertex(im.pixels(), 0);
    for (LatticePoint p : cdt.points()) vertex[std::size_t(p.y / 2) * std::size_t(im.width) + std::size_t(p.x / 2)] = 1;
    while (cdt.vertex_count() < target) {
        bool found = false;
        RefFace top;
        for (FaceInd f = 0; f < FaceInd(cdt.face_count()); ++f) {
            const RefFace r = scan_face(cdt, f, im, model, rounded, vertex);
            if (!(r.best > 0.0)) continue;
            const bool first = r.cand.y < top.cand.y || (r.cand.y == top.cand.y && r.cand.x < top.cand.x);
            if (!found || r.sum > top.sum || (r.sum == top.sum && first)) top = r;
            found = true;
        }
        if (!found) break;
        VertInd v = noVertex;
        REQUIRE(cdt.insert_point(top.cand, &v).ok());
        vertex[std::size_t(top.cand.y / 2) * std::size_t(im.width) + std::size_t(top.cand.x / 2)] = 1;
    }
    return cdt.points();
}

// The points greedy_refine inserts, in order (the four corners first).
std::vector<LatticePoint> fast_greedy(const Image& im, GreedyModel& model, bool rounded, std::size_t target) {
    Cdt cdt;
    erd_test::refine_to(im, model, target, &cdt, rounded);
    return cdt.points();
}

}  // namespace

TEST_CASE("greedy loop: the same points in the same order as a from-scratch reference", "[basic]") {
    // Sizes, maxvals and planes that exercise every scan path: exact rounding of integer planes
    // (GPI's own, flat ones full of exact .5 values, 16-bit), integral offsets that push some
    // faces' values past 0 and maxval (those faces take the clamping real-valued rounding),
    // fractional offsets (all faces real-valued), and the real-valued loop of ERDGPI.
    struct Case {
        int w, h;
        std::uint32_t maxval;
        double offset;
        bool flat, rounded;
    };
    const Case cases[] = {{23, 17, 255, 0.0, false, true},    {31, 12, 255, 7.5, false, true},
                          {19, 26, 65535, 0.0, false, true},  {23, 17, 255, 0.0, false, false},
                          {31, 12, 255, 7.5, false, false},   {19, 26, 65535, 900.0, false, false},
                          {2, 9, 255, 3.0, false, true},      {16, 2, 255, 3.0, false, false},
                          {25, 21, 255, 0.0, true, true},     {25, 21, 255, 0.0, true, false},
                          {22, 18, 255, 4.0, true, false}};
    std::mt19937 rng(4242);
    for (const Case& c : cases) {
        Image im(c.w, c.h, c.maxval);
        const double scale = double(c.maxval) / 255.0;
        for (int y = 0; y < c.h; ++y)
            for (int x = 0; x < c.w; ++x) {
                // Around 64 and 128 with steps and noise; a few pixels at the extremes.
                double v = (x + y) % 11 < 5 ? 64.0 : 128.0;
                v += 20.0 * std::sin(0.7 * x) - 9.0 * std::cos(0.45 * y) + double(rng() % 7) - 3.0;
                if (rng() % 29 == 0) v = (rng() % 2) ? 255.0 : 0.0;
                im.at(x, y) = std::uint16_t(std::clamp(std::lround(v * scale), 0L, long(c.maxval)));
            }
        const std::size_t target = std::min<std::size_t>(im.pixels(), 4 + std::size_t(c.w * c.h) / 6);
        OffsetModel model(im, c.offset * scale, c.flat);
        INFO(c.w << "x" << c.h << " maxval " << c.maxval << " offset " << c.offset << " flat " << c.flat << " rounded "
                 << c.rounded);
        CHECK(fast_greedy(im, model, c.rounded, target) == reference_greedy(im, model, c.rounded, target));
    }
}

TEST_CASE("greedy loop: GPI on a photo-like image matches the reference", "[basic]") {
    Image im(40, 30, 255);
    std::mt19937 rng(99);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            im.at(x, y) = std::uint16_t(std::clamp(std::lround(120.0 + 70.0 * std::sin(x / 6.0 + y / 9.0) +
                                                               double(rng() % 11) - 5.0),
                                                   0L, 255L));
    BasicGreedyModel model(im);
    CHECK(fast_greedy(im, model, true, 120) == reference_greedy(im, model, true, 120));
}
