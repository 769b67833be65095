#include "algorithms/output/vector_svg.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>

#include "algorithms/model/model_topology.h"
#include "algorithms/model/reconstruct.h"

namespace erd {

namespace {

// v with `decimals` decimals in its shortest spelling: no trailing zeros, no leading "0" before
// the point (".5", "-.25"), "0" for minus zero.
std::string short_num(double v, int decimals) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") return "0";
    if (s.compare(0, 2, "0.") == 0) s.erase(0, 1);
    if (s.compare(0, 3, "-0.") == 0) s.erase(1, 1);
    return s;
}

std::string integer(double v) { return short_num(v, 0); }

// Shortest #rgb or #rrggbb of a gray level (channel -1) or of that level in one channel of
// black (0 red, 1 green, 2 blue).
std::string level_hex(int g, int channel) {
    static const char* hex = "0123456789abcdef";
    std::string s = "#";
    if (g % 17 == 0) {
        for (int k = 0; k < 3; ++k) s += channel < 0 || channel == k ? hex[g / 17] : '0';
    } else {
        for (int k = 0; k < 3; ++k) {
            s += channel < 0 || channel == k ? hex[g >> 4] : '0';
            s += channel < 0 || channel == k ? hex[g & 15] : '0';
        }
    }
    return s;
}

// Gradient ids in order of first use: a letter, then letters and digits ("a", ..., "Z", "ba", ...).
std::string gradient_id(std::size_t n) {
    static const char* k = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::string id(1, k[n % 52]);
    for (n /= 52; n > 0; n /= 62) {
        --n;
        id += k[n % 62];
    }
    return id;
}

// What a renderer paints at (u, v) for a black-to-white gradient from (x0, y0) to (x1, y1), in
// 8-bit levels before quantisation; NaN when the two ends coincide (renderers then paint the last
// stop, not a plane).
double painted(double x0, double y0, double x1, double y1, double u, double v) {
    double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    if (!(len2 > 0)) return std::nan("");
    return 255 * std::clamp(((u - x0) * dx + (v - y0) * dy) / len2, 0.0, 1.0);
}

struct Pt {
    double u, v;
};

// The gradient templates: gray black to white; colour black to pure red, green, blue.
const char* const kTemplate[4] = {"_", "_r", "_g", "_b"};

// A template's <linearGradient> (userSpaceOnUse; the faces' gradients set its end points) for one
// channel (-1 gray): smooth, two stops (level 0 at offset 0, 255 at 1: the plane itself); levels,
// the plane rounded to the nearest level, floor(z + 1/2), as erd reconstruct writes it: two stops
// at each half level (k + 1/2) / 255, level k below and k + 1 from there on, 512 stops in all.
std::string ramp_template(const char* id, int channel, Ramp ramp) {
    std::string t = std::string("<linearGradient id=\"") + id + "\" gradientUnits=\"userSpaceOnUse\"><stop/>";
    if (ramp == Ramp::levels)
        for (int k = 0; k < 255; ++k) {
            const std::string at = "<stop offset=\"" + short_num((k + 0.5) / 255, 6) + "\" stop-color=\"";
            t += at + level_hex(k, channel) + "\"/>" + at + level_hex(k + 1, channel) + "\"/>";
        }
    return t + "<stop offset=\"1\" stop-color=\"" + level_hex(255, channel) + "\"/></linearGradient>\n";
}

// The paint of a face with corners p (user units) and values z (8-bit levels) in one channel
// (-1 gray, else 0..2): one colour when flat, else a gradient on the channel's template (written
// to *defs the first time those end points occur in that channel).
std::string plane_paint(const Pt p[3], const double z[3], int channel, std::unordered_map<std::string, std::string>* gradients,
                        std::string* defs) {
    const double zmin = std::min({z[0], z[1], z[2]}), zmax = std::max({z[0], z[1], z[2]});
    if (zmax - zmin < kFlatRange || zmax <= 0 || zmin >= 255)
        return level_hex(int(std::clamp(std::floor((z[0] + z[1] + z[2]) / 3 + 0.5), 0.0, 255.0)), channel);
    // The plane z = zc + g.(p - c) through the corners, c the centroid; its 0 and 255
    // points along g are the gradient's ends.
    double du1 = p[1].u - p[0].u, dv1 = p[1].v - p[0].v, du2 = p[2].u - p[0].u, dv2 = p[2].v - p[0].v;
    double dz1 = z[1] - z[0], dz2 = z[2] - z[0], det = du1 * dv2 - du2 * dv1;
    double gu = (dz1 * dv2 - dz2 * dv1) / det, gv = (du1 * dz2 - du2 * dz1) / det, g2 = gu * gu + gv * gv;
    double cu = (p[0].u + p[1].u + p[2].u) / 3, cv = (p[0].v + p[1].v + p[2].v) / 3, zc = (z[0] + z[1] + z[2]) / 3;
    double e[4] = {cu - zc / g2 * gu, cv - zc / g2 * gv, cu + (255 - zc) / g2 * gu, cv + (255 - zc) / g2 * gv};
    std::string s[4];
    for (int decimals = 0; decimals <= 9; ++decimals) {
        double r[4];
        for (int k = 0; k < 4; ++k) {
            s[k] = short_num(e[k], decimals);
            r[k] = std::strtod(s[k].c_str(), nullptr);
        }
        bool close = true;
        for (int k = 0; k < 3; ++k)
            close = close && std::fabs(painted(r[0], r[1], r[2], r[3], p[k].u, p[k].v) - std::clamp(z[k], 0.0, 255.0)) <=
                                 kGradientTolerance;
        if (close) break;
    }
    const char* tmpl = kTemplate[channel + 1];
    std::string key = tmpl + (" " + s[0]) + " " + s[1] + " " + s[2] + " " + s[3];
    auto it = gradients->find(key);
    if (it == gradients->end()) {
        it = gradients->emplace(key, gradient_id(gradients->size())).first;
        *defs += "<linearGradient id=\"" + it->second + "\" xlink:href=\"#" + tmpl + "\" x1=\"" + s[0] + "\" y1=\"" + s[1] + "\" x2=\"" +
                 s[2] + "\" y2=\"" + s[3] + "\"/>\n";
    }
    return "url(#" + it->second + ")";
}

}  // namespace

