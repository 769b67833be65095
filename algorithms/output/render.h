// Pictures of a mesh: SVG text and an anti-aliased RGB raster, both drawn to scale.
//
// Output frame: image pixel (x, y) is the square [x, x+1) x [y, y+1) times `scale`, its sample at
// the square's centre, so a mesh vertex at lattice point (X, Y) lands at ((X/2 + 0.5) s, (Y/2 + 0.5) s)
// and a background image lines up pixel for pixel. A crop window (in pixels) selects a part.
//
// Edges come from algorithms/model/model_topology.h: constrained edges (the model's list, or where
// the corner values of an ERD model differ across an edge) are drawn thick and red (orange: those
// of the other kind than the model's, Model::kind_exceptions), the others thin and blue, vertices
// as dark dots. The library draws; cli/ encodes PNG and writes files.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "kernel/progress.h"
#include "kernel/status.h"

namespace erd {

// 8-bit RGB, row-major, 3 bytes per pixel.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;

    RgbImage() = default;
    RgbImage(int w, int h, std::uint8_t fill) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3, fill) {}
};

// Largest rendered picture, checked before allocating: 8192 px a side, 2^24 px (48 MiB of RGB).
constexpr int kMaxRenderSide = 4096 * 2;
constexpr std::int64_t kMaxRenderPixels = std::int64_t(1) << 24;

struct RenderOptions {
    double scale = 0;        // output pixels per image pixel; <= 0: auto_scale()
    int crop_x = 0, crop_y = 0, crop_w = 0, crop_h = 0;  // pixels; crop_w or crop_h 0: whole image
    bool edges = true;       // draw the triangulation
    bool vertices = false;   // draw a dot at each vertex
    double edge_width = 1.0;         // output pixels
    double constrained_width = 2.5;  // output pixels
    double vertex_radius = 1.6;      // output pixels
    ProgressHook progress;           // render_raster: "render", the fraction of edges drawn
};

// The smallest integer scale that makes the larger side of the (cropped) picture at least 512
// output pixels, or 1 when it already is.
double auto_scale(int width, int height);

// Checks the options against the model (crop inside the image, scale > 0, output size within
// kMaxRenderSide / kMaxRenderPixels) and fills the effective crop and scale into *resolved.
Status resolve_render(const Model& m, const RenderOptions& options, RenderOptions* resolved);

// Samples scaled to 0..255 by maxval, as RGB: a colour image channel by channel, a gray one
// with its sample in all three.
RgbImage image_to_rgb(const Image& im);

// Absolute error |orig - approx| as a colour ramp (black, purple, red, orange, yellow, white):
// error 0 is black and `full` (<= 0: maxval / 8) or more is white; a colour pixel shows its
// largest channel error. Fails (Code::input) when the sizes or the channel counts differ.
Status error_map(const Image& orig, const Image& approx, double full, RgbImage* out);

// Draws the model onto a raster. `background` (may be null: white) is in image pixels (W x H).
Status render_raster(const Model& m, const RgbImage* background, const RenderOptions& options, RgbImage* out);

// The same picture as SVG text. `background_href` (may be empty: white) is the URI of a W x H
// background picture, typically a data: URI of a PNG made by cli/.
Status render_svg(const Model& m, const std::string& background_href, const RenderOptions& options, std::string* out);

}  // namespace erd
