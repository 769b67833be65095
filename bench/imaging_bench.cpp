// Imaging benchmark (issue 4): the two image-analysis stages the methods run on every input.
//
//   edges: detect_edges -> trace_polylines -> Douglas-Peucker on bull (1024x768; half-pixel grid
//          2047x1535), beta 0.028, r 0.4, eps 2, l 5 (thesis Table 3.2 at 1%). Target <= 60 ms.
//   ed:    select_points with the exact-count search, K = 1% of the pixels (7864 on bull), on the
//          ED density (MMSODD, 3rd-order binomial, gamma 1; computed once, not timed), no startup
//          handling as in ED. Target <= 30 ms. The mirror mode of ERDED is timed too (no target).
// Each case runs RUNS times (argument 2, default 7); the median thread CPU time is printed, which
// is steadier than wall time on a shared machine. Argument 3 selects a case (edges|ed|mirror|all)
// so callgrind can count one of them.
// Build: g++ -O2 -std=c++17 -I. bench/imaging_bench.cpp build/liberd.a -o build/imaging_bench
// Run:   build/imaging_bench ../shared/images/bull.pgm [RUNS] [CASE]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "algorithms/imaging/douglas_peucker.h"
#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/imaging/edge_polylines.h"

using namespace erd;

namespace {

// Minimal binary PGM (P5, 8-bit) reader: the library has no file access and the bench links
// only liberd.a.
bool read_pgm(const char* path, Image* im) {
    FILE* f = std::fopen(path, "rb");
    if (!f) return false;
    char magic[3] = {0};
    int w = 0, h = 0, mv = 0;
    bool ok = std::fscanf(f, "%2s %d %d %d", magic, &w, &h, &mv) == 4 && std::strcmp(magic, "P5") == 0 && w > 0 &&
              h > 0 && mv > 0 && mv < 256;
    if (ok) {
        std::fgetc(f);
        *im = Image(w, h, std::uint32_t(mv));
        std::vector<unsigned char> b(std::size_t(w) * std::size_t(h));
        ok = std::fread(b.data(), 1, b.size(), f) == b.size();
        for (std::size_t i = 0; i < b.size(); ++i) im->samples[i] = b[i];
    }
    std::fclose(f);
    return ok;
}

double cpu_ms() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: imaging_bench BULL.pgm [RUNS] [edges|ed|mirror|all]\n");
        return 2;
    }
    Image im;
    if (!read_pgm(argv[1], &im)) {
        std::fprintf(stderr, "imaging_bench: cannot read %s as an 8-bit P5 PGM\n", argv[1]);
        return 1;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 7;
    const std::string which = argc > 3 ? argv[3] : "all";

    if (which == "edges" || which == "all") {
        EdgePolylineParams p;
        p.canny.beta = 0.028;
        p.canny.r = 0.4;
        p.epsilon = 1;  // pixel
        p.min_length = 5;
        std::vector<double> t;
        EdgePolylineResult out;
        for (int i = 0; i < runs; ++i) {
            const double t0 = cpu_ms();
            if (!edge_polylines(im, p, &out)) return 1;
            t.push_back(cpu_ms() - t0);
        }
        const std::vector<Polyline>& lines = out.polylines;
        const CannyStats& st = out.stats;
        std::size_t pts = 0;
        for (const Polyline& l : lines) pts += l.size();
        std::printf("%-34s cpu %7.1f ms (median of %d)  target %3d ms %-4s  %zu edge points, %zu polylines, %zu vertices\n",
                    "imaging edges->polylines bull", median(t), runs, 60, median(t) <= 60 ? "ok" : "over",
                    st.edge_points, lines.size(), pts);
    }
    if (which == "edges") return 0;  // the density below is not part of the edges case
    const Grid<double> density = ed_density(mmsodd(to_grid(im), 3), 1.0);
    const std::size_t k = std::size_t(im.width) * std::size_t(im.height) / 100;
    for (const char* mode : {"ed", "mirror"}) {
        if (which != mode && which != "all") continue;
        DiffusionParams dp;
        dp.startup = std::strcmp(mode, "ed") == 0 ? Startup::none : Startup::mirror;
        std::vector<double> t;
        DiffusionResult r;
        for (int i = 0; i < runs; ++i) {
            const double t0 = cpu_ms();
            if (!select_points(density, k, dp, &r)) return 1;
            t.push_back(cpu_ms() - t0);
        }
        const bool target = dp.startup == Startup::none;
        std::printf("%-34s cpu %7.1f ms (median of %d)  target %3s ms %-4s  K %zu, got %zu, %d passes\n",
                    target ? "imaging error diffusion bull 1%" : "imaging error diffusion mirror 1%", median(t), runs,
                    target ? "30" : "-", target ? (median(t) <= 30 ? "ok" : "over") : "", k, r.points.size(), r.passes);
    }
    return 0;
}
