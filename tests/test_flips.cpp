// Data-dependent flips (algorithms/methods/flips.h), the flip primitive of the kernel, the
// regularised wedge refit (algorithms/methods/wedge_fit.h) and --optimize (optimize.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/flips.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/optimize.h"
#include "algorithms/methods/scaffold.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/erd_model.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"
#include "kernel/cdt.h"
#include "tests/erd_check.h"

using namespace erd;

namespace {

// A smooth ramp with a diagonal step: the Delaunay diagonals ignore the step's direction.
Image ridge(int w, int h) {
    Image im(w, h, 255);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            im.at(x, y) = std::uint16_t((2 * x + y < w ? 40 : 190) + (x + 3 * y) % 23);
    return im;
}

void random_points(Cdt* cdt, int count, std::uint32_t seed) {
    for (int i = 0; i < count; ++i) {
        seed = seed * 1664525u + 1013904223u;
        const LatticePoint p{std::int32_t(2 * ((seed >> 8) % std::uint32_t(cdt->max_x() / 2 + 1))),
                             std::int32_t(2 * ((seed >> 20) % std::uint32_t(cdt->max_y() / 2 + 1)))};
        VertInd v = 0;
        REQUIRE(cdt->insert_point(p, &v).ok());
    }
}

// The mesh the flip and move tests change: a 48 x 40 ridge image's initial ERD mesh with 60 random
// points (seeded) and its wedge values, and the constrained edges it has before.
struct RidgeMesh {
    const Image im = ridge(48, 40);
    Cdt cdt;
    std::vector<std::array<VertInd, 2>> constraints;
    ErdModel model{im, WedgeValueOptions{}};

    explicit RidgeMesh(std::uint32_t seed) {
        InitialMeshOptions mo;
        mo.target = 150;
        InitialMesh mesh;
        REQUIRE(build_initial_mesh(im, mo, &cdt, &mesh).ok());
        random_points(&cdt, 60, seed);
        cdt.export_constraints(&constraints);
        model.assign_all(cdt);
    }

    // What flips and moves keep: a valid topology, the constrained edges, an ERD model of the
    // wedge values.
    void check_kept() const {
        std::string why;
        INFO(why);
        CHECK(cdt.verify_topology(&why));
        std::vector<std::array<VertInd, 2>> after;
        cdt.export_constraints(&after);
        CHECK(after == constraints);
        Model m;
        model.to_model(cdt, im.width, im.height, im.maxval, &m);
        test::check_model(m);  // the flipped-faces path of check_model
    }
};

}  // namespace

TEST_CASE("kernel flip_edge: unconstrained convex edges only; a flip twice is the identity", "[flips][kernel]") {
    Cdt cdt;
    REQUIRE(cdt.reset(40, 30).ok());
    random_points(&cdt, 12, 7);
    VertInd a = 0, b = 0;
    REQUIRE(cdt.insert_point({4, 4}, &a).ok());
    REQUIRE(cdt.insert_point({34, 26}, &b).ok());
    REQUIRE(cdt.insert_constraint(a, b).ok());
    const auto before = canonical_faces(cdt);
    std::size_t flipped = 0;
    for (EdgeInd e = 0; e < 3 * cdt.face_count(); ++e) {
        if (cdt.constrained(e) || cdt.on_hull(e)) {
            CHECK(!cdt.can_flip(e));
            CHECK(cdt.flip_edge(e) == noEdge);
            continue;
        }
        if (!cdt.can_flip(e)) continue;
        const EdgeInd d = cdt.flip_edge(e);
        REQUIRE(d != noEdge);
        std::string why;
        INFO(why);
        REQUIRE(cdt.verify_topology(&why));
        REQUIRE(cdt.can_flip(d));
        REQUIRE(cdt.flip_edge(d) != noEdge);
        ++flipped;
    }
    CHECK(flipped > 10);
    CHECK(canonical_faces(cdt) == before);  // a flip of a flip restores the faces
    std::string why;
    CHECK(cdt.verify(&why));
}

