// Georeferencing read from GeoTIFF's tags (algorithms/imaging/image.h GeoTags): the affine map
// from pixel positions to the raster's world (model) coordinates, and the CRS code, for exports
// in world units and `erd info`. The tags themselves travel unchanged; nothing is reprojected.
#pragma once
#include <string>

#include "algorithms/imaging/image.h"

namespace erd {

// world = (a*x + b*y + c, d*x + e*y + f) for the pixel position (x, y), pixel centres at integers
// (x right, y down), whether the raster's pixels are areas (GeoTIFF's default: the centre of pixel
// (0, 0) is raster point (0.5, 0.5)) or points (GTRasterTypeGeoKey = 2).
struct PixelToWorld {
    double a = 1, b = 0, c = 0, d = 0, e = 1, f = 0;
    double x(double px, double py) const { return a * px + b * py + c; }
    double y(double px, double py) const { return d * px + e * py + f; }
};

// The map the tags give: ModelTransformation, else ModelTiepoint (the first) with ModelPixelScale.
// False (and the identity) when they give none.
bool pixel_to_world(const GeoTags& g, PixelToWorld* out);

// The EPSG code of the CRS the GeoKeys name (ProjectedCSTypeGeoKey, else GeographicTypeGeoKey),
// 0 when none (or user-defined).
int geo_epsg(const GeoTags& g);

// True when the GeoKeys say the model space is projected (GTModelTypeGeoKey 1): x, y in metres
// (or the CRS's linear unit), as heights are.
bool geo_projected(const GeoTags& g);

// One line for people: "EPSG:32615, pixel 30 x 30 at (500000, 4100000)" or "none".
std::string describe_georef(const GeoTags& g);

}  // namespace erd
