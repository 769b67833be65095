// libFuzzer target: erd's Cdt against CGAL's Constrained_Delaunay_triangulation_2 (issue 49), the
// comparison of tests/cgal/cgal_diff.h after every operation (vertex sets, constrained edges and
// erd's constraint policy, the Delaunay subdivision, triangle counts, exact Delaunay checks).
//
// The input is a program on a small lattice (ties everywhere), optionally scaled:
//   byte 0, 1: rectangle max_x, max_y (1..32)
//   byte 2:    bit 0: the CDT of the hole for every removal (else erd's default methods);
//              bit 1: every coordinate times 2^18 plus a small offset (the 128-bit in-circle path
//              with near-ties)
//   then per operation one opcode byte and its operand bytes:
//     op % 4 == 0, 1: insert point (x, y)                              2 bytes
//     op % 4 == 2:    insert constraint between vertices (i, j)        2 bytes (indices into the
//                     points inserted so far; crossing pieces are dropped by erd's policy)
//     op % 4 == 3:    remove the vertex at inserted point i            1 byte
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz/fuzz_checks.h"
#include "tests/cgal/cgal_diff.h"
#include "third_party/cgal_glue.h"

using fuzz_checks::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace cgal_diff;
    fuzz_checks::ByteReader in{data, size};
    const std::int32_t gx = std::int32_t(1 + in.byte() % 32), gy = std::int32_t(1 + in.byte() % 32);
    const std::uint32_t mode = in.byte();
    const bool scaled = (mode & 2) != 0;
    const std::int32_t scale = scaled ? (1 << 18) : 1;
    // Scaled: lattice point (x, y) at (x * 2^18 + (x * y) % 3, y * 2^18 + x % 2), inside the
    // rectangle (32 * 2^18 + 3 < 2^24), so most ties break by a unit far from the origin.
    auto map = [&](std::int32_t x, std::int32_t y) {
        if (!scaled) return LatticePoint{x, y};
        return LatticePoint{x * scale + (x * y) % 3 * (x < gx), y * scale + x % 2 * (y < gy)};
    };
    Differential d(gx * scale, gy * scale, (mode & 1) ? 0u : 10u);
    std::vector<LatticePoint> pts;
    for (int ops = 0; ops < 48 && in.more(); ++ops) {
        const std::uint32_t op = in.byte() % 4;
        if (op <= 1) {
            const std::int32_t x = std::int32_t(in.byte() % std::uint32_t(gx + 1)), y = std::int32_t(in.byte() % std::uint32_t(gy + 1));
            const LatticePoint p = map(x, y);
            check(d.insert_point(p).empty());
            pts.push_back(p);
        } else if (op == 2) {
            const std::uint32_t i = in.byte(), j = in.byte();
            if (pts.empty()) continue;
            const LatticePoint a = pts[i % pts.size()], b = pts[j % pts.size()];
            if (d.cdt().locate(a).kind != erd::Location::Kind::on_vertex ||
                d.cdt().locate(b).kind != erd::Location::Kind::on_vertex)
                continue;  // removed meanwhile
            check(d.insert_constraint(a, b).empty());
        } else {
            const std::uint32_t i = in.byte();
            if (pts.empty()) continue;
            bool removed = false;
            check(d.remove(pts[i % pts.size()], &removed).empty());
        }
        check(d.compare().difference.empty());
    }
    return 0;
}
