// The mesh an .erdz decoder rebuilds from positions and chains, and the coding units of its
// values; the encoder builds the same to know what the decoder will see.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/codec/erdz_sections.h"
#include "kernel/cdt.h"

namespace erd::codec {

struct Rebuilt {
    Cdt cdt;
    std::vector<VertInd> order;              // vertices sorted by (y, x): order[rank] = vertex
    std::vector<std::uint32_t> rank;         // per vertex
    std::vector<std::uint32_t> unit_begin;   // per rank + 1: the vertex's units (1 for basic; its wedges)
    std::vector<std::uint32_t> corner_unit;  // per half-edge: the unit holding face e/3's value at org(e)
    ValueGraph graph;
};

// Triangulates the W x H image's rectangle with the free points and the chains' points, the
// chains' segments as constraints (r->cdt; the rest of *r is left for number_units). Fails
// (input) when a free point is a corner or a chain point, or when two chain segments cross.
Status rebuild(int width, int height, const std::vector<LatticePoint>& free_points, const std::vector<Chain>& chains,
               Rebuilt* r);

// Numbers the value units of r->cdt as it is now (after the flips section): per vertex for a
// basic model, per wedge in rotational order for an ERD model, and fills the rest of *r.
void number_units(bool erd, Rebuilt* r);

}  // namespace erd::codec