TEST_CASE("data-dependent flips lower the squared error and keep constraints and wedges", "[flips]") {
    RidgeMesh r(3);
    FlipStats fs;
    improve_by_flips(&r.cdt, r.im, r.model, 100000, &fs);
    CHECK(fs.flips > 0);
    CHECK(fs.sse_after < fs.sse_before);
    r.check_kept();
}

TEST_CASE("kernel move_vertex: free interior vertices only, inside their star", "[flips][kernel]") {
    Cdt cdt;
    REQUIRE(cdt.reset(40, 40).ok());
    VertInd v = 0, w = 0;
    REQUIRE(cdt.insert_point(LatticePoint{20, 20}, &v).ok());
    REQUIRE(cdt.insert_point(LatticePoint{30, 30}, &w).ok());
    CHECK(!cdt.can_move(0, LatticePoint{2, 2}));     // a corner
    CHECK(!cdt.can_move(v, LatticePoint{30, 30}));   // onto a vertex
    CHECK(!cdt.can_move(v, LatticePoint{0, 20}));    // onto the boundary
    CHECK(!cdt.can_move(v, LatticePoint{34, 34}));   // out of its star
    REQUIRE(cdt.can_move(v, LatticePoint{22, 18}));
    REQUIRE(cdt.move_vertex(v, LatticePoint{22, 18}));
    CHECK(cdt.point(v) == LatticePoint{22, 18});
    std::string why;
    INFO(why);
    CHECK(cdt.verify_topology(&why));
    VertInd a = 0, b = 0;
    REQUIRE(cdt.insert_point(LatticePoint{10, 30}, &a).ok());
    REQUIRE(cdt.insert_point(LatticePoint{30, 10}, &b).ok());
    REQUIRE(cdt.insert_constraint(a, b).ok());
    const EdgeInd e = cdt.find_edge(a, b);
    if (e != noEdge) CHECK(!cdt.can_move(a, LatticePoint{12, 30}));  // a vertex of a constrained edge
    CHECK(cdt.verify_topology(&why));
}

TEST_CASE("vertex moves lower the squared error and keep the count, constraints and topology", "[flips]") {
    RidgeMesh r(5);
    Cdt& cdt = r.cdt;
    const Image& im = r.im;
    ErdModel& model = r.model;
    const std::size_t n = cdt.vertex_count();
    MeshSystems systems;
    WedgeFitOptions o;
    WedgeFitStats before;
    fit_wedge_values(cdt, im, o, &model, &before, nullptr, {}, &systems);
    REQUIRE(systems.matches(cdt));
    MoveStats ms;
    improve_by_moves(&cdt, im, model, 2, 0.0, &systems, &ms);
    CHECK(ms.moves > 0);
    CHECK(ms.tested >= ms.moves);
    CHECK(cdt.vertex_count() == n);
    // The kept systems are those of the moved mesh: a refit from them equals a fresh one.
    ErdModel fresh = model;
    WedgeFitStats kept_stats, fresh_stats;
    fit_wedge_values(cdt, im, o, &model, &kept_stats, nullptr, {}, &systems);
    fit_wedge_values(cdt, im, o, &fresh, &fresh_stats, nullptr);
    CHECK(kept_stats.sse_after == fresh_stats.sse_after);
    CHECK(kept_stats.sse_after < before.sse_after);
    for (std::size_t i = 0; i < model.entry_count(); ++i) CHECK(model.entry_value(i) == fresh.entry_value(i));
    r.check_kept();
}

namespace {

// The squared error of channels models[c] on planes[c] over every face, from the face systems.
double channels_sse(const Cdt& cdt, const std::vector<const Image*>& planes, const std::vector<ErdModel*>& models) {
    double total = 0;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        if (!cdt.face_live(f)) continue;
        const EdgeInd e = 3 * f;
        for (std::size_t c = 0; c < planes.size(); ++c) {
            const FaceSystem fs = face_system(*planes[c], RasterDomain{cdt.max_x(), cdt.max_y()}, cdt.point(cdt.org(e)),
                                              cdt.point(cdt.org(e + 1)), cdt.point(cdt.org(e + 2)));
            total += fs.sse(models[c]->corner_value(cdt, e), models[c]->corner_value(cdt, e + 1),
                            models[c]->corner_value(cdt, e + 2));
        }
    }
    return total;
}

}  // namespace

