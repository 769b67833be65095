#include "algorithms/output/export.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "algorithms/imaging/georef.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/output/gltf.h"
#include "algorithms/output/little_endian.h"

namespace erd {

double default_zscale(const Model& m) {
    PixelToWorld w;
    const bool world = pixel_to_world(m.meta.geo, &w);
    if (world && geo_projected(m.meta.geo)) return 1.0;
    double side = double(std::max(m.width, m.height));
    if (world) {
        // The larger extent of the raster in its world units (degrees).
        const double W1 = m.width - 1, H1 = m.height - 1;
        side = std::max(std::hypot(w.a * W1, w.d * W1), std::hypot(w.b * H1, w.e * H1));
    }
    if (!m.real) return side / (10.0 * double(m.maxval == 0 ? 1 : m.maxval));
    const double range = m.hi > m.lo ? m.hi - m.lo : 1.0;
    return side / (10.0 * range);
}

namespace {

// BT.601 luma of one RGB value triple, the height of a colour model's surface (as erd's gray
// conversion of colour images weighs the channels).
double luma(const double* v) { return 0.299 * v[0] + 0.587 * v[1] + 0.114 * v[2]; }

void append(std::string* s, const char* fmt, double a, double b, double c) {
    char buf[96];
    int n = std::snprintf(buf, sizeof buf, fmt, a, b, c);
    if (n > 0) s->append(buf, std::size_t(std::min(n, int(sizeof buf) - 1)));
}

void append_face(std::string* s, const char* fmt, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    char buf[64];
    int n = std::snprintf(buf, sizeof buf, fmt, a, b, c);
    if (n > 0) s->append(buf, std::size_t(std::min(n, int(sizeof buf) - 1)));
}


using Vec3 = std::array<float, 3>;

void put_facet(std::string* s, const Vec3& a, const Vec3& b, const Vec3& c) {
    const float ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const float vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    float n[3] = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (float& x : n) x = len > 0 ? x / len : 0.0f;
    for (float x : n) put_f32(s, x);
    for (const Vec3* p : {&a, &b, &c})
        for (float x : *p) put_f32(s, x);
    s->push_back('\0');
    s->push_back('\0');
}

// Binary STL of the faces (corners counter-clockwise seen from +z); with base > 0, lifted by base
// and closed by walls under the boundary edges (those whose reverse no face has) and a bottom.
void write_stl(const std::vector<std::array<double, 3>>& pos, const std::vector<std::array<std::uint32_t, 3>>& faces,
               double base, const std::string& header_text, std::string* out, std::size_t* facets) {
    std::vector<Vec3> top(pos.size());
    for (std::size_t i = 0; i < pos.size(); ++i) top[i] = {float(pos[i][0]), float(pos[i][1]), float(pos[i][2] + base)};
    std::vector<std::uint64_t> boundary;  // directed edges a -> b, a in the high half
    if (base > 0) {
        std::vector<std::uint64_t> edges;
        edges.reserve(3 * faces.size());
        for (const auto& t : faces)
            for (int k = 0; k < 3; ++k) edges.push_back((std::uint64_t(t[std::size_t(k)]) << 32) | t[std::size_t((k + 1) % 3)]);
        std::sort(edges.begin(), edges.end());
        for (const std::uint64_t e : edges)
            if (!std::binary_search(edges.begin(), edges.end(), (e << 32) | (e >> 32))) boundary.push_back(e);
    }
    const std::size_t n = base > 0 ? 2 * faces.size() + 2 * boundary.size() : faces.size();
    std::string header = header_text;
    header.resize(80, ' ');
    out->append(header);
    put_u32(out, std::uint32_t(n));
    out->reserve(out->size() + 50 * n);
    for (const auto& t : faces) put_facet(out, top[t[0]], top[t[1]], top[t[2]]);
    if (base > 0) {
        auto bottom = [&](std::uint32_t v) { return Vec3{top[v][0], top[v][1], 0.0f}; };
        for (const auto& t : faces) put_facet(out, bottom(t[0]), bottom(t[2]), bottom(t[1]));
        for (const std::uint64_t e : boundary) {
            const std::uint32_t a = std::uint32_t(e >> 32), b = std::uint32_t(e);
            put_facet(out, top[a], bottom(a), bottom(b));
            put_facet(out, top[a], bottom(b), top[b]);
        }
    }
    *facets = n;
}

}  // namespace

Status export_mesh(const Model& m, const ExportOptions& options, std::string* out, ExportCounts* counts) {
    out->clear();
    if (m.values.empty() && !m.vertices.empty())
        return Status::bad_input("the mesh has no sample values (a triangulation file?): export the .model or .erd");
    if (m.channels != 1 && m.channels != 3) return Status::bad_input("model has " + std::to_string(m.channels) + " channels (1 or 3)");
    const std::size_t C = std::size_t(m.channels);
    if (m.values.size() != m.vertices.size() * C)
        return Status::bad_input("model has " + std::to_string(m.vertices.size()) + " vertices but " + std::to_string(m.values.size()) +
                                 " values" + (C > 1 ? " for " + std::to_string(C) + " channels" : ""));
    const bool erd = m.kind == ModelKind::erd;
    if (options.format == MeshFormat::stl && options.base > 0 && erd)
        return Status::bad_input("--base needs a basic model (.model): an ERD surface is open along its constrained edges");
    if (erd && m.corner_values.size() != m.faces.size() * C)
        return Status::bad_input("ERD model without a value for every face corner");
    ModelTopology topo;
    if (Status st = build_topology(m, &topo); !st) return st;
    const double zs = options.zscale > 0 ? options.zscale : default_zscale(m);
    const double top = double(m.height - 1);
    // Pixels with y up, or the raster's world coordinates (GeoTIFF).
    PixelToWorld wmap;
    const bool world = pixel_to_world(m.meta.geo, &wmap);
    const auto place = [&](LatticePoint p) -> std::array<double, 2> {
        const double px = p.x / 2.0, py = p.y / 2.0;
        if (world) return {wmap.x(px, py), wmap.y(px, py)};
        return {px, top - py};
    };

    // Positions of the written vertices (z from the luma of a colour model), their colours, and
    // each face's three indices into them.
    std::vector<std::array<double, 3>> pos, rgb;
    const auto value = [&](const double* v) { return C == 1 ? v[0] : luma(v); };
    const auto colour = [&](const double* v) {
        if (C > 1) rgb.push_back({v[0], v[1], v[2]});
    };
    std::vector<std::array<std::uint32_t, 3>> face_idx(m.faces.size());
    if (erd) {
        const CornerWedges cw = corner_wedges(m, topo);
        // A vertex without faces still gets written once, so no input vertex vanishes silently.
        std::vector<std::uint32_t> copy_of_wedge(cw.count);
        std::vector<bool> placed(cw.count, false);
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            const auto [x, y] = place(m.vertices[v]);
            if (cw.first[v] == cw.first[v + 1]) {
                pos.push_back({x, y, value(&m.values[v * C]) * zs});
                colour(&m.values[v * C]);
                continue;
            }
            for (std::uint32_t w = cw.first[v]; w < cw.first[v + 1]; ++w) {
                copy_of_wedge[w] = std::uint32_t(pos.size());
                pos.push_back({x, y, 0});
                colour(&m.values[v * C]);  // replaced by the wedge's colour below
            }
        }
        for (std::size_t f = 0; f < m.faces.size(); ++f)
            for (int i = 0; i < 3; ++i) {
                std::uint32_t w = cw.label[3 * f + std::size_t(i)];
                face_idx[f][std::size_t(i)] = copy_of_wedge[w];
                if (placed[w]) continue;
                double z[3] = {0, 0, 0};  // a gray model fills z[0] alone
                for (std::size_t c = 0; c < C; ++c) z[c] = m.corner_values[f * C + c][std::size_t(i)];
                pos[copy_of_wedge[w]][2] = value(z) * zs;
                if (C > 1) rgb[copy_of_wedge[w]] = {z[0], z[1], z[2]};
                placed[w] = true;
            }
    } else {
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            const auto [x, y] = place(m.vertices[v]);
            pos.push_back({x, y, value(&m.values[v * C]) * zs});
            colour(&m.values[v * C]);
        }
        face_idx = m.faces;
    }

    // Flipping y turns positive orientation in image coordinates into clockwise seen from +z;
    // writing corners 0, 2, 1 restores counter-clockwise (normals up).
    // A hard-edged model says so (its pixels are the surface at their centres, not 4x4 means);
    // soft-edged and basic exports stay as they were.
    // Per-edge kinds (edge_kinds.h) say how many edges are of the other kind.
    const std::string listed = std::to_string(m.kind_exceptions.size());
    const std::string kind = std::string(erd && m.edges == EdgeKind::hard ? "; edges hard: a pixel is the surface at its centre" : "") +
                             (erd && !m.kind_exceptions.empty()
                                  ? (m.edges == EdgeKind::hard ? " (" + listed + " soft edges: the pixels along them are 4x4 means)"
                                                               : "; " + listed + " hard edges: the pixels along them are the surface at their centres")
                                  : "") +
                             (C > 1 ? "; colour: z from BT.601 luma, the vertex colours are the RGB values" : "");
    const std::string frame = world ? "x, y in world units (GeoTIFF)" : "x, y in pixels (y up)";
    // A colour value in [0, 1]: over maxval, or a real model's range.
    const double c_lo = m.real ? m.lo : 0.0, c_span = m.real ? (m.hi > m.lo ? m.hi - m.lo : 1.0) : double(m.maxval);
    // STL and glTF hold floats: world coordinates from the centre of the mesh.
    double x0 = 0, y0 = 0;
    if (world && !pos.empty() && (options.format == MeshFormat::stl || options.format == MeshFormat::glb)) {
        double lx = pos[0][0], hx = lx, ly = pos[0][1], hy = ly;
        for (const auto& q : pos) {
            lx = std::min(lx, q[0]), hx = std::max(hx, q[0]);
            ly = std::min(ly, q[1]), hy = std::max(hy, q[1]);
        }
        x0 = std::floor(0.5 * (lx + hx));
        y0 = std::floor(0.5 * (ly + hy));
        for (auto& q : pos) q[0] -= x0, q[1] -= y0;
    }
    std::size_t facets = 0;
    // Progress over the text lines (vertices, then faces), about every 1%.
    const std::size_t lines = pos.size() + face_idx.size(), every = lines / 100 + 1;
    const auto tick = [&](std::size_t i) {
        if (options.progress && i % every == 0) options.progress("export", double(i) / double(lines));
    };
    // The vertex and face lines of OBJ and PLY: each vertex's position (and, in colour, its RGB
    // values as `scale` writes them), then each face from index `base`, corners 0, 2, 1.
    const auto text_lines = [&](const char* position, const char* colour_format, auto scale, const char* face,
                                std::uint32_t base) {
        for (std::size_t i = 0; i < pos.size(); ++i) {
            tick(i);
            append(out, position, pos[i][0], pos[i][1], pos[i][2]);
            if (C > 1) append(out, colour_format, scale(rgb[i][0]), scale(rgb[i][1]), scale(rgb[i][2]));
            out->push_back('\n');
        }
        for (std::size_t i = 0; i < face_idx.size(); ++i) {
            tick(pos.size() + i);
            append_face(out, face, face_idx[i][0] + base, face_idx[i][2] + base, face_idx[i][1] + base);
        }
    };
    if (options.format == MeshFormat::stl) {
        for (auto& t : face_idx) std::swap(t[1], t[2]);
        char head[81];
        if (world) std::snprintf(head, sizeof head, "erd binary STL: world x - %.0f, y - %.0f (GeoTIFF), z = value * zscale", x0, y0);
        write_stl(pos, face_idx, options.base, world ? std::string(head) : "erd binary STL: x, y in pixels (y up), z = value * zscale", out,
                  &facets);
    } else if (options.format == MeshFormat::glb) {
        std::vector<std::array<std::uint8_t, 3>> colours;
        for (const auto& c : rgb) {
            std::array<std::uint8_t, 3> b{};
            for (int k = 0; k < 3; ++k)
                b[std::size_t(k)] = std::uint8_t(std::min(255.0, std::max(0.0, std::floor((c[std::size_t(k)] - c_lo) * 255.0 / c_span + 0.5))));
            colours.push_back(b);
        }
        GltfMesh g;
        g.positions = &pos;
        g.faces = &face_idx;
        g.colours = C > 1 ? &colours : nullptr;
        g.origin = {x0, y0};
        g.description = "erd mesh: " + frame + ", z = value * " + std::to_string(zs) + kind;
        write_glb(g, out);
    } else if (options.format == MeshFormat::obj) {
        out->reserve(pos.size() * 32 + face_idx.size() * 24 + 256);
        out->append("# erd mesh: " + frame + ", z = value * " + std::to_string(zs) + kind + "\n");
        // Colours as reals in [0, 1] after the position (an extension most OBJ readers take).
        const auto unit = [&](double v) { return std::min(1.0, std::max(0.0, (v - c_lo) / c_span)); };
        text_lines(world ? "v %.12g %.12g %.9g" : "v %.9g %.9g %.9g", " %.6g %.6g %.6g", unit, "f %u %u %u\n", 1);
    } else {
        out->reserve(pos.size() * 32 + face_idx.size() * 24 + 256);
        out->append("ply\nformat ascii 1.0\ncomment erd mesh: " + frame + ", z = value * " + std::to_string(zs) + kind + "\n");
        out->append("element vertex " + std::to_string(pos.size()) + "\nproperty double x\nproperty double y\nproperty double z\n");
        if (C > 1) out->append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
        out->append("element face " + std::to_string(face_idx.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n");
        const auto byte = [&](double v) { return std::min(255.0, std::max(0.0, std::floor((v - c_lo) * 255.0 / c_span + 0.5))); };
        text_lines(world ? "%.12g %.12g %.9g" : "%.9g %.9g %.9g", " %.0f %.0f %.0f", byte, "3 %u %u %u\n", 0);
    }
    if (counts) {
        counts->vertices = pos.size();
        counts->faces = face_idx.size();
        counts->facets = facets;
    }
    return Status::success();
}

}  // namespace erd