Status render_vector_svg(const Model& m, const VectorSvgOptions& o, std::string* out) {
    if (Status st = check_triangulation(m); !st) return st;  // 1 or 3 channels, values of every channel
    const int C = m.channels;
    if (!(o.scale > 0) || !std::isfinite(o.scale)) return Status::bad_input("scale must be a positive finite number");
    int cx = o.crop_x, cy = o.crop_y, cw = o.crop_w, ch = o.crop_h;
    if (cw == 0 || ch == 0) {
        cx = cy = 0;
        cw = m.width;
        ch = m.height;
    }
    if (cx < 0 || cy < 0 || cw <= 0 || ch <= 0 || cx > m.width - cw || cy > m.height - ch)
        return Status::bad_input("crop window " + std::to_string(cx) + "," + std::to_string(cy) + "," + std::to_string(cw) +
                                 "," + std::to_string(ch) + " is not inside the " + std::to_string(m.width) + "x" +
                                 std::to_string(m.height) + " image");

    // User units per pixel: 1 when every coordinate is even (pixel positions), else 2.
    bool even = std::all_of(m.vertices.begin(), m.vertices.end(), [](LatticePoint p) { return p.x % 2 == 0 && p.y % 2 == 0; });
    const double d = even ? 1 : 2;
    const double umax = (m.width - 1) * d, vmax = (m.height - 1) * d;
    // Vertex positions; those on the border of the domain move out by half a pixel, to the edge of
    // the picture, so the border pixels (whose centres the domain's border passes through) are
    // covered whole. The planes stay those of the original positions.
    std::vector<Pt> at(m.vertices.size()), drawn(m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        at[i] = {m.vertices[i].x * d / 2, m.vertices[i].y * d / 2};
        drawn[i] = at[i];
        if (at[i].u == 0) drawn[i].u = -d / 2;
        if (at[i].u == umax) drawn[i].u = umax + d / 2;
        if (at[i].v == 0) drawn[i].v = -d / 2;
        if (at[i].v == vmax) drawn[i].v = vmax + d / 2;
    }
    const double vx0 = cx * d - d / 2, vy0 = cy * d - d / 2, vx1 = vx0 + cw * d, vy1 = vy0 + ch * d;
    const double level = 255.0 / std::max<std::uint32_t>(1, m.maxval);

    std::string& t = *out;
    t.clear();
    t += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
         short_num(cw * o.scale, 6) + "\" height=\"" + short_num(ch * o.scale, 6) + "\" viewBox=\"" + short_num(vx0, 1) + " " +
         short_num(vy0, 1) + " " + integer(cw * d) + " " + integer(ch * d) + "\"";
    if (o.seams == SeamFix::crisp) t += " shape-rendering=\"crispEdges\"";
    t += ">\n<desc>erd vector: " + std::to_string(m.width) + "x" + std::to_string(m.height) + ", " +
         std::to_string(m.vertices.size()) + " vertices, " + std::to_string(m.faces.size()) + " faces</desc>\n";
    if (C == 1) {
        t += ramp_template(kTemplate[0], -1, o.ramp);
    } else {
        for (int c = 0; c < 3; ++c) t += ramp_template(kTemplate[c + 1], c, o.ramp);
    }

    // Faces along a hard jump (edge_kinds.h: an edge of kind hard) are left out of the
    // anti-aliased layer, so the pixels at that jump are painted whole by one side (the crisp
    // layer), as erd reconstruct evaluates them. The anti-aliased <use> is hidden and every other
    // face says visibility="visible" (which beats the inherited hidden); those faces inherit it.
    // Models without hard jumps are written as before.
    std::vector<std::uint8_t> crisp_face(m.faces.size(), 0);
    bool any_crisp = false;
    if (m.kind == ModelKind::erd && o.seams == SeamFix::layered && (m.edges == EdgeKind::hard || !m.kind_exceptions.empty())) {
        ModelTopology topo;
        if (Status st = build_topology(m, &topo); !st) return st;
        for (std::uint32_t h = 0; h < topo.twin.size(); ++h) {
            if (topo.twin[h] == kNoHalfEdge || !is_discontinuity(m, topo, h)) continue;
            const std::uint32_t a = m.faces[h / 3][h % 3], b = m.faces[h / 3][(h + 1) % 3];
            const std::array<std::uint32_t, 2> e{std::min(a, b), std::max(a, b)};
            const bool listed = std::binary_search(m.kind_exceptions.begin(), m.kind_exceptions.end(), e);
            if ((m.edges == EdgeKind::hard) != listed) crisp_face[h / 3] = 1, any_crisp = true;
        }
    }

    std::unordered_map<std::string, std::string> gradients;  // template and end points -> id
    // One layer per channel (gray: one). Colour layers after the first are screened over the ones
    // below: screen(a, b) = a + b - ab per component, which adds layers that are black in each
    // other's channels exactly.
    for (int c = 0; c < C; ++c) {
        const int channel = C == 1 ? -1 : c;
        const std::string group = C == 1 ? "_m" : "_m" + std::to_string(c);
        if (c > 0) t += "<g style=\"mix-blend-mode:screen\">\n";
        // Layered: the faces once in a group that is drawn twice, without and then with anti-aliasing
        // (the faces along hard jumps only in the first).
        if (o.seams == SeamFix::layered) t += "<defs><g id=\"" + group + "\">\n";
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            const auto& fc = m.faces[f];
            Pt p[3], q[3];
            double z[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = at[fc[std::size_t(k)]];
                q[k] = drawn[fc[std::size_t(k)]];
                z[k] = corner_value(m, std::uint32_t(3 * f + std::size_t(k)), c) * level;
            }
            double lo = std::min({q[0].u, q[1].u, q[2].u}), hi = std::max({q[0].u, q[1].u, q[2].u});
            double top = std::min({q[0].v, q[1].v, q[2].v}), bottom = std::max({q[0].v, q[1].v, q[2].v});
            if (hi <= vx0 || lo >= vx1 || bottom <= vy0 || top >= vy1) continue;

            const std::string paint = plane_paint(p, z, channel, &gradients, &t);
            t += "<path fill=\"" + paint + "\"";
            if (any_crisp && !crisp_face[f]) t += " visibility=\"visible\"";
            t += " d=\"M";
            for (int k = 0; k < 3; ++k) t += (k ? " " : "") + short_num(q[k].u, 1) + " " + short_num(q[k].v, 1);
            t += "z\"/>\n";
        }
        if (o.seams == SeamFix::layered && any_crisp)
            t += "</g></defs>\n<use xlink:href=\"#" + group + "\" shape-rendering=\"crispEdges\"/>\n<use xlink:href=\"#" + group +
                 "\" visibility=\"hidden\"/>\n";
        else if (o.seams == SeamFix::layered)
            t += "</g></defs>\n<use xlink:href=\"#" + group + "\" shape-rendering=\"crispEdges\"/>\n<use xlink:href=\"#" + group +
                 "\"/>\n";
        if (c > 0) t += "</g>\n";
    }
    t += "</svg>\n";
    return Status::success();
}

}  // namespace erd