TEST_CASE("colour vertex moves lower the channels' summed error; one channel moves as the gray moves", "[flips]") {
    SECTION("three channels") {
        RidgeMesh r(5);
        Image g = r.im, b = r.im;  // two more planes: the ramp reversed, and a vertical ramp
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x) {
                g.at(x, y) = std::uint16_t(255 - r.im.at(x, y));
                b.at(x, y) = std::uint16_t((r.im.at(x, y) + 5 * y) % 256);
            }
        const std::vector<const Image*> planes{&r.im, &g, &b};
        ErdModel mg(g, WedgeValueOptions{}), mb(b, WedgeValueOptions{});
        mg.assign_all(r.cdt);
        mb.assign_all(r.cdt);
        const std::vector<ErdModel*> models{&r.model, &mg, &mb};
        for (std::size_t c = 0; c < 3; ++c) fit_wedge_values(r.cdt, *planes[c], WedgeFitOptions{}, models[c], nullptr);
        const std::size_t n = r.cdt.vertex_count();
        const double before = channels_sse(r.cdt, planes, models);
        MoveStats ms;
        improve_by_moves(&r.cdt, planes, {models.begin(), models.end()}, 2, 0.0, &ms);
        CHECK(ms.moves > 0);
        CHECK(ms.tested >= ms.moves);
        CHECK(r.cdt.vertex_count() == n);
        CHECK(channels_sse(r.cdt, planes, models) < before);
        r.check_kept();
    }
    SECTION("one channel: the same moves as the gray function's") {
        RidgeMesh a(7), b(7);
        MeshSystems systems;
        fit_wedge_values(a.cdt, a.im, WedgeFitOptions{}, &a.model, nullptr, nullptr, {}, &systems);
        fit_wedge_values(b.cdt, b.im, WedgeFitOptions{}, &b.model, nullptr);
        MoveStats ma, mb;
        improve_by_moves(&a.cdt, a.im, a.model, 2, 0.0, &systems, &ma);
        improve_by_moves(&b.cdt, {&b.im}, {&b.model}, 2, 0.0, &mb);
        CHECK(ma.moves > 0);
        CHECK(ma.moves == mb.moves);
        CHECK(ma.tested == mb.tested);
        for (VertInd v = 0; v < a.cdt.vertex_count(); ++v) CHECK(a.cdt.point(v) == b.cdt.point(v));
    }
}

namespace {

// RidgeMesh with two more planes (the ramp reversed, and a vertical ramp) and their models.
struct ColourRidge {
    RidgeMesh r;
    Image g = r.im, b = r.im;
    std::unique_ptr<ErdModel> mg, mb;
    explicit ColourRidge(std::uint32_t seed) : r(seed) {
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x) {
                g.at(x, y) = std::uint16_t(255 - r.im.at(x, y));
                b.at(x, y) = std::uint16_t((r.im.at(x, y) + 5 * y) % 256);
            }
        mg = std::make_unique<ErdModel>(g, WedgeValueOptions{});
        mb = std::make_unique<ErdModel>(b, WedgeValueOptions{});
        mg->assign_all(r.cdt);
        mb->assign_all(r.cdt);
    }
    std::vector<const Image*> planes() const { return {&r.im, &g, &b}; }
    std::vector<ErdModel*> models() { return {&r.model, mg.get(), mb.get()}; }
};

bool same_system(const FaceSystem& a, const FaceSystem& b) {
    for (int j = 0; j < 6; ++j)
        if (a.g[j] != b.g[j]) return false;
    return a.h[0] == b.h[0] && a.h[1] == b.h[1] && a.h[2] == b.h[2] && a.bb == b.bb && a.lo == b.lo && a.hi == b.hi &&
           a.owns == b.owns;
}

}  // namespace

