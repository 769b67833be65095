// libFuzzer target for the -t triangulation reader (algorithms/model/model_io.h).
// A refusal is one non-empty line with Code::input; an accepted file has indices in range,
// positive faces, coordinates inside W x H, constraints that are face edges, and survives
// write -> read unchanged. Replay without libFuzzer: fuzz/replay.cpp.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "algorithms/model/model_io.h"
#include "fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 1 << 16) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    erd::Model m;
    erd::Status s = erd::read_triangulation(text, &m);
    if (!fuzz_checks::accepted(s)) return 0;
    fuzz_checks::check_mesh(m);
    for (const auto& c : m.constraints) {
        bool edge = false;
        for (const auto& f : m.faces)
            edge = edge || (std::count(f.begin(), f.end(), c[0]) == 1 && std::count(f.begin(), f.end(), c[1]) == 1);
        if (!edge || c[0] >= c[1]) std::abort();
    }
    std::string out;
    if (!erd::write_triangulation(m, &out).ok()) std::abort();
    erd::Model r;
    if (!erd::read_triangulation(out, &r).ok()) std::abort();
    if (r.vertices != m.vertices || r.faces != m.faces || r.constraints != m.constraints || r.width != m.width ||
        r.height != m.height)
        std::abort();
    return 0;
}
