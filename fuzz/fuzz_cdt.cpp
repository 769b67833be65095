// libFuzzer target for the constrained Delaunay triangulation (kernel/cdt.h).
//
// The input is read as a program on a small lattice (rectangle at most 16x16 in doubled units), so
// collinear, cocircular, duplicate and crossing cases are the common case rather than the rare one:
//   byte 0, 1: rectangle max_x, max_y (1..16)
//   then per operation one opcode byte and its operand bytes:
//     op % 4 == 0, 1: insert point (x, y, hint)            3 bytes
//     op % 4 == 2:    insert constraint (vertex a, b)     2 bytes
//     op % 4 == 3:    insert a point on an existing constrained edge (edge k, position t)  2 bytes
// verify() runs after every operation. At the end, when no crossing constraint was refused, the same
// point set and segments are inserted again in another order (points first, in reverse, then the
// segments in reverse) and with insert_points(); all three canonical forms must agree.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "kernel/cdt.h"
#include "fuzz/fuzz_checks.h"
#include "tests/cdt_util.h"

using fuzz_checks::check;
using cdt_util::constraint_coords;

namespace {

void check_verify(const erd::Cdt& cdt) {
    std::string why;
    check(cdt.verify(&why));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace erd;
    fuzz_checks::ByteReader in{data, size};
    const std::int32_t mx = std::int32_t(1 + in.byte() % 16), my = std::int32_t(1 + in.byte() % 16);
    Cdt cdt;
    check(cdt.reset(mx, my).ok());
    check_verify(cdt);
    std::vector<LatticePoint> points;
    std::vector<std::pair<LatticePoint, LatticePoint>> segments;
    std::vector<std::array<VertInd, 2>> cons;
    bool refused = false;
    for (int ops = 0; ops < 96 && in.more(); ++ops) {
        const std::uint32_t op = in.byte() % 4;
        const std::size_t nf = cdt.face_count();
        if (op <= 1 || op == 3) {
            LatticePoint p{std::int32_t(in.byte() % std::uint32_t(mx + 1)), std::int32_t(in.byte() % std::uint32_t(my + 1))};
            FaceInd hint = noFace;
            if (op == 3) {
                cdt.export_constraints(&cons);
                if (!cons.empty()) {
                    const auto& e = cons[p.x % std::int32_t(cons.size())];
                    const LatticePoint a = cdt.point(e[0]), b = cdt.point(e[1]);
                    const std::int32_t g = std::gcd(std::abs(b.x - a.x), std::abs(b.y - a.y));
                    if (g > 1) {
                        const std::int32_t t = 1 + p.y % (g - 1);
                        p = {a.x + (b.x - a.x) / g * t, a.y + (b.y - a.y) / g * t};
                    }
                }
            } else {
                const std::uint32_t h = in.byte();
                if (h & 1) hint = FaceInd(h >> 1);  // may be out of range: must be ignored
            }
            VertInd v = noVertex;
            check(cdt.insert_point(p, &v, hint).ok());
            check(v < cdt.vertex_count() && cdt.point(v) == p);
            const Location loc = cdt.locate(p);
            check(loc.kind == Location::Kind::on_vertex && loc.vertex == v);
            points.push_back(p);
            const ChangeReport& ch = cdt.changes();
            check(ch.created.size() == ch.destroyed.size() + (cdt.face_count() - nf));
            for (FaceInd f : ch.destroyed) check(f < nf);
            for (FaceInd f : ch.created) check(f < cdt.face_count());
        } else {
            const std::uint32_t n = std::uint32_t(cdt.vertex_count());
            const VertInd a = in.byte() % n, b = in.byte() % n;
            ConstraintReport rep;
            check(cdt.insert_constraint(a, b, &rep).ok());
            check(cdt.face_count() == nf);
            check(rep.pieces == rep.inserted + rep.already + rep.dropped_crossing);
            if (rep.dropped_crossing) refused = true;
            segments.push_back({cdt.point(a), cdt.point(b)});
        }
        check_verify(cdt);
    }
    if (refused) return 0;
    const auto canon = canonical_faces(cdt);
    const auto ccons = constraint_coords(cdt);
    // Another order: points first (reversed), then the segments (reversed).
    Cdt other;
    check(other.reset(mx, my).ok());
    for (std::size_t i = points.size(); i-- > 0;) check(other.insert_point(points[i], nullptr).ok());
    ConstraintReport rep;
    for (std::size_t i = segments.size(); i-- > 0;) {
        const Location a = other.locate(segments[i].first), b = other.locate(segments[i].second);
        check(a.kind == Location::Kind::on_vertex && b.kind == Location::Kind::on_vertex);
        check(other.insert_constraint(b.vertex, a.vertex, &rep).ok());
    }
    check(rep.dropped_crossing == 0);
    check_verify(other);
    check(canonical_faces(other) == canon);
    check(constraint_coords(other) == ccons);
    // And the batch (Hilbert-sorted) insertion of the points.
    Cdt batch;
    check(batch.reset(mx, my).ok());
    check(batch.insert_points(points, nullptr).ok());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Location a = batch.locate(segments[i].first), b = batch.locate(segments[i].second);
        check(batch.insert_constraint(a.vertex, b.vertex, nullptr).ok());
    }
    check_verify(batch);
    check(canonical_faces(batch) == canon);
    return 0;
}
