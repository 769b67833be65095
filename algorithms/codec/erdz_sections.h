// The coded sections of an .erdz file (algorithms/codec/erdz.h has the layout): each an
// encoder that returns the section's bytes (the newest version, kErdzVersion) and a decoder
// that checks everything it reads, for the file's version.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kernel/cdt.h"
#include "kernel/lattice.h"
#include "algorithms/codec/range_coder.h"
#include "kernel/status.h"

namespace erd::codec {

// The newest .erdz version; the decoders read 1 .. kErdzVersion. The encoder writes version 3
// unless the model has edges of two kinds (version 4: version 3 and a kinds section).
constexpr int kErdzVersion = 4;
constexpr int kErdzPlainVersion = 3;
inline Adaptation adaptation(int version) { return version <= 2 ? Adaptation::fixed : Adaptation::warm; }

// The free vertices' lattice: cells (i, j) of a GW x GH grid, the point (2i, 2j) on the even
// lattice of a W x H image (GW = W) or (i, j) on the doubled one (GW = 2W - 1).
struct Lattice {
    int width = 0, height = 0;  // image size
    bool full = false;
    std::int64_t cells_x() const { return full ? 2 * std::int64_t(width) - 1 : width; }
    std::int64_t cells_y() const { return full ? 2 * std::int64_t(height) - 1 : height; }
};

// Positions: pts are distinct points of the lattice (any order). The decoder returns them in
// quadtree order (Morton order of the cells), the order decoder_order puts them in.
std::string encode_positions(const Lattice& lat, std::vector<LatticePoint> pts);
void decoder_order(const Lattice& lat, std::vector<LatticePoint>* pts);
Status decode_positions(const unsigned char* data, std::size_t size, const Lattice& lat, int version,
                        std::vector<LatticePoint>* out);

// Edges: segments between lattice points, each a constrained edge, as chains of points.
using Chain = std::vector<LatticePoint>;
std::vector<Chain> make_chains(const std::vector<std::array<LatticePoint, 2>>& segments);
std::string encode_chains(const std::vector<Chain>& chains);
// Points must lie in [0, 2W-2] x [0, 2H-2], on the even lattice when `even`; at most max_steps
// steps in all.
Status decode_chains(const unsigned char* data, std::size_t size, int width, int height, bool even,
                     std::uint64_t max_steps, int version, std::vector<Chain>* out);

// Flips (version 2): the edges flipped in the rebuilt triangulation *cdt (erdz_flips.cpp has the
// visiting order). The encoder asks choose(a, b, c, d) whether to flip edge a-b into c-d (vertices
// of *cdt) at each edge the decoder visits, and returns the section; *flips (may be null) gets the
// number of flips. It returns "" when choose wanted more than max_flips flips. The decoder makes
// the same flips, and refuses a section that ends early or goes on, or that flips more often.
using FlipChoice = std::function<bool(VertInd a, VertInd b, VertInd c, VertInd d)>;
std::string encode_flips(Cdt* cdt, const FlipChoice& choose, std::uint64_t* flips = nullptr);
Status decode_flips(const unsigned char* data, std::size_t size, Cdt* cdt, std::uint64_t* flips = nullptr);
inline std::uint64_t max_flips(std::size_t faces) { return 4 * std::uint64_t(faces); }

// Values: `units` values per channel, coded in unit order. unit_corners lists, per unit
// (CSR: begin[u] .. begin[u+1]), the units of the other two corners of every face the unit
// covers; those below u are the already-coded neighbours its prediction averages.
struct ValueGraph {
    std::vector<std::uint32_t> begin;      // units + 1
    std::vector<std::uint32_t> neighbour;  // unit indices
    std::size_t units() const { return begin.empty() ? 0 : begin.size() - 1; }
};
// q: units * channels quantised values, q[u * channels + c].
std::string encode_values(const ValueGraph& g, int channels, const std::vector<std::int64_t>& q);
Status decode_values(const unsigned char* data, std::size_t size, const ValueGraph& g, int channels, int version,
                     std::vector<std::int64_t>* q);

// Kinds (version 4): the discontinuity edges of the other kind than the model's (erdz_kinds.cpp
// has the visiting order). corner_unit and q are the rebuilt triangulation's coding units and
// their quantised values (channels per unit). The encoder asks other_kind(a, b) for each
// discontinuity a-b (vertices of cdt) and returns "" when it said no to every one; *coded (may be
// null) gets the number of edges of the other kind. The decoder returns those edges (pairs of
// vertices of cdt) and refuses a section that ends early, goes on, or lists none.
using KindChoice = std::function<bool(VertInd a, VertInd b)>;
std::string encode_kinds(const Cdt& cdt, const std::vector<std::uint32_t>& corner_unit, int channels,
                         const std::vector<std::int64_t>& q, const KindChoice& other_kind, std::size_t* coded = nullptr);
Status decode_kinds(const unsigned char* data, std::size_t size, const Cdt& cdt, const std::vector<std::uint32_t>& corner_unit,
                    int channels, const std::vector<std::int64_t>& q, std::vector<std::array<VertInd, 2>>* out);

// The largest |k| a value section holds (values up to 1e9 at the finest step).
constexpr std::int64_t kMaxQuantised = std::int64_t(1) << 39;

}  // namespace erd::codec
