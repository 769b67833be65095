// Decode time of .erdz files, in process: file bytes -> Model and its adjacency
// (decode_erdz_topology, as erd reconstruct reads a file), then -> image by
// point evaluation and by the model's own reconstruction (4x4 supersampled for a soft-edged ERD
// model, else the same point evaluation). Medians of N runs of each, and the best run (on a
// shared machine the best is the closest to the unloaded cost).
// Usage: erdz_decode_bench [-j THREADS] N FILE.erdz...   (THREADS for the reconstruction, as
// erd reconstruct -j: default 1, 0 = one per processor, the CLI's default)
// Prints per file: "FILE W H decode MED BEST  +point MED BEST  +own MED BEST" (ms).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/model/reconstruct.h"

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Times {
    std::vector<double> v;
    double median() {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    }
    double best() const { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
};

}  // namespace

int main(int argc, char** argv) {
    int threads = 1;
    if (argc > 2 && std::string(argv[1]) == "-j") {
        threads = std::atoi(argv[2]);
        argv += 2, argc -= 2;
    }
    if (argc < 3) {
        std::fprintf(stderr, "usage: erdz_decode_bench [-j THREADS] N FILE.erdz...\n");
        return 2;
    }
    const int n = std::max(1, std::atoi(argv[1]));
    for (int a = 2; a < argc; ++a) {
        std::ifstream f(argv[a], std::ios::binary);
        std::stringstream ss;
        ss << f.rdbuf();
        const std::string bytes = ss.str();
        Times decode, point, own;
        erd::Model m;
        for (int i = 0; i < n; ++i) {
            for (int mode = 0; mode < 3; ++mode) {
                const auto t0 = std::chrono::steady_clock::now();
                erd::ModelTopology topo;
                erd::Status st = erd::decode_erdz_topology(bytes, &m, &topo);
                erd::Image im;
                if (st && mode > 0) st = erd::reconstruct(m, topo, mode == 2 && erd::supersampled(m), &im, {}, threads);
                const double t = ms_since(t0);
                if (!st) {
                    std::fprintf(stderr, "%s: %s\n", argv[a], st.message.c_str());
                    return 1;
                }
                (mode == 0 ? decode : mode == 1 ? point : own).v.push_back(t);
            }
        }
        std::printf("%s %d %d decode %.2f %.2f  +point %.2f %.2f  +own %.2f %.2f\n", argv[a], m.width, m.height, decode.median(),
                    decode.best(), point.median(), point.best(), own.median(), own.best());
    }
    return 0;
}