TEST_CASE("colour face systems: one pass is each channel's own, and kept ones refit and move as fresh ones", "[flips]") {
    ColourRidge a(11), b(11);
    const std::vector<const Image*> planes = a.planes();
    const Cdt& cdt = a.r.cdt;
    const RasterDomain domain{cdt.max_x(), cdt.max_y()};
    std::size_t owning = 0;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        const EdgeInd e = 3 * f;
        const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
        FaceSystem three[3];
        face_systems3(planes.data(), domain, p0, p1, p2, three);
        for (int c = 0; c < 3; ++c) CHECK(same_system(three[c], face_system(*planes[std::size_t(c)], domain, p0, p1, p2)));
        owning += three[0].owns ? 1 : 0;
    }
    CHECK(owning > 100);
    // a: systems kept from the refit through the moves to the next refit; b: made afresh each time.
    ColourSystems kept;
    std::vector<WedgeFitStats> sa, sb;
    const std::vector<ErdModel*> ma = a.models(), mb = b.models();
    fit_wedge_values(a.r.cdt, planes, WedgeFitOptions{}, ma, &sa, nullptr, {}, &kept);
    fit_wedge_values(b.r.cdt, b.planes(), WedgeFitOptions{}, mb, &sb);
    MoveStats va, vb;
    improve_by_moves(&a.r.cdt, planes, {ma.begin(), ma.end()}, 2, 0.0, &va, &kept);
    improve_by_moves(&b.r.cdt, b.planes(), {mb.begin(), mb.end()}, 2, 0.0, &vb);
    CHECK(va.moves > 0);
    CHECK(va.moves == vb.moves);
    CHECK(va.tested == vb.tested);
    fit_wedge_values(a.r.cdt, planes, WedgeFitOptions{}, ma, &sa, nullptr, {}, &kept);
    fit_wedge_values(b.r.cdt, b.planes(), WedgeFitOptions{}, mb, &sb);
    for (std::size_t c = 0; c < 3; ++c) {
        CHECK(sa[c].sse_after == sb[c].sse_after);
        for (std::size_t i = 0; i < ma[c]->entry_count(); ++i) CHECK(ma[c]->entry_value(i) == mb[c]->entry_value(i));
    }
    for (VertInd v = 0; v < a.r.cdt.vertex_count(); ++v) CHECK(a.r.cdt.point(v) == b.r.cdt.point(v));
    // Kept systems are refused for a face whose corners changed.
    std::size_t found = 0;
    FaceSystem fs[3];
    for (FaceInd f = 0; f < a.r.cdt.face_count(); ++f) found += kept.find(a.r.cdt, f, fs) ? 1 : 0;
    CHECK(found == a.r.cdt.face_count());  // the refit after the moves made the changed ones again
    a.r.check_kept();
}

TEST_CASE("rounds of moves go coarse to fine: one pixel, then half a pixel", "[flips]") {
    // Displacements of the vertices after `moves` rounds (doubled units): round 1 steps 2, round 2
    // steps 1, so an odd component shows a second-round move and moves 1 leaves every one even.
    auto displacements = [&](int moves) {
        RidgeMesh r(5);
        Cdt& cdt = r.cdt;
        const Image& im = r.im;
        ErdModel& model = r.model;
        std::vector<LatticePoint> before;
        for (VertInd v = 0; v < cdt.vertex_count(); ++v) before.push_back(cdt.point(v));
        GenerateOptions o;
        o.flips = 2;
        o.moves = moves;
        o.move_min_gain = 0;
        MeshSystems systems;
        WedgeFitStats st;
        fit_wedge_values(cdt, im, wedge_fit_options(o), &model, &st, nullptr, {}, &systems);
        optimize_by_flips(&cdt, im, o, &model, nullptr, &st, &systems);
        std::string why;
        INFO(why);
        CHECK(cdt.verify_topology(&why));
        REQUIRE(cdt.vertex_count() == before.size());
        std::vector<LatticePoint> d;
        for (VertInd v = 0; v < cdt.vertex_count(); ++v)
            d.push_back({cdt.point(v).x - before[v].x, cdt.point(v).y - before[v].y});
        return d;
    };
    int odd = 0, moved = 0;
    for (const LatticePoint& d : displacements(2)) {
        CHECK(std::abs(d.x) <= 3);
        CHECK(std::abs(d.y) <= 3);
        odd += (d.x % 2 != 0 || d.y % 2 != 0);
        moved += (d.x != 0 || d.y != 0);
    }
    CHECK(moved > 0);
    CHECK(odd > 0);
    for (const LatticePoint& d : displacements(1)) {
        CHECK(d.x % 2 == 0);
        CHECK(d.y % 2 == 0);
        CHECK(std::abs(d.x) <= 2);
        CHECK(std::abs(d.y) <= 2);
    }
}

