// ED and GPI, the methods of the basic model: exact counts, valid Delaunay meshes, vertex values
// equal to the samples, early stop on planar images, determinism, the greedy loop's contract, and
// the thesis images. (Against a reference loop: test_greedy.cpp; CLI: test_generate_cli.cpp.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/methods/ed.h"
#include "algorithms/methods/gpi.h"
#include "algorithms/methods/greedy.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/scaffold.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "kernel/cdt.h"
#include "tests/thesis_cases.h"
#include "tests/test_greedy_util.h"
#include "tests/test_rounding_util.h"

using namespace erd;

namespace {

// A smooth bump, a vertical step and mild noise: nothing special about any pixel.
Image synthetic(int w, int h, unsigned seed) {
    Image im(w, h, 255);
    std::mt19937 rng(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double v = 90.0 + 60.0 * std::sin(x / 5.0) * std::cos(y / 7.0) + (x > w / 2 ? 50.0 : 0.0) +
                       double(rng() % 9) - 4.0;
            im.at(x, y) = std::uint16_t(std::clamp(std::lround(v), 0L, 255L));
        }
    return im;
}

// The model must be THE Delaunay triangulation of its vertices (the kernel's tie rule makes it
// unique): rebuild it from the points alone and compare canonical faces; verify() the rebuild.
void require_delaunay(const Model& m) {
    Cdt cdt;
    REQUIRE(cdt.reset(2 * (m.width - 1), 2 * (m.height - 1)).ok());
    std::vector<LatticePoint> pts;
    for (LatticePoint p : m.vertices) {
        bool corner = (p.x == 0 || p.x == 2 * (m.width - 1)) && (p.y == 0 || p.y == 2 * (m.height - 1));
        if (!corner) pts.push_back(p);
    }
    std::vector<VertInd> ids;
    REQUIRE(cdt.insert_points(pts, &ids).ok());
    std::string why;
    INFO(why);
    REQUIRE(cdt.verify(&why));
    REQUIRE(cdt.vertex_count() == m.vertices.size());
    auto expected = canonical_faces(cdt);
    std::vector<std::array<std::int32_t, 6>> got;
    for (const auto& f : m.faces) {
        std::array<LatticePoint, 3> q = {m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]};
        // positive orientation as the model promises
        std::int64_t o = orient2d(q[0], q[1], q[2]);
        REQUIRE(o > 0);
        std::size_t first = 0;
        for (std::size_t i = 1; i < 3; ++i)
            if (q[i].y < q[first].y || (q[i].y == q[first].y && q[i].x < q[first].x)) first = i;
        std::array<std::int32_t, 6> c;
        for (std::size_t i = 0; i < 3; ++i) {
            c[2 * i] = q[(first + i) % 3].x;
            c[2 * i + 1] = q[(first + i) % 3].y;
        }
        got.push_back(c);
    }
    std::sort(got.begin(), got.end());
    REQUIRE(got == expected);
}

// Vertex values are the samples, and imgsyn (point reconstruction) gives them back exactly.
void require_samples_at_vertices(const Model& m, const Image& im) {
    REQUIRE(m.values.size() == m.vertices.size());
    Image rec;
    REQUIRE(reconstruct(m, false, &rec).ok());
    REQUIRE(rec.width == im.width);
    REQUIRE(rec.height == im.height);
    for (LatticePoint p : m.vertices) REQUIRE(rec.at(p.x / 2, p.y / 2) == im.at(p.x / 2, p.y / 2));
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        LatticePoint p = m.vertices[i];
        REQUIRE(p.x % 2 == 0);
        REQUIRE(p.y % 2 == 0);
        REQUIRE(m.values[i] == double(im.at(p.x / 2, p.y / 2)));
    }
}

GenerateOptions with_points(std::int64_t n) {
    GenerateOptions o;
    o.points = n;
    return o;
}

}  // namespace

TEST_CASE("target points: density wins, rounds half away, default 3%", "[basic]") {
    GenerateOptions o;
    CHECK(target_points(o, 512, 512) == 7864);
    o.points = 100;
    CHECK(target_points(o, 512, 512) == 100);
    o.density = 1.0;
    o.density_given = true;
    CHECK(target_points(o, 512, 512) == 2621);  // 2621.44
    o.density = 0.125;
    CHECK(target_points(o, 1024, 768) == 983);  // 983.04
    CHECK(check_target(3, 10, 10).code == Code::input);
    CHECK(check_target(101, 10, 10).code == Code::input);
    CHECK(check_target(100, 10, 10).ok());
}

