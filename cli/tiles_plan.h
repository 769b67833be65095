// The plan of `erd tiles` (cli/cmd_tiles.cpp): the task list written once by --plan and read by
// every --task K and by --finish, so that each task needs only the plan and its window of the
// raster. A text file, DIR/plan.txt ("erd-tiles-plan 1"), one fact per line:
//
//   erd-tiles-plan 1
//   raster PATH                 the raster, as an absolute path
//   size W H / tile T / grid NX NY / method NAME / format EXT (tile exports; "-" none)
//   values int MAXVAL | real LO HI     what the merged mesh's default zscale reads
//   geo-scale, geo-tie, geo-transform  the GeoTIFF tags, as read (index.json repeats them)
//   arg TEXT                    each of generate's flags as given, re-parsed by every task
//   vborder I J K o1 .. oK      vertical line I, tile row J: the chosen samples' offsets from its top
//   hborder J I K o1 .. oK      horizontal line J, tile column I: offsets from its left end
//   vcross I J K o1 .. oK       ERD: where a discontinuity crosses that border, between samples o
//   hcross J I K o1 .. oK       and o + 1 (doubled offset 2o + 1); only lines with K > 0
//   task K I J POINTS TRIANGLES one tile: column I, row J, its vertex budget and triangle budget (0: off)
//   end
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/tiles.h"
#include "kernel/lattice.h"
#include "kernel/status.h"

namespace erd::cli {

struct TilesPlan {
    std::string raster;
    TileGrid grid;
    std::string method;
    std::string format;  // tile export extension (obj, ply, stl, glb) or empty
    bool real = false;
    std::uint32_t maxval = 0;
    double lo = 0, hi = 0;
    GeoTags geo;
    std::vector<std::string> args;
    // vborder[i][j]: offsets (from row(j)) of the chosen samples on vertical line i in tile row j;
    // hborder[j][i]: offsets (from column(i)) on horizontal line j in tile column i. Both ends included.
    std::vector<std::vector<std::vector<int>>> vborder, hborder;
    // vcross[i][j], hcross[j][i]: the crossings of the same borders (tiles.h profile_crossings),
    // offsets o of crossings between samples o and o + 1. Empty for GPI.
    std::vector<std::vector<std::vector<int>>> vcross, hcross;
    std::vector<std::int64_t> points, triangles;  // per task k = j * nx + i

    // The tile of task k: its window (inclusive) and its sides' points in the tile's doubled
    // coordinates, corners included.
    void window(int k, int* x0, int* y0, int* x1, int* y1) const;
    std::vector<LatticePoint> side_points(int k) const;
    // Its sides' crossings in the same coordinates (one coordinate odd).
    std::vector<LatticePoint> side_crossings(int k) const;
    std::string tile_name(int k) const;  // "tile_J_I"
};

std::string plan_text(const TilesPlan& p);
// Fails (Code::input) naming the line of the first problem.
Status parse_plan(const std::string& text, TilesPlan* p);

}  // namespace erd::cli
