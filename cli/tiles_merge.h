// The merged mesh of `erd tiles --merge FILE` (cli/cmd_tiles.cpp): the tiles' models read one at
// a time and written as one mesh as they come, never the whole mesh in memory. The vertices on
// the tiles' sides are written once (the tiles share them exactly: tiles_plan.h) and the faces
// of every tile use them; an ERD tile's vertex gets a copy per distinct wedge value, as
// algorithms/output/export.h does, so its discontinuities stay open.
//
// Frame as export.h: x = X/2, y = (H-1) - Y/2 in the whole raster's pixels, z = value * zscale
// (default max(W, H) / (10 * maxval), or over the range hi - lo of a real raster). Formats by the
// name: .obj (one pass), .ply (ASCII; the counts first: two passes more), .stl (binary; one more
// pass), .glb (glTF 2.0 binary, one mesh of 32-bit indices: three passes). No world coordinates:
// index.json has the georeferencing.
#pragma once
#include <cstdint>
#include <string>

#include "cli/tiles_plan.h"
#include "kernel/status.h"

namespace erd::cli {

struct MergeCounts {
    std::uint64_t vertices = 0, faces = 0;
};

// True for the names --merge takes (.obj, .ply, .stl, .glb).
bool merge_format_known(const std::string& path);

// Writes the merged mesh of the tiles in dir (tile_J_I.model or .erd) to the descriptor fd.
Status write_merged(const TilesPlan& plan, const std::string& dir, const std::string& path, double zscale, int fd,
                    MergeCounts* counts);

}  // namespace erd::cli