TEST_CASE("registry finds ed and gpi by name", "[basic]") {
    REQUIRE(find_method("ed") != nullptr);
    REQUIRE(find_method("gpi") != nullptr);
    CHECK(find_method("nonesuch") == nullptr);
    std::size_t n = 0;
    const MethodInfo* m = methods(&n);
    REQUIRE(n >= 2);
    CHECK(std::string(m[0].name) == "ed");
}

TEST_CASE("GPI: exact N, Delaunay, sample values at vertices", "[basic]") {
    Image im = synthetic(41, 29, 7);
    for (std::int64_t n : {4, 5, 37, 120, 400}) {
        GenerateResult r;
        REQUIRE(generate_gpi(im, with_points(n), &r).ok());
        CHECK(r.requested == std::size_t(n));
        CHECK(r.achieved == std::size_t(n));
        REQUIRE(r.model.size() == std::size_t(n));
        CHECK(r.model.kind == ModelKind::basic);
        require_delaunay(r.model);
        require_samples_at_vertices(r.model, im);
    }
}

TEST_CASE("GPI: more points never raise the final error", "[basic]") {
    Image im = synthetic(33, 33, 3);
    double prev = 1e300;
    for (std::int64_t n : {10, 40, 160, 640}) {
        BasicGreedyModel model(im);
        Cdt cdt;
        const GreedyStats gs = erd_test::refine_to(im, model, std::size_t(n), &cdt);
        CHECK(gs.stop == GreedyStop::target);
        CHECK(gs.total_squared_error < prev);
        prev = gs.total_squared_error;
    }
}

TEST_CASE("GPI: a planar image stops early with zero error", "[basic]") {
    Image im(30, 20, 255);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 30; ++x) im.at(x, y) = std::uint16_t(10 + 3 * x + 2 * y);  // exact plane
    GenerateResult r;
    REQUIRE(generate_gpi(im, with_points(50), &r).ok());
    CHECK(r.achieved == 4);  // the corners already interpolate the plane everywhere
    CHECK(r.requested == 50);

    Image flat(16, 16, 255);
    std::fill(flat.samples.begin(), flat.samples.end(), std::uint16_t(77));
    REQUIRE(generate_gpi(flat, with_points(20), &r).ok());
    CHECK(r.achieved == 4);
}

TEST_CASE("GPI: --psnr and --max-error stop rules", "[basic]") {
    Image im = synthetic(40, 40, 11);
    BasicGreedyModel model(im);
    // Refinement towards 1600 points (rounded values), which the rule set by `rule` stops first.
    const auto stopped = [&](auto rule, Cdt* cdt) {
        GreedyOptions go;
        go.target_vertices = 1600;
        go.round_values = true;
        rule(go);
        return erd_test::refine_from_corners(im, model, go, cdt);
    };
    Cdt cdt;
    const GreedyStats gs = stopped([](GreedyOptions& go) { go.psnr = 30.0; }, &cdt);
    CHECK(gs.stop == GreedyStop::psnr);
    CHECK(gs.psnr >= 30.0);
    {
        // With rounded values the running total is exact: it is the imgsyn reconstruction's.
        Model m = basic_model(cdt, im);
        Image rec;
        REQUIRE(reconstruct(m, false, &rec).ok());
        CHECK(mse(im, rec) * double(im.pixels()) == gs.total_squared_error);
    }
    CHECK(cdt.vertex_count() < 1600);
    // The incremental total equals a fresh scan: refine again to the same count without the rule.
    Cdt cdt2;
    const GreedyStats gs2 = erd_test::refine_to(im, model, cdt.vertex_count(), &cdt2);
    CHECK(gs2.total_squared_error == gs.total_squared_error);
    CHECK(canonical_faces(cdt2) == canonical_faces(cdt));

    Cdt cdt3;
    const GreedyStats gs3 = stopped([](GreedyOptions& go) { go.max_error = 6.0; }, &cdt3);
    CHECK(gs3.stop == GreedyStop::max_error);
    CHECK(gs3.max_error <= 6.0);

    // --triangles: stops at T or T + 1 triangles (an insertion adds two), before the target.
    for (std::size_t t : {std::size_t(7), std::size_t(100), std::size_t(501)}) {
        Cdt cdt4;
        const GreedyStats gs4 = stopped([t](GreedyOptions& go) { go.max_triangles = t; }, &cdt4);
        CHECK(gs4.stop == GreedyStop::triangles);
        CHECK(cdt4.face_count() >= t);
        CHECK(cdt4.face_count() <= t + 1);
    }
}

