#include "algorithms/output/render.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "algorithms/model/model_topology.h"

namespace erd {

namespace {

struct Colour {
    std::uint8_t r, g, b;
};
constexpr Colour kEdge{0, 120, 255};
constexpr Colour kConstrained{235, 25, 25};
constexpr Colour kVertex{20, 20, 20};
constexpr const char* kEdgeHex = "#0078ff";
constexpr const char* kConstrainedHex = "#eb1919";
// Edges of the other kind than the model's (Model::kind_exceptions, issue 44).
constexpr Colour kOtherKind{255, 170, 0};
constexpr const char* kOtherKindHex = "#ffaa00";
constexpr const char* kVertexHex = "#141414";

// Output position of a lattice coordinate (doubled) along one axis.
double place(std::int32_t doubled, int crop, double scale) { return (doubled / 2.0 - crop + 0.5) * scale; }

void blend(RgbImage* im, int x, int y, Colour c, double a) {
    std::uint8_t* p = &im->pixels[(std::size_t(y) * std::size_t(im->width) + std::size_t(x)) * 3];
    const std::uint8_t src[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(p[k] * (1 - a) + src[k] * a));
}

// A segment with round caps of the given width, anti-aliased by coverage: a pixel whose centre
// lies at distance d from the segment is covered by clamp(width/2 + 1/2 - d, 0, 1). Lines thinner
// than one pixel are drawn one pixel wide with proportionally less opacity, so they fade instead
// of breaking up. Rows are visited only over the x-span the segment can reach.
void draw_segment(RgbImage* im, double x0, double y0, double x1, double y1, double width, Colour c) {
    double alpha = 1, hw = width / 2;
    if (width < 1) { alpha = std::max(width, 0.0); hw = 0.5; }
    const double reach = hw + 1;
    const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    int ya = std::max(0, int(std::floor(std::min(y0, y1) - reach)));
    int yb = std::min(im->height - 1, int(std::ceil(std::max(y0, y1) + reach)));
    for (int y = ya; y <= yb; ++y) {
        double yc = y + 0.5;
        double ta = 0, tb = 1;
        if (dy != 0) {
            double t0 = (yc - reach - y0) / dy, t1 = (yc + reach - y0) / dy;
            ta = std::max(0.0, std::min(t0, t1));
            tb = std::min(1.0, std::max(t0, t1));
            if (ta > tb) continue;
        }
        double xa = x0 + ta * dx, xb = x0 + tb * dx;
        int xs = std::max(0, int(std::floor(std::min(xa, xb) - reach)));
        int xe = std::min(im->width - 1, int(std::ceil(std::max(xa, xb) + reach)));
        for (int x = xs; x <= xe; ++x) {
            double px = x + 0.5 - x0, py = yc - y0;
            double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
            double ex = px - t * dx, ey = py - t * dy;
            double cov = std::clamp(hw + 0.5 - std::sqrt(ex * ex + ey * ey), 0.0, 1.0);
            if (cov > 0) blend(im, x, y, c, cov * alpha);
        }
    }
}

void draw_dot(RgbImage* im, double cx, double cy, double r, Colour c) {
    int xs = std::max(0, int(std::floor(cx - r - 1))), xe = std::min(im->width - 1, int(std::ceil(cx + r + 1)));
    int ys = std::max(0, int(std::floor(cy - r - 1))), ye = std::min(im->height - 1, int(std::ceil(cy + r + 1)));
    for (int y = ys; y <= ye; ++y)
        for (int x = xs; x <= xe; ++x) {
            double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            double cov = std::clamp(r + 0.5 - d, 0.0, 1.0);
            if (cov > 0) blend(im, x, y, c, cov);
        }
}

// Whether e is listed in m.kind_exceptions (an edge of the other kind).
bool other_kind(const Model& m, const ModelEdge& e) {
    return e.constrained && std::binary_search(m.kind_exceptions.begin(), m.kind_exceptions.end(), std::array<std::uint32_t, 2>{e.a, e.b});
}

// The edges to draw (none when options.edges is off); fails on a face list that is not a mesh.
Status edges_to_draw(const Model& m, const RenderOptions& o, std::vector<ModelEdge>* edges) {
    edges->clear();
    if (!o.edges) return Status::success();
    ModelTopology topo;
    if (Status st = build_topology(m, &topo); !st) return st;
    *edges = model_edges(m, topo);
    return Status::success();
}

// Ramp stops for the error map, evenly spaced from error 0 to `full`.
constexpr Colour kRamp[] = {{0, 0, 0}, {70, 10, 120}, {190, 30, 80}, {245, 110, 20}, {250, 220, 40}, {255, 255, 255}};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7g", v);
    return buf;
}

}  // namespace