TEST_CASE("regularised refit: values stay within their pixels' range and near a weakly supported line-search value",
          "[flips][erd]") {
    // A step image without constraints: plain least squares overshoots the step (values above
    // the bright side's 200 or below the dark side's 20); the support bounds forbid it.
    Image im(40, 30, 255);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) im.at(x, y) = std::uint16_t(x + y / 3 < 21 ? 20 : 200);
    Cdt cdt;
    REQUIRE(cdt.reset(78, 58).ok());
    random_points(&cdt, 40, 11);
    for (double bounds : {-1.0, 0.0}) {
        ErdModel model(im, WedgeValueOptions{});
        model.assign_all(cdt);
        WedgeFitOptions o;
        o.iterations = 30;
        o.support_bounds = bounds;
        fit_wedge_values(cdt, im, o, &model, nullptr);
        double lo = 1e9, hi = -1e9;
        for (std::size_t i = 0; i < model.entry_count(); ++i) {
            lo = std::min(lo, model.entry_value(i));
            hi = std::max(hi, model.entry_value(i));
        }
        INFO("bounds " << bounds << ": values in [" << lo << ", " << hi << "]");
        if (bounds < 0) CHECK((lo < 19.5 || hi > 200.5));  // the overshoot the bounds remove
        else CHECK((lo >= 20.0 && hi <= 200.0));
    }
    // The prior: a huge weight keeps every value at its line-search value.
    ErdModel model(im, WedgeValueOptions{});
    model.assign_all(cdt);
    std::vector<double> start;
    for (std::size_t i = 0; i < model.entry_count(); ++i) start.push_back(model.entry_value(i));
    WedgeFitOptions o;
    o.prior_weight = 1e9;
    fit_wedge_values(cdt, im, o, &model, nullptr);
    for (std::size_t i = 0; i < model.entry_count(); ++i) CHECK(model.entry_value(i) == Approx(start[i]).margin(1e-3));
}

TEST_CASE("gpi and ed --optimize: same points, exactly N, a better PSNR", "[flips][methods]") {
    const Image im = ridge(64, 48);
    for (const char* name : {"gpi", "ed"}) {
        INFO(name);
        const MethodInfo* m = find_method(name);
        REQUIRE(m != nullptr);
        GenerateOptions o;
        o.density = 4;
        o.density_given = true;
        GenerateResult plain, opt;
        REQUIRE(m->run(im, o, &plain).ok());
        o.optimize = true;
        REQUIRE(m->run(im, o, &opt).ok());
        CHECK(opt.achieved == opt.requested);
        CHECK(opt.model.vertices == plain.model.vertices);
        Image a, b;
        double pa = 0, pb = 0;
        REQUIRE(reconstruct(plain.model, false, &a).ok());
        REQUIRE(reconstruct(opt.model, false, &b).ok());
        REQUIRE(psnr(im, a, &pa).ok());
        REQUIRE(psnr(im, b, &pb).ok());
        CHECK(pb > pa + 0.5);
    }
}
