// Vertex removal beside CGAL (issue 45): erd's Cdt::remove_vertex and CGAL's
// Delaunay_triangulation_2::remove on the same points, in the same order, in one run.
//
// For each size N: N random distinct points of a square of the doubled lattice (side about
// 2 sqrt(N), so a fifth of its points are used and collinear and cocircular neighbours are common),
// triangulated by both (erd: insert_points; CGAL: its spatially sorted range insertion; untimed), then a
// random half of them removed, in the same random order, timed: thread CPU time per removed vertex.
// The two alternate run by run (RUNS runs each, argument 1, default 5) and the medians are printed
// with their ratio (target: erd <= 0.5x CGAL). Argument 2 picks one side (erd|cgal|both) so that
// callgrind can count one phase's instructions:
//   valgrind --tool=callgrind --toggle-collect='*phase_erd*' remove_bench 1 erd 100000
// Argument 3 (optional): one size instead of 100000 and 1000000.
// Build (bench/run.sh does): g++ -O2 -std=c++17 -I. bench/remove_bench.cpp <cgal_glue.o at -O2>
//   build/liberd.a -lgmp -lmpfr
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <unordered_set>
#include <vector>

#include "kernel/cdt.h"
#include "third_party/cgal_glue.h"

using namespace erd;

namespace {

double now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Input {
    std::int32_t side = 0;
    std::vector<LatticePoint> points;  // the 4 corners first, then N distinct inner points
    std::vector<std::size_t> order;    // indices of the points to remove, in removal order
};

Input make_input(std::size_t n, std::uint32_t seed) {
    Input in;
    std::int32_t side = 2;
    while (std::size_t(side) * std::size_t(side) < 5 * n) side *= 2;
    in.side = side;
    std::mt19937 g(seed);
    std::unordered_set<std::uint64_t> used;
    in.points = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    while (in.points.size() < n + 4) {
        const std::int32_t x = std::int32_t(1 + g() % std::uint32_t(side - 1)), y = std::int32_t(1 + g() % std::uint32_t(side - 1));
        if (used.insert(std::uint64_t(x) << 32 | std::uint32_t(y)).second) in.points.push_back({x, y});
    }
    for (std::size_t i = 4; i < in.points.size(); ++i) in.order.push_back(i);
    std::shuffle(in.order.begin(), in.order.end(), g);
    in.order.resize(n / 2);
    return in;
}

__attribute__((noinline)) bool phase_erd_remove(Cdt& cdt, const std::vector<VertInd>& ids, const std::vector<std::size_t>& order) {
    for (const std::size_t i : order)
        if (!cdt.remove_vertex(ids[i]).ok()) return false;
    return true;
}

__attribute__((noinline)) void phase_cgal_remove(cgal_glue::Delaunay& dt, const std::vector<std::size_t>& order) {
    for (const std::size_t i : order) dt.remove(i);
}

// One timed erd run: ns per removed vertex, or -1 on a failure.
double run_erd(const Input& in) {
    Cdt cdt;
    std::vector<VertInd> ids;
    if (!cdt.reset(in.side, in.side).ok() || !cdt.insert_points(in.points, &ids, false).ok()) return -1;
    const double t0 = now_ns();
    if (!phase_erd_remove(cdt, ids, in.order)) return -1;
    const double t = (now_ns() - t0) / double(in.order.size());
    std::string why;
    if (cdt.live_vertex_count() != in.points.size() - in.order.size() || !cdt.verify(&why)) {
        std::fprintf(stderr, "remove_bench: erd's result is wrong: %s\n", why.c_str());
        return -1;
    }
    return t;
}

double run_cgal(const Input& in) {
    cgal_glue::Delaunay dt;
    dt.insert(in.points);
    const double t0 = now_ns();
    phase_cgal_remove(dt, in.order);
    const double t = (now_ns() - t0) / double(in.order.size());
    if (dt.face_count() != 2 * (in.points.size() - in.order.size()) - 2 - 4) {  // 2V - 2 - hull (4)
        std::fprintf(stderr, "remove_bench: CGAL's face count is off\n");
        return -1;
    }
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const std::string which = argc > 2 ? argv[2] : "both";
    std::vector<std::size_t> sizes = {100000, 1000000};
    if (argc > 3) sizes = {std::size_t(std::strtoull(argv[3], nullptr, 10))};
    for (const std::size_t n : sizes) {
        const Input in = make_input(n, 45);
        std::vector<double> te, tc;
        for (int r = 0; r < runs; ++r) {
            if (which != "cgal") te.push_back(run_erd(in));
            if (which != "erd") tc.push_back(run_cgal(in));
            if ((!te.empty() && te.back() < 0) || (!tc.empty() && tc.back() < 0)) return 1;
        }
        const double e = median(te), c = median(tc);
        std::printf("remove %8zu points, %7zu removed (random half, random order): erd %7.1f ns/vertex  CGAL %7.1f ns/vertex",
                    n, in.order.size(), e, c);
        if (e > 0 && c > 0) std::printf("  erd/CGAL %.2fx (target <= 0.5x)", e / c);
        std::printf("\n");
    }
    return 0;
}