double auto_scale(int width, int height) {
    int side = std::max(width, height);
    if (side <= 0 || side >= 512) return 1;
    return double((512 + side - 1) / side);
}

Status resolve_render(const Model& m, const RenderOptions& options, RenderOptions* r) {
    *r = options;
    if (m.width <= 0 || m.height <= 0) return Status::bad_input("model has no image size");
    if (r->crop_w == 0 || r->crop_h == 0) {
        r->crop_x = r->crop_y = 0;
        r->crop_w = m.width;
        r->crop_h = m.height;
    }
    if (r->crop_x < 0 || r->crop_y < 0 || r->crop_w <= 0 || r->crop_h <= 0 || r->crop_x > m.width - r->crop_w ||
        r->crop_y > m.height - r->crop_h)
        return Status::bad_input("crop window " + std::to_string(r->crop_x) + "," + std::to_string(r->crop_y) + "," +
                                 std::to_string(r->crop_w) + "," + std::to_string(r->crop_h) + " is not inside the " +
                                 std::to_string(m.width) + "x" + std::to_string(m.height) + " image");
    if (!(r->scale > 0)) r->scale = auto_scale(r->crop_w, r->crop_h);
    if (!std::isfinite(r->scale)) return Status::bad_input("scale must be a finite number");
    double w = std::ceil(r->crop_w * r->scale), h = std::ceil(r->crop_h * r->scale);
    if (w < 1 || h < 1 || w > kMaxRenderSide || h > kMaxRenderSide || w * h > double(kMaxRenderPixels))
        return Status::bad_input("picture of " + num(w) + "x" + num(h) + " pixels: each side must lie in 1.." +
                                 std::to_string(kMaxRenderSide) + " and the area be at most " +
                                 std::to_string(kMaxRenderPixels) + " pixels (change --scale or --crop)");
    return Status::success();
}

RgbImage image_to_rgb(const Image& im) {
    RgbImage out(im.width, im.height, 0);
    double k = im.maxval > 0 ? 255.0 / im.maxval : 0;
    const auto byte = [&](std::uint16_t v) { return std::uint8_t(std::lround(std::min(255.0, v * k))); };
    if (im.channels == 3) {
        for (std::size_t i = 0; i < out.pixels.size() && i < im.samples.size(); ++i) out.pixels[i] = byte(im.samples[i]);
        return out;
    }
    for (std::size_t i = 0; i < im.samples.size(); ++i) {
        auto g = byte(im.samples[i]);
        out.pixels[3 * i] = out.pixels[3 * i + 1] = out.pixels[3 * i + 2] = g;
    }
    return out;
}