TEST_CASE("GPI and ED are deterministic", "[basic]") {
    Image im = synthetic(37, 23, 5);
    for (const char* name : {"gpi", "ed"}) {
        const MethodInfo* m = find_method(name);
        REQUIRE(m);
        GenerateResult a, b;
        REQUIRE(m->run(im, with_points(60), &a).ok());
        REQUIRE(m->run(im, with_points(60), &b).ok());
        CHECK(a.model.vertices == b.model.vertices);
        CHECK(a.model.faces == b.model.faces);
        CHECK(a.model.values == b.model.values);
    }
}

TEST_CASE("ED: exactly N points including the corners, Delaunay", "[basic]") {
    Image im = synthetic(48, 36, 9);
    for (std::int64_t n : {8, 30, 87, 200}) {
        GenerateResult r;
        REQUIRE(generate_ed(im, with_points(n), &r).ok());
        INFO("N = " << n);
        CHECK(r.achieved == std::size_t(n));
        require_delaunay(r.model);
        require_samples_at_vertices(r.model, im);
        int corners = 0;
        for (LatticePoint p : r.model.vertices)
            if ((p.x == 0 || p.x == 94) && (p.y == 0 || p.y == 70)) ++corners;
        CHECK(corners == 4);
    }
}

TEST_CASE("ED on an all-zero image reports the shortfall instead of failing", "[basic]") {
    // (A constant nonzero image still has density along its frame: zero extension.)
    Image flat(20, 20, 255);
    GenerateResult r;
    REQUIRE(generate_ed(flat, with_points(30), &r).ok());
    CHECK(r.requested == 30);
    CHECK(r.achieved == 4);  // the density is zero everywhere: only the corners
    require_delaunay(r.model);
}

TEST_CASE("methods refuse impossible targets and tiny images", "[basic]") {
    Image im = synthetic(10, 10, 1);
    GenerateResult r;
    CHECK(generate_gpi(im, with_points(101), &r).code == Code::input);
    CHECK(generate_ed(im, with_points(3), &r).code == Code::input);
    Image line(1, 10, 255);
    CHECK(generate_gpi(line, with_points(4), &r).code == Code::input);
}

namespace {

// A model for the loop's contract: refuses candidates left of a column (admissible), and shifts
// every plane by a bias that changes at each insertion, marking every face dirty.
class ContractModel : public GreedyModel {
public:
    ContractModel(const Image& im, std::int32_t min_x) : im_(im), min_x_(min_x) {}
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const override {
        LatticePoint p[3];
        double z[3];
        for (int i = 0; i < 3; ++i) {
            p[i] = cdt.point(cdt.face_vertex(f, i));
            z[i] = double(im_.at(p[i].x / 2, p[i].y / 2)) + bias_;
        }
        SpanPlane pl;
        pl.set(p[0], z[0], p[1], z[1], p[2], z[2]);
        return pl;
    }
    Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>* dirty) override {
        ++inserted;
        if (cdt.point(v).x < min_x_) bad_insert = true;
        bias_ = double(inserted % 3);  // every plane moves
        for (FaceInd f = 0; f < FaceInd(cdt.face_count()); ++f) dirty->push_back(f);
        return Status::success();
    }
    bool admissible(const Cdt&, LatticePoint p) const override { return p.x >= min_x_; }

    int inserted = 0;
    bool bad_insert = false;

private:
    const Image& im_;
    std::int32_t min_x_;
    double bias_ = 0.0;
};

// Squared error of the rounded approximation over the whole image, from scratch.
double fresh_total(const Cdt& cdt, const Image& im, const GreedyModel& model) {
    double total = 0.0;
    std::vector<Span> spans;
    const Lattice lat = Lattice::pixels();
    for (FaceInd f = 0; f < FaceInd(cdt.face_count()); ++f) {
        SpanPlane pl = model.face_plane(cdt, f);
        const LatticePoint p[3] = {cdt.point(cdt.face_vertex(f, 0)), cdt.point(cdt.face_vertex(f, 1)),
                                   cdt.point(cdt.face_vertex(f, 2))};
        std::int64_t z[3] = {0, 0, 0};
        bool integers = model.integer_values(cdt, f, z);
        for (std::int64_t zk : z) integers = integers && zk >= 0 && zk <= std::int64_t(im.maxval);
        scan_triangle(lat, RasterDomain{cdt.max_x(), cdt.max_y()}, p[0], p[1], p[2], &spans);
        for (const Span& s : spans) {
            double v = pl.at(lat, s.x_begin, s.y);
            for (std::int32_t x = s.x_begin; x <= s.x_end; ++x, v += pl.step_x(lat)) {
                const double r = erd_test::reference_rounded(integers, p, z, x, s.y, v, im.maxval);
                double e = double(im.at(x, s.y)) - r;
                total += e * e;
            }
        }
    }
    return total;
}

}  // namespace

