#include "algorithms/imaging/georef.h"

#include <cstdio>

namespace erd {

namespace {

// A GeoKey's SHORT value stored in the directory itself (TIFFTagLocation 0); -1 when absent.
int geo_key(const GeoTags& g, int id) {
    const auto& k = g.keys;
    if (k.size() < 4) return -1;
    const std::size_t n = k[3];
    for (std::size_t i = 0; i < n && 4 * (i + 2) <= k.size(); ++i) {
        const std::size_t at = 4 * (i + 1);
        if (k[at] == id && k[at + 1] == 0) return k[at + 3];
    }
    return -1;
}

}  // namespace

bool pixel_to_world(const GeoTags& g, PixelToWorld* out) {
    *out = PixelToWorld();
    // Raster space: pixel (x, y) is at raster point (x + h, y + h), h = 0.5 for PixelIsArea.
    const double h = geo_key(g, 1025) == 2 ? 0.0 : 0.5;
    if (g.transform.size() >= 16) {
        const auto& m = g.transform;
        out->a = m[0];
        out->b = m[1];
        out->c = m[3] + (m[0] + m[1]) * h;
        out->d = m[4];
        out->e = m[5];
        out->f = m[7] + (m[4] + m[5]) * h;
        return true;
    }
    if (g.tiepoints.size() >= 6 && g.pixel_scale.size() >= 2) {
        const auto& t = g.tiepoints;
        const double sx = g.pixel_scale[0], sy = g.pixel_scale[1];
        // X = (I - t0) sx + t3, Y = -(J - t1) sy + t4 for raster point (I, J).
        out->a = sx;
        out->b = 0;
        out->c = (h - t[0]) * sx + t[3];
        out->d = 0;
        out->e = -sy;
        out->f = -(h - t[1]) * sy + t[4];
        return true;
    }
    return false;
}

bool geo_projected(const GeoTags& g) { return geo_key(g, 1024) == 1; }

int geo_epsg(const GeoTags& g) {
    int code = geo_key(g, 3072);  // ProjectedCSTypeGeoKey
    if (code <= 0 || code == 32767) code = geo_key(g, 2048);  // GeographicTypeGeoKey
    return code > 0 && code != 32767 ? code : 0;
}

std::string describe_georef(const GeoTags& g) {
    if (g.empty()) return "none";
    PixelToWorld w;
    std::string s;
    const int epsg = geo_epsg(g);
    s = epsg ? "EPSG:" + std::to_string(epsg) : std::string("CRS not given by an EPSG code");
    if (pixel_to_world(g, &w)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, ", pixel %.10g x %.10g, pixel (0, 0) at (%.12g, %.12g)", w.a, -w.e, w.c, w.f);
        s += buf;
    } else {
        s += ", no pixel-to-world transform";
    }
    return s;
}

}  // namespace erd