Status error_map(const Image& orig, const Image& approx, double full, RgbImage* out) {
    if (orig.width != approx.width || orig.height != approx.height)
        return Status::bad_input("original is " + std::to_string(orig.width) + "x" + std::to_string(orig.height) +
                                 " but the model is " + std::to_string(approx.width) + "x" + std::to_string(approx.height));
    if (orig.channels != approx.channels) {
        const auto kind = [](const Image& im) { return im.channels == 1 ? std::string("gray") : "colour (" + std::to_string(im.channels) + " channels)"; };
        return Status::bad_input("original is " + kind(orig) + " but the model is " + kind(approx));
    }
    if (!(full > 0)) full = std::max(1.0, orig.maxval / 8.0);
    *out = RgbImage(orig.width, orig.height, 0);
    const int stops = int(sizeof kRamp / sizeof kRamp[0]) - 1;
    const std::size_t C = std::size_t(orig.channels);
    for (std::size_t i = 0; i < orig.pixels(); ++i) {
        // A colour pixel's error is that of its worst channel.
        double e = 0.0;
        for (std::size_t c = 0; c < C; ++c)
            e = std::max(e, std::fabs(double(orig.samples[i * C + c]) - double(approx.samples[i * C + c])));
        double t = std::min(1.0, e / full) * stops;
        int k = std::min(stops - 1, int(t));
        double u = t - k;
        const Colour a = kRamp[k], b = kRamp[k + 1];
        out->pixels[3 * i] = std::uint8_t(std::lround(a.r + (b.r - a.r) * u));
        out->pixels[3 * i + 1] = std::uint8_t(std::lround(a.g + (b.g - a.g) * u));
        out->pixels[3 * i + 2] = std::uint8_t(std::lround(a.b + (b.b - a.b) * u));
    }
    return Status::success();
}

Status render_raster(const Model& m, const RgbImage* background, const RenderOptions& options, RgbImage* out) {
    RenderOptions o;
    Status st = resolve_render(m, options, &o);
    if (!st) return st;
    if (background && (background->width != m.width || background->height != m.height))
        return Status::bad_input("background is " + std::to_string(background->width) + "x" +
                                 std::to_string(background->height) + " but the model is " + std::to_string(m.width) +
                                 "x" + std::to_string(m.height));
    std::vector<ModelEdge> edges;
    if (!(st = edges_to_draw(m, o, &edges))) return st;
    const double s = o.scale;
    const int w = int(std::ceil(o.crop_w * s)), h = int(std::ceil(o.crop_h * s));
    *out = RgbImage(w, h, 255);
    if (background) {
        // Nearest pixel when enlarging, the mean of the covered pixels when shrinking.
        for (int oy = 0; oy < h; ++oy) {
            int y0 = o.crop_y + std::min(o.crop_h - 1, int(std::floor(oy / s)));
            int y1 = std::max(y0 + 1, std::min(o.crop_y + o.crop_h, o.crop_y + int(std::ceil((oy + 1) / s))));
            for (int ox = 0; ox < w; ++ox) {
                int x0 = o.crop_x + std::min(o.crop_w - 1, int(std::floor(ox / s)));
                int x1 = std::max(x0 + 1, std::min(o.crop_x + o.crop_w, o.crop_x + int(std::ceil((ox + 1) / s))));
                unsigned sum[3] = {0, 0, 0};
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x)
                        for (int k = 0; k < 3; ++k)
                            sum[k] += background->pixels[(std::size_t(y) * std::size_t(m.width) + std::size_t(x)) * 3 + std::size_t(k)];
                unsigned n = unsigned((y1 - y0) * (x1 - x0));
                for (int k = 0; k < 3; ++k)
                    out->pixels[(std::size_t(oy) * std::size_t(w) + std::size_t(ox)) * 3 + std::size_t(k)] =
                        std::uint8_t((sum[k] + n / 2) / n);
            }
        }
    }
    auto px = [&](LatticePoint p) { return place(p.x, o.crop_x, s); };
    auto py = [&](LatticePoint p) { return place(p.y, o.crop_y, s); };
    // Thin edges first so the thick constrained ones stay on top.
    const std::size_t every = edges.size() / 50 + 1;
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < edges.size(); ++i) {
            if (options.progress && i % every == 0)
                options.progress("render", 0.5 * (double(pass) + double(i) / double(edges.size())));
            const ModelEdge& e = edges[i];
            if (e.constrained != (pass == 1)) continue;
            LatticePoint a = m.vertices[e.a], b = m.vertices[e.b];
            draw_segment(out, px(a), py(a), px(b), py(b), e.constrained ? o.constrained_width : o.edge_width,
                         !e.constrained ? kEdge : other_kind(m, e) ? kOtherKind : kConstrained);
        }
    if (o.vertices)
        for (LatticePoint p : m.vertices) draw_dot(out, px(p), py(p), o.vertex_radius, kVertex);
    return Status::success();
}

