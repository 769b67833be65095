// The approximating function of a model as an exact vector picture: SVG in which every face is a
// triangle filled with a linear gradient that is its plane.
//
// A linear gradient paints, at a point p, the stop colours interpolated at
// t = (p - p0).(p1 - p0) / |p1 - p0|^2 and clamped to [0, 1] (spreadMethod pad). With the stops
// black at offset 0 and white at offset 1, p0 the point where the face's plane is 0 and p1 where
// it is 255, with p1 - p0 along the plane's gradient, that is the plane itself clamped to the 8-bit
// range: what `erd reconstruct` evaluates and clamps. SVG interpolates stop colours linearly in
// sRGB component values, the units the samples are in. So every face's gradient shares one
// template (stops, userSpaceOnUse) and sets only its two end points; faces on one plane share the
// gradient. A face whose values differ by less than kFlatRange is filled with one colour. The
// jumps of an ERD model need nothing of their own: the faces on the two sides are different faces.
//
// Frame: pixel (x, y) is the output square [x, x+1) x [y, y+1) (times the scale), sampled at its
// centre as a browser draws an SVG 1:1, so a vertex at image position (x, y) lands at (x + 0.5,
// y + 0.5). The user units are pixels for a basic model (integer vertex coordinates) and half
// pixels for an ERD model (its vertices sit on the half-pixel lattice), with the viewBox moved by
// half a pixel, so every vertex coordinate is a short integer.
//
// Colour (a value per channel, once models have it) is designed in: each channel becomes one
// layer of the same triangles with its own template (black to pure red, green, blue), layers after
// the first composited with mix-blend-mode:screen, which adds channels that do not overlap.
#pragma once
#include <string>

#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

// How the hairlines between abutting anti-aliased triangles are avoided (docs/DECISIONS.md,
// "Vector SVG"). layered: the faces are drawn twice (one group, two <use>), first with
// shape-rendering="crispEdges" (each pixel painted whole by one face, no background left), then
// anti-aliased over it, so an edge pixel mixes its faces by coverage over that underlayer instead
// of over the background. crisp: only the crispEdges layer (jagged jumps when zoomed). none: only
// the anti-aliased layer (the seams show).
enum class SeamFix { layered, crisp, none };

// What a face's gradient paints (docs/DECISIONS.md, "Vector SVG"). levels: the plane rounded to
// 8-bit levels, as erd reconstruct writes it (a template of 512 stops, two at each half level,
// shared by every face: about 23 KB once a channel). A renderer that dithers gradients (chromium
// does, a fixed 2x2 pattern of up to 3/8 of a level) then paints each level exactly. smooth: the
// plane itself (two stops), which such a renderer dithers before it rounds.
enum class Ramp { levels, smooth };

struct VectorSvgOptions {
    double scale = 1;  // output pixels per image pixel (the width and height attributes)
    int crop_x = 0, crop_y = 0, crop_w = 0, crop_h = 0;  // pixels; crop_w or crop_h 0: whole image
    SeamFix seams = SeamFix::layered;
    Ramp ramp = Ramp::levels;
};

// Faces whose three values (8-bit units) lie within this range are filled with one colour.
constexpr double kFlatRange = 1.0 / 8;
// Gradient end points are written with the fewest decimals that keep the painted plane within
// this many 8-bit levels of the exact one at the face's corners.
constexpr double kGradientTolerance = 1.0 / 64;

// The SVG text of m's approximating function (gray: values scaled by 255 / maxval). Fails on a
// model that is not a triangulation of its image (check_triangulation), a crop window outside
// the image or a scale that is not positive and finite.
Status render_vector_svg(const Model& m, const VectorSvgOptions& options, std::string* out);

}  // namespace erd
