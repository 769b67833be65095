// The positions section: occupancy of the free vertices' lattice as a quadtree.
//
// The root is the smallest power-of-two square holding the GW x GH grid; every occupied node
// codes, for each child that overlaps the grid, one bit "occupied" under the context (level,
// how many children of the node's parent are occupied, occupied siblings so far), and the last
// overlapping child of a node none of whose earlier children is occupied is occupied without a
// bit. Meshes cluster their points where the image is busy, so the per-level models learn the
// density at each scale, and the parent's count tells a busy neighbourhood from a sparse one.
// Its bits are CountModels (a level's rate is steady over the section). Versions 1 and 2 had
// no parent count and BitModels.
#include <algorithm>
#include <array>

#include "algorithms/codec/erdz_sections.h"
#include "algorithms/codec/range_coder.h"

namespace erd::codec {
namespace {

constexpr int kLevels = 18;  // cells per side < 2^17 (2 * kMaxImageSide)

std::uint64_t morton(std::uint32_t x, std::uint32_t y) {
    std::uint64_t m = 0;
    for (int b = 0; b < 32; ++b) {
        m |= std::uint64_t((x >> b) & 1u) << (2 * b);
        m |= std::uint64_t((y >> b) & 1u) << (2 * b + 1);
    }
    return m;
}

int levels_for(const Lattice& lat) {
    const std::int64_t side = std::max(lat.cells_x(), lat.cells_y());
    int l = 0;
    while ((std::int64_t(1) << l) < side) ++l;
    return l;
}

struct Models {
    BitModel any;
    std::array<std::array<std::array<CountModel, 4>, 5>, kLevels> child;  // [level][parent][occupied]
    std::array<std::array<BitModel, 4>, kLevels> child_v2;                 // [level][occupied]
};

struct Encoder {
    const Lattice& lat;
    const std::vector<std::uint64_t>& codes;
    RangeEncoder rc;
    Models m;

    // Node of side 2^level at (x0, y0) holding codes[b, e) (nonempty).
    // parent: how many children of this node's parent are occupied (0 at the root).
    void node(std::int64_t x0, std::int64_t y0, int level, int parent, std::size_t b, std::size_t e) {
        if (level == 0) return;
        const std::int64_t half = std::int64_t(1) << (level - 1);
        const int shift = 2 * (level - 1);
        std::array<std::size_t, 5> cut{};
        cut[0] = b;
        for (int q = 0; q < 4; ++q)
            cut[q + 1] = std::size_t(std::partition_point(codes.begin() + long(cut[q]), codes.begin() + long(e),
                                                          [&](std::uint64_t c) { return int((c >> shift) & 3u) <= q; }) -
                                     codes.begin());
        int last = -1;
        for (int q = 0; q < 4; ++q)
            if (x0 + (q & 1) * half < lat.cells_x() && y0 + (q >> 1) * half < lat.cells_y()) last = q;
        int occupied = 0;
        for (int q = 0; q <= last; ++q) {
            if (x0 + (q & 1) * half >= lat.cells_x() || y0 + (q >> 1) * half >= lat.cells_y()) continue;
            const bool here = cut[q + 1] > cut[q];
            if (!(q == last && occupied == 0))
                rc.bit(m.child[std::size_t(level)][std::size_t(parent)][std::size_t(occupied)], here);
            occupied += here;
        }
        for (int q = 0; q <= last; ++q)
            if (cut[q + 1] > cut[q])
                node(x0 + (q & 1) * half, y0 + (q >> 1) * half, level - 1, occupied, cut[q], cut[q + 1]);
    }
};

struct Decoder {
    const Lattice& lat;
    RangeDecoder rc;
    Models m;
    std::vector<LatticePoint>* out;
    int version;

    int child_bit(int level, int parent, int occupied) {
        if (version <= 2) return rc.bit(m.child_v2[std::size_t(level)][std::size_t(occupied)]);
        return rc.bit(m.child[std::size_t(level)][std::size_t(parent)][std::size_t(occupied)]);
    }

    void node(std::int64_t x0, std::int64_t y0, int level, int parent) {
        if (!rc.good()) return;
        if (level == 0) {
            const std::int32_t x = std::int32_t(x0), y = std::int32_t(y0);
            out->push_back(lat.full ? LatticePoint{x, y} : LatticePoint{2 * x, 2 * y});
            return;
        }
        const std::int64_t half = std::int64_t(1) << (level - 1);
        int last = -1;
        for (int q = 0; q < 4; ++q)
            if (x0 + (q & 1) * half < lat.cells_x() && y0 + (q >> 1) * half < lat.cells_y()) last = q;
        std::array<bool, 4> here{};
        int occupied = 0;
        for (int q = 0; q <= last; ++q) {
            if (x0 + (q & 1) * half >= lat.cells_x() || y0 + (q >> 1) * half >= lat.cells_y()) continue;
            here[std::size_t(q)] =
                (q == last && occupied == 0) || child_bit(level, parent, occupied) != 0;
            occupied += here[std::size_t(q)];
        }
        for (int q = 0; q <= last; ++q)
            if (here[std::size_t(q)]) node(x0 + (q & 1) * half, y0 + (q >> 1) * half, level - 1, occupied);
    }
};

std::uint64_t cell_code(const Lattice& lat, LatticePoint p) {
    return lat.full ? morton(std::uint32_t(p.x), std::uint32_t(p.y)) : morton(std::uint32_t(p.x / 2), std::uint32_t(p.y / 2));
}

}  // namespace

void decoder_order(const Lattice& lat, std::vector<LatticePoint>* pts) {
    std::sort(pts->begin(), pts->end(), [&](LatticePoint a, LatticePoint b) { return cell_code(lat, a) < cell_code(lat, b); });
}

std::string encode_positions(const Lattice& lat, std::vector<LatticePoint> pts) {
    std::vector<std::uint64_t> codes(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) codes[i] = cell_code(lat, pts[i]);
    std::sort(codes.begin(), codes.end());
    Encoder enc{lat, codes, RangeEncoder(), {}};
    enc.rc.bit(enc.m.any, !codes.empty());
    if (!codes.empty()) enc.node(0, 0, levels_for(lat), 0, 0, codes.size());
    return enc.rc.finish();
}

Status decode_positions(const unsigned char* data, std::size_t size, const Lattice& lat, int version,
                        std::vector<LatticePoint>* out) {
    out->clear();
    Decoder dec{lat, RangeDecoder(data, size, adaptation(version)), {}, out, version};
    if (dec.rc.bit(dec.m.any)) dec.node(0, 0, levels_for(lat), 0);
    const std::string why = dec.rc.finish();
    if (!why.empty()) return Status::bad_input("positions section " + why);
    return Status::success();
}

}  // namespace erd::codec
