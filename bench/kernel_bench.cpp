// Kernel benchmark: the constrained Delaunay triangulation on the doubled lattice of a 512x512 image.
//
// 26,214 random distinct points of the 1023x1023 lattice (doubled coordinates 0..1022), then
//   batch:       insert_points (Hilbert order, each walk starting at the previous point), without
//                the change report (insert_points(pts, nullptr, false))
//   random:      insert_point one by one in random order, walking from the previous point
//   constraints: 500 segments of length ~30 between existing vertices of the random-order mesh
// Each phase is repeated RUNS times (argument 1, default 7) and the median of the thread CPU time is
// printed. Argument 2
// selects one phase (batch|random|constraints|all) so callgrind can count its instructions:
//   valgrind --tool=callgrind --toggle-collect='phase_*' kernel_bench 1 batch
// Build: g++ -O2 -std=c++17 -I. bench/kernel_bench.cpp build/liberd.a -o build/kernel_bench
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kernel/cdt.h"

using namespace erd;

namespace {

constexpr int kSide = 1022;      // doubled lattice of a 512x512 image: 0..1022
constexpr std::size_t kPoints = 26214;
constexpr int kConstraints = 500;

std::vector<LatticePoint> make_points(std::uint32_t seed) {
    std::mt19937 g(seed);
    std::vector<std::uint8_t> used(std::size_t(kSide + 1) * (kSide + 1), 0);
    std::vector<LatticePoint> pts;
    while (pts.size() < kPoints) {
        const int x = int(g() % (kSide + 1)), y = int(g() % (kSide + 1));
        std::uint8_t& u = used[std::size_t(y) * (kSide + 1) + std::size_t(x)];
        if (u) continue;
        u = 1;
        pts.push_back({x, y});
    }
    return pts;
}

// CPU time of this thread: on a shared machine wall time mostly measures the other processes.
double now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

__attribute__((noinline)) bool phase_batch(Cdt& cdt, const std::vector<LatticePoint>& pts) {
    if (!cdt.reset(kSide, kSide).ok()) return false;
    return cdt.insert_points(pts, nullptr, false).ok();  // no change report: nobody reads it here
}

__attribute__((noinline)) bool phase_random(Cdt& cdt, const std::vector<LatticePoint>& pts) {
    if (!cdt.reset(kSide, kSide).ok()) return false;
    cdt.reserve(pts.size());
    for (const LatticePoint& p : pts)
        if (!cdt.insert_point(p, nullptr).ok()) return false;
    return true;
}

__attribute__((noinline)) bool phase_constraints(Cdt& cdt, const std::vector<std::pair<VertInd, VertInd>>& segs,
                                                 ConstraintReport* rep) {
    for (const auto& s : segs)
        if (!cdt.insert_constraint(s.first, s.second, rep).ok()) return false;
    return true;
}

// Segments of length 28..32 between random vertices (found with a coarse grid).
std::vector<std::pair<VertInd, VertInd>> make_segments(const Cdt& cdt, std::uint32_t seed) {
    const int cell = 32, cells = kSide / cell + 1;
    std::vector<std::vector<VertInd>> grid(std::size_t(cells) * cells);
    for (VertInd v = 0; v < cdt.vertex_count(); ++v) {
        const LatticePoint p = cdt.point(v);
        grid[std::size_t(p.y / cell) * cells + std::size_t(p.x / cell)].push_back(v);
    }
    std::mt19937 g(seed);
    std::vector<std::pair<VertInd, VertInd>> segs;
    while (segs.size() < std::size_t(kConstraints)) {
        const VertInd a = VertInd(4 + g() % (cdt.vertex_count() - 4));
        const LatticePoint pa = cdt.point(a);
        std::vector<VertInd> cand;
        for (int cy = std::max(0, pa.y / cell - 1); cy <= std::min(cells - 1, pa.y / cell + 1); ++cy)
            for (int cx = std::max(0, pa.x / cell - 1); cx <= std::min(cells - 1, pa.x / cell + 1); ++cx)
                for (VertInd b : grid[std::size_t(cy) * cells + std::size_t(cx)]) {
                    const LatticePoint pb = cdt.point(b);
                    const std::int64_t d2 = std::int64_t(pb.x - pa.x) * (pb.x - pa.x) + std::int64_t(pb.y - pa.y) * (pb.y - pa.y);
                    if (d2 >= 28 * 28 && d2 <= 32 * 32) cand.push_back(b);
                }
        if (cand.empty()) continue;
        segs.push_back({a, cand[g() % cand.size()]});
    }
    return segs;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const std::string which = argc > 2 ? argv[2] : "all";
    const std::vector<LatticePoint> pts = make_points(2024);
    std::vector<LatticePoint> shuffled = pts;  // make_points is already in random order
    std::vector<double> t_batch, t_random, t_cons;
    ConstraintReport rep;
    std::size_t faces = 0;
    for (int r = 0; r < runs; ++r) {
        Cdt cdt;
        if (which == "all" || which == "batch") {
            const double t0 = now_ns();
            if (!phase_batch(cdt, pts)) return 1;
            t_batch.push_back((now_ns() - t0) / double(kPoints));
            faces = cdt.face_count();
        }
        if (which == "all" || which == "random" || which == "constraints") {
            Cdt cr;
            const double t0 = now_ns();
            if (!phase_random(cr, shuffled)) return 1;
            if (which != "constraints") t_random.push_back((now_ns() - t0) / double(kPoints));
            if (which == "all" || which == "constraints") {
                const auto segs = make_segments(cr, 99);
                rep = ConstraintReport{};
                const double t1 = now_ns();
                if (!phase_constraints(cr, segs, &rep)) return 1;
                t_cons.push_back((now_ns() - t1) / 1000.0 / double(kConstraints));
                std::string why;
                if (!cr.verify(&why)) {
                    std::fprintf(stderr, "kernel_bench: verify failed: %s\n", why.c_str());
                    return 1;
                }
            }
        }
    }
    std::printf("kernel_bench: %zu points, %d runs, %zu faces\n", kPoints, runs, faces);
    if (!t_batch.empty()) std::printf("  batch (Hilbert, walk)        %8.1f ns/point  (target <= 300)\n", median(t_batch));
    if (!t_random.empty()) std::printf("  one by one, random order     %8.1f ns/point  (target < 2000)\n", median(t_random));
    if (!t_cons.empty())
        std::printf("  500 constraints, length ~30  %8.2f us each   (target < 5; pieces %u, inserted %u, crossing dropped %u)\n",
                    median(t_cons), rep.pieces, rep.inserted, rep.dropped_crossing);
    return 0;
}
