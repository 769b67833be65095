// A model checked to be a triangulation of its image domain (reconstruct.h check_triangulation),
// with what both ways of reconstructing it read: its adjacency, the plane of every face and
// channel, the value at a vertex; and the rounding both write a sample with. Private to
// reconstruct.cpp (point evaluation) and supersampling.cpp.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/model/model_topology.h"
#include "kernel/raster.h"
#include "kernel/status.h"

namespace erd {

struct PreparedModel {
    ModelTopology own;                     // built here unless the caller passes one
    const ModelTopology* topo = nullptr;   // own or the caller's
    RasterDomain dom;
    // The function's value at vertex v in channel c (the mean of its wedges), computed where it is
    // used: point evaluation needs it at the vertices on pixels, supersampling at the corners only.
    double vertex_value(const Model& m, std::uint32_t v, std::size_t c) const {
        return m.kind == ModelKind::erd ? vertex_wedges(m, *topo, v, int(c)).mean : m.values[v * std::size_t(m.channels) + c];
    }
    std::vector<SpanPlane> planes;     // per face and channel, through its corner values, [f*C + c]
};

// Checks m as check_triangulation() describes (the pixel count only when count_pixels) and sets
// up *p. `given` (may be null) is m's adjacency when the caller has it.
Status prepare_model(const Model& m, bool count_pixels, const ModelTopology* given, PreparedModel* p);

// Round to nearest (halves up) and clamp; truncation is floor for the non-negative values left.
// Selects instead of branches (NaN also gives 0), so the loops applying it can vectorise.
inline std::uint16_t to_sample(double v, double maxval) {
    const double c = v > 0.0 ? (v < maxval ? v : maxval) : 0.0;
    return std::uint16_t(std::int32_t(c + 0.5));
}

}  // namespace erd