Status render_svg(const Model& m, const std::string& background_href, const RenderOptions& options, std::string* out) {
    RenderOptions o;
    Status st = resolve_render(m, options, &o);
    if (!st) return st;
    std::vector<ModelEdge> edges;
    if (!(st = edges_to_draw(m, o, &edges))) return st;
    const double s = o.scale;
    const double w = o.crop_w * s, h = o.crop_h * s;
    std::string& t = *out;
    t.clear();
    t += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    t += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" + num(w) +
         "\" height=\"" + num(h) + "\" viewBox=\"0 0 " + num(w) + " " + num(h) + "\">\n";
    t += "<desc>erd mesh: " + std::to_string(m.width) + "x" + std::to_string(m.height) + ", " +
         std::to_string(m.vertices.size()) + " vertices, " + std::to_string(m.faces.size()) + " faces</desc>\n";
    if (background_href.empty()) {
        t += "<rect id=\"background\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" fill=\"#ffffff\"/>\n";
    } else {
        // The whole image placed so the crop window fills the viewport; the viewport clips the rest.
        t += "<image id=\"background\" x=\"" + num(-o.crop_x * s) + "\" y=\"" + num(-o.crop_y * s) + "\" width=\"" +
             num(m.width * s) + "\" height=\"" + num(m.height * s) +
             "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" xlink:href=\"" + background_href +
             "\" href=\"" + background_href + "\"/>\n";
    }
    auto px = [&](LatticePoint p) { return place(p.x, o.crop_x, s); };
    auto py = [&](LatticePoint p) { return place(p.y, o.crop_y, s); };
    auto outside = [&](LatticePoint a, LatticePoint b) {
        double ax = px(a), bx = px(b), ay = py(a), by = py(b);
        return (ax < 0 && bx < 0) || (ay < 0 && by < 0) || (ax > w && bx > w) || (ay > h && by > h);
    };
    // Edges, constrained edges of the model's kind, and (when it lists some) those of the other kind.
    for (int pass = 0; pass < (m.kind_exceptions.empty() ? 2 : 3); ++pass) {
        bool cons = pass >= 1;
        t += pass == 2 ? "<g id=\"other-kind\" stroke=\"" + std::string(kOtherKindHex) + "\" stroke-width=\"" + num(o.constrained_width)
             : cons    ? "<g id=\"constrained\" stroke=\"" + std::string(kConstrainedHex) + "\" stroke-width=\"" + num(o.constrained_width)
                       : "<g id=\"edges\" stroke=\"" + std::string(kEdgeHex) + "\" stroke-width=\"" + num(o.edge_width);
        t += "\" stroke-linecap=\"round\" fill=\"none\">\n";
        for (const ModelEdge& e : edges) {
            if (e.constrained != cons || (cons && other_kind(m, e) != (pass == 2))) continue;
            LatticePoint a = m.vertices[e.a], b = m.vertices[e.b];
            if (outside(a, b)) continue;
            t += "<line x1=\"" + num(px(a)) + "\" y1=\"" + num(py(a)) + "\" x2=\"" + num(px(b)) + "\" y2=\"" + num(py(b)) + "\"/>\n";
        }
        t += "</g>\n";
    }
    if (o.vertices) {
        t += "<g id=\"vertices\" fill=\"" + std::string(kVertexHex) + "\">\n";
        for (LatticePoint p : m.vertices) {
            if (outside(p, p)) continue;
            t += "<circle cx=\"" + num(px(p)) + "\" cy=\"" + num(py(p)) + "\" r=\"" + num(o.vertex_radius) + "\"/>\n";
        }
        t += "</g>\n";
    }
    t += "</svg>\n";
    return Status::success();
}

}  // namespace erd