TEST_CASE("greedy loop: refused candidates are banned, dirty faces are re-scanned", "[basic]") {
    Image im = synthetic(30, 24, 21);
    ContractModel model(im, 30);  // doubled x >= 30: pixel columns 15..29 only
    Cdt cdt;
    const GreedyStats gs = erd_test::refine_to(im, model, 80, &cdt);
    CHECK(gs.stop == GreedyStop::target);
    CHECK(cdt.vertex_count() == 80);
    CHECK(model.inserted == 76);
    CHECK(gs.insertions == 76);
    CHECK_FALSE(model.bad_insert);
    CHECK(gs.banned > 0);
    for (LatticePoint p : cdt.points())
        if (p.x != 0) CHECK(p.x >= 30);
    // The incremental total, with every plane moved at every step, equals a fresh scan.
    CHECK(gs.total_squared_error == fresh_total(cdt, im, model));
    std::string why;
    CHECK(cdt.verify(&why));
}

TEST_CASE("greedy loop: the total squared error of GPI equals a fresh scan", "[basic]") {
    Image im = synthetic(45, 31, 2);
    BasicGreedyModel model(im);
    Cdt cdt;
    const GreedyStats gs = erd_test::refine_to(im, model, 150, &cdt);
    CHECK(gs.total_squared_error == fresh_total(cdt, im, model));
    double mse_v = gs.total_squared_error / double(im.pixels());
    CHECK(gs.psnr == Approx(10.0 * std::log10(255.0 * 255.0 / mse_v)));
}

TEST_CASE("ED on the thesis photos: exactly N points", "[basic]") {
    const char* name = GENERATE("peppers", "lena");
    const double d = GENERATE(0.5, 2.0);
    Image im;
    if (!test::read_thesis_image(name, &im)) return;
    GenerateOptions o;
    o.density = d;
    o.density_given = true;
    GenerateResult r;
    REQUIRE(generate_ed(im, o, &r).ok());
    INFO(name << " " << d << "%");
    CHECK(r.requested == std::size_t(std::llround(d * double(im.pixels()) / 100.0)));
    CHECK(r.achieved == r.requested);
}

TEST_CASE("greedy loop: exact totals on a 16-bit image with values at binade edges and the extremes", "[basic]") {
    // Values cluster around powers of two and touch 0 and maxval (16-bit faces, where RoundedPlane
    // restarts from the exact t most often); the incremental total must still equal a fresh scan
    // with exact integer rounding.
    Image im(40, 33, 65535);
    std::mt19937 rng(77);
    const int edges[] = {1, 2, 128, 256, 1024, 32768, 65535};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const int base = edges[std::size_t((x / 7 + y / 5) % 7)];
            const int v = base + int(rng() % 5) - 2 + (x % 3 == 0 ? 40 * (y % 4) : 0);
            im.at(x, y) = std::uint16_t(std::clamp(v, 0, 65535));
        }
    BasicGreedyModel model(im);
    Cdt cdt;
    const GreedyStats gs = erd_test::refine_to(im, model, 200, &cdt);
    CHECK(cdt.vertex_count() == 200);
    CHECK(gs.total_squared_error > 0.0);
    CHECK(gs.total_squared_error == fresh_total(cdt, im, model));
}

TEST_CASE("ED and GPI on the thesis images at the thesis densities: -t files are Delaunay, vertices reproduced", "[basic][images]") {
    // Issue 5: every generated model's -t file is the Delaunay triangulation of its vertices over
    // the image rectangle, the model has exactly N vertices, and its reconstruction equals the
    // image at every vertex.
    test::for_each_thesis_case({"ed", "gpi"}, [](const Image& im, const GenerateResult& r) {
        CHECK(r.model.size() == r.requested);
        std::string tri;
        REQUIRE(write_triangulation(r.model, &tri).ok());
        Model t;
        REQUIRE(read_triangulation(tri, &t).ok());
        t.width = im.width;
        t.height = im.height;
        REQUIRE(t.vertices == r.model.vertices);
        require_delaunay(t);
        Image rec;
        REQUIRE(reconstruct(r.model, false, &rec).ok());
        for (const LatticePoint p : r.model.vertices)
            REQUIRE(rec.at(p.x / 2, p.y / 2) == im.at(p.x / 2, p.y / 2));
    });
}
