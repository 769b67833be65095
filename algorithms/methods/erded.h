// ERDED (thesis 3.4.2): the initial ERD mesh of step 1 with its wedge values, plus a set S of
// N - N0 pixels chosen all at once by Floyd-Steinberg error diffusion and inserted into the
// constrained Delaunay triangulation.
//
// Error diffusion as in ED with the thesis's changes: MMSODD with 5th-order binomial smoothing,
// sigma = (d / d_max)^0.5, the density set to zero on edge pixels (the step-1.1 edge map mapped to
// pixels), and the start-up effect handled by mirroring (-B 0, default), forcing (-B 1) or not
// at all (-B 2). The thesis discards chosen points that land on a constrained edge; here those
// pixels (and pixels that already are vertices) are forbidden to the diffusion instead, so the
// count search aims at exactly N - N0 usable points and no point is lost afterwards. When no
// threshold gives the exact count the nearest pass is topped up with the densest unchosen pixels
// (or trimmed of its least dense chosen ones), so the mesh has exactly N vertices whenever the
// image has enough usable pixels. -f 0 chooses S uniformly at random instead (fixed seed).
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/methods/options.h"
#include "kernel/cdt.h"
#include "kernel/status.h"

namespace erd {

// Pixels (W x H) that may not become sample points: vertices of cdt at pixel positions and pixels
// lying on a constrained edge.
Grid<std::uint8_t> occupied_pixels(const Cdt& cdt, int width, int height);

// Pixels whose cell (the square of side one pixel around it) holds a point of the half-pixel
// edge map: the pixels "on an edge" whose density ERDED sets to zero.
Grid<std::uint8_t> edge_cells(const Grid<std::uint8_t>& half_pixel_edges, int width, int height);

// Registry entry "erded" (algorithms/methods/methods.h contract).
Status generate_erded(const Image& image, const GenerateOptions& options, GenerateResult* result);

}  // namespace erd
