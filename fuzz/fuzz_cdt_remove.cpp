// libFuzzer target for vertex removal (Cdt::remove_vertex) interleaved with insertions and
// constraints. After every operation verify() runs and the triangulation must equal, face for
// face and constrained edge for constrained edge, a fresh build of its live points and constrained
// edges; the change report must describe what changed.
//
// The input is a program on a small lattice, so collinear and cocircular stars are the rule:
//   byte 0, 1: rectangle max_x, max_y (1..16)
//   byte 2:    bits 0-1 the hole method (0: the default, 1: apex scan always, 2: CDT of the hole
//              always, 3: scan up to 4 vertices); bit 2 scales every coordinate by 2^19 (the
//              128-bit predicates; the rectangle stays below kMaxCoord)
//   then per operation one opcode byte and its operand bytes:
//     op % 8 == 0, 1, 2: insert point (x, y)                           2 bytes
//     op % 8 == 3:       insert constraint (vertex a, b)              2 bytes
//     op % 8 == 4:       insert a point on a constrained edge (k, t)   2 bytes
//     op % 8 == 5, 6, 7: remove vertex (index k; a refusal is checked) 1 byte
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kernel/cdt.h"
#include "fuzz/fuzz_checks.h"
#include "tests/cdt_util.h"

using fuzz_checks::check;
using cdt_util::constraint_coords;

namespace {

// verify(), then a fresh build of the live points (in reverse index order, one by one) and of
// the constrained edges must give the same faces and constraints.
void check_fresh(const erd::Cdt& cdt) {
    using namespace erd;
    std::string why;
    check(cdt.verify(&why));
    Cdt f;
    check(f.reset(cdt.max_x(), cdt.max_y()).ok());
    for (VertInd v = VertInd(cdt.vertex_count()); v-- > 4;)
        if (cdt.vertex_live(v)) check(f.insert_point(cdt.point(v), nullptr).ok());
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    for (const auto& e : cons) {
        const Location a = f.locate(cdt.point(e[0])), b = f.locate(cdt.point(e[1]));
        check(a.kind == Location::Kind::on_vertex && b.kind == Location::Kind::on_vertex);
        ConstraintReport rep;
        check(f.insert_constraint(a.vertex, b.vertex, &rep).ok());
        check(rep.dropped_crossing == 0);
    }
    check(f.face_count() == cdt.live_face_count());
    check(canonical_faces(f) == canonical_faces(cdt));
    check(constraint_coords(f) == constraint_coords(cdt));
}

// The change report of the last call, given the live faces before it and which were live.
void check_changes(const erd::Cdt& cdt, std::size_t live_before, const std::vector<std::uint8_t>& was_live) {
    const erd::ChangeReport& ch = cdt.changes();
    check(ch.created.size() + live_before == ch.destroyed.size() + cdt.live_face_count());
    check(std::set<erd::FaceInd>(ch.created.begin(), ch.created.end()).size() == ch.created.size());
    check(std::set<erd::FaceInd>(ch.destroyed.begin(), ch.destroyed.end()).size() == ch.destroyed.size());
    for (erd::FaceInd f : ch.created) check(cdt.face_live(f));
    for (erd::FaceInd f : ch.destroyed) check(f < was_live.size() && was_live[f]);
    for (erd::FaceInd f = 0; f < cdt.face_count(); ++f)  // every slot that came alive is listed
        if (cdt.face_live(f) && (f >= was_live.size() || !was_live[f]))
            check(std::find(ch.created.begin(), ch.created.end(), f) != ch.created.end());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace erd;
    fuzz_checks::ByteReader in{data, size};
    const std::int32_t mx = std::int32_t(1 + in.byte() % 16), my = std::int32_t(1 + in.byte() % 16);
    const std::uint32_t mode = in.byte();
    const std::int32_t scale = (mode & 4) ? (1 << 19) : 1;
    Cdt cdt;
    check(cdt.reset(mx * scale, my * scale).ok());
    static constexpr std::uint32_t kLimits[4] = {10, 0xFFFFFFFFu, 0, 4};
    if ((mode & 3) != 0) cdt.set_removal_scan_limit(kLimits[mode & 3]);
    std::vector<std::array<VertInd, 2>> cons;
    std::vector<std::uint8_t> was_live;
    for (int ops = 0; ops < 64 && in.more(); ++ops) {
        const std::uint32_t op = in.byte() % 8;
        const std::size_t live_before = cdt.live_face_count();
        was_live.assign(cdt.face_count(), 0);
        for (FaceInd f = 0; f < cdt.face_count(); ++f) was_live[f] = cdt.face_live(f);
        if (op <= 2 || op == 4) {
            LatticePoint p{std::int32_t(in.byte() % std::uint32_t(mx + 1)), std::int32_t(in.byte() % std::uint32_t(my + 1))};
            if (op == 4) {
                cdt.export_constraints(&cons);
                if (cons.empty()) continue;
                const auto& e = cons[std::size_t(p.x) % cons.size()];
                const LatticePoint a = cdt.point(e[0]), b = cdt.point(e[1]);
                const std::int32_t g = std::gcd(std::abs(b.x - a.x), std::abs(b.y - a.y));
                if (g <= 1) continue;
                const std::int32_t t = 1 + p.y % (g - 1);
                p = {a.x + (b.x - a.x) / g * t, a.y + (b.y - a.y) / g * t};
            } else {
                p = {p.x * scale, p.y * scale};
            }
            VertInd v = noVertex;
            check(cdt.insert_point(p, &v).ok());
            check(cdt.vertex_live(v) && cdt.point(v) == p);
        } else if (op == 3) {
            const std::uint32_t n = std::uint32_t(cdt.vertex_count());
            const VertInd a = in.byte() % n, b = in.byte() % n;
            const Status s = cdt.insert_constraint(a, b);
            check(s.ok() == (cdt.vertex_live(a) && cdt.vertex_live(b)));
            check(cdt.live_face_count() == live_before);
        } else {
            const VertInd v = VertInd(in.byte() % cdt.vertex_count());
            const bool removable = cdt.can_remove(v);
            const bool side = cdt.vertex_live(v) && cdt.on_boundary(v);
            const auto before = removable ? decltype(canonical_faces(cdt))() : canonical_faces(cdt);
            const Status s = cdt.remove_vertex(v);
            check(s.ok() == removable);
            if (removable) {
                check(!cdt.vertex_live(v));
                check(cdt.live_face_count() + (side ? 1 : 2) == live_before);
            } else {
                check(s.code == Code::input);
                check(cdt.changes().created.empty() && cdt.changes().destroyed.empty());
                check(canonical_faces(cdt) == before);
            }
        }
        check_changes(cdt, live_before, was_live);
        check_fresh(cdt);
    }
    return 0;
}
