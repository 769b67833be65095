// .erdz: the compact binary model file. A basic or ERD model, gray or colour, in a versioned,
// self-describing container whose sections are range-coded (algorithms/codec/range_coder.h).
//
// Layout (integers are LEB128 varints unless said otherwise):
//   magic      the 4 bytes "ERDZ", then the version byte (3, or 4 for a model with edges of two
//              kinds; 2 and 1 are still read: version 1 had no flips section, versions 1 and 2
//              adapted every BitModel by fixed steps of 1/32 and coded positions and values under
//              the plainer contexts said below)
//   header     width, height, maxval, channels (1 or 3), kind (0 basic, 1 erd), edges (0 soft,
//              1 hard), step (the value quantisation step in 1/256ths, >= 1), lattice (0: free
//              vertices on the even lattice, 1: on the doubled lattice), the method's name
//              (length byte + that many bytes of [a-z0-9_-], may be empty)
//   sections   four (five in version 4), in this order, each its byte length (varint) then its
//              range-coded bytes:
//     positions  the vertices on no constrained edge, other than the four corners: occupancy of
//                the lattice as a quadtree, one adaptive bit per child (context: level, how many
//                children of the parent are occupied (not in 1, 2) and how many earlier siblings
//                were occupied; a last child that must be occupied is not coded)
//     edges      the constrained edges as chains: a chain starts at a position (coded relative
//                to the previous chain's start) and goes on by steps (dx, dy) between its
//                successive vertices; the chain's vertices are vertices of the model
//     flips      the edges to flip in the rebuilt triangulation, one adaptive bit per edge the
//                decoder visits (erdz_flips.cpp); empty (0 bytes) when nothing is flipped
//     values     the values, quantised to integer multiples k of the step, in the order of the
//                vertices sorted by (y, x): per vertex (basic) or per wedge (erd), per channel,
//                k minus a prediction from the vertex's already-coded neighbours in that wedge,
//                and in channels 1 and 2 also the residual of channel 0, under a context of the
//                neighbours' spread (and, not in 1, 2, whether there is only one)
//     kinds      (version 4 only) the discontinuity edges of the other kind than the header's
//                edges (Model::kind_exceptions, algorithms/model/edge_kinds.h): one adaptive bit
//                per edge across which the decoded values jump (erdz_kinds.cpp); an edge listed in
//                the model whose values quantisation merged is no discontinuity and is not kept
//   Nothing may follow the last section. Models with edges of one kind are written as version 3,
//   byte for byte as before per-edge kinds, so every erd since version 3 reads them.
//
// Topology is not stored. The decoder rebuilds the constrained Delaunay triangulation of the
// positions with the edges as constraints (kernel/cdt.h), the same as the encoder's (the same
// input in the same order), then makes the flips. The encoder's constraints are the model's own
// and its discontinuities; it flips an edge when the other diagonal crosses fewer of the model's
// edges, which reaches any triangulation of the points (a flip that lowers the crossings always
// exists while any remain), so the flips do not depend on how the model's faces were chosen.
// Should the faces still differ (faces that are not a triangulation of the points, or more flips
// than max_flips), it adds the missing edges as constraints and starts again. The decoded model
// lists its vertices sorted by (y, x), its faces as the kernel exports them and, as
// Model::constraints, the decoded edges.
//
// Every value decodes to within step / 2 of the encoded model's (exactly, for integer values and
// step 1). A decoder refuses every file that an encoder cannot have written: a bad magic or
// version, a header value out of range, a section that ends early or goes on after its last
// symbol, a position outside the image or given twice, a chain step of zero, crossing edges,
// more flips than any encoder makes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/status.h"

namespace erd {

struct ErdzOptions {
    double step = 1.0;   // value quantisation step (rounded to a multiple of 1/256, at least 1/256)
    std::string method;  // stored in the header; [a-z0-9_-], at most 32 characters
};

// What a file holds and what each part costs.
struct ErdzInfo {
    int version = 0;
    std::string method;
    double step = 0.0;
    bool full_lattice = false;          // free vertices on the doubled lattice
    std::size_t header_bits = 0;        // magic, version, header and the section length prefixes
    std::size_t position_bits = 0, edge_bits = 0, flip_bits = 0, value_bits = 0, kind_bits = 0;
    std::size_t total_bits = 0;
    std::size_t free_points = 0;        // coded in the positions section
    std::size_t chains = 0, chain_steps = 0;
    std::size_t flips = 0;              // edges flipped after the rebuild
    std::size_t coded_values = 0;       // vertices (basic) or wedges (erd), times channels
    std::size_t other_kind_edges = 0;   // edges of the other kind (version 4)
};

struct ErdzLimits {
    std::uint64_t max_pixels = std::uint64_t(1) << 28;  // W * H of a decoded model
};

// True when bytes start with the .erdz magic.
bool is_erdz(const std::string& bytes);

// For reading a stream: the size of the whole file once `prefix` holds its header and the three
// section lengths; 0 while more bytes are needed; prefix.size() when prefix cannot start a valid
// file (the decoder then names the problem).
std::uint64_t erdz_stream_size(const std::string& prefix);

// Encodes m. Fails (input) when m is not a model of a W x H image with its four corners as
// vertices and faces that form a triangulation of them; *info (may be null) gets the sizes.
Status encode_erdz(const Model& m, const ErdzOptions& options, std::string* out, ErdzInfo* info = nullptr);

// Decodes a whole file into *out; every problem is one Status (input) naming the section.
Status decode_erdz(const std::string& bytes, Model* out, ErdzInfo* info = nullptr,
                   const ErdzLimits& limits = ErdzLimits());

// decode_erdz, also handing back the model's adjacency (*topo, as build_topology(*out) gives it)
// from the triangulation the decoder rebuilt: the model's faces are its faces in order, so the
// twins are the kernel's and only the vertex fans are counted (no directed-edge search).
Status decode_erdz_topology(const std::string& bytes, Model* out, ModelTopology* topo, ErdzInfo* info = nullptr,
                            const ErdzLimits& limits = ErdzLimits());

}  // namespace erd
