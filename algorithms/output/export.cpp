#include "algorithms/output/export.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include "algorithms/model/model_topology.h"

namespace erd {

double default_zscale(const Model& m) {
    double side = double(std::max(m.width, m.height));
    return side / (10.0 * double(m.maxval == 0 ? 1 : m.maxval));
}

namespace {

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

}  // namespace

Status export_mesh(const Model& m, const ExportOptions& options, std::string* out, ExportCounts* counts) {
    out->clear();
    if (m.values.empty() && !m.vertices.empty())
        return Status::bad_input("the mesh has no sample values (a triangulation file?): export the .model or .erd");
    if (m.values.size() != m.vertices.size()) return Status::bad_input("model has " + std::to_string(m.vertices.size()) +
                                                                       " vertices but " + std::to_string(m.values.size()) + " values");
    const bool erd = m.kind == ModelKind::erd;
    if (erd && m.corner_values.size() != m.faces.size())
        return Status::bad_input("ERD model without a value for every face corner");
    ModelTopology topo;
    if (Status st = build_topology(m, &topo); !st) return st;
    const double zs = options.zscale > 0 ? options.zscale : default_zscale(m);
    const double top = double(m.height - 1);

    // Positions of the written vertices and each face's three indices into them.
    std::vector<std::array<double, 3>> pos;
    std::vector<std::array<std::uint32_t, 3>> face_idx(m.faces.size());
    if (erd) {
        const CornerWedges cw = corner_wedges(m, topo);
        // A vertex without faces still gets written once, so no input vertex vanishes silently.
        std::vector<std::uint32_t> copy_of_wedge(cw.count);
        std::vector<bool> placed(cw.count, false);
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            double x = m.vertices[v].x / 2.0, y = top - m.vertices[v].y / 2.0;
            if (cw.first[v] == cw.first[v + 1]) { pos.push_back({x, y, m.values[v] * zs}); continue; }
            for (std::uint32_t w = cw.first[v]; w < cw.first[v + 1]; ++w) {
                copy_of_wedge[w] = std::uint32_t(pos.size());
                pos.push_back({x, y, 0});
            }
        }
        for (std::size_t f = 0; f < m.faces.size(); ++f)
            for (int i = 0; i < 3; ++i) {
                std::uint32_t w = cw.label[3 * f + std::size_t(i)];
                face_idx[f][std::size_t(i)] = copy_of_wedge[w];
                if (!placed[w]) { pos[copy_of_wedge[w]][2] = m.corner_values[f][std::size_t(i)] * zs; placed[w] = true; }
            }
    } else {
        for (std::size_t v = 0; v < m.vertices.size(); ++v)
            pos.push_back({m.vertices[v].x / 2.0, top - m.vertices[v].y / 2.0, m.values[v] * zs});
        face_idx = m.faces;
    }

    // Flipping y turns positive orientation in image coordinates into clockwise seen from +z;
    // writing corners 0, 2, 1 restores counter-clockwise (normals up).
    out->reserve(pos.size() * 32 + face_idx.size() * 24 + 256);
    // A hard-edged model says so (its pixels are the surface at their centres, not 4x4 means);
    // soft-edged and basic exports stay as they were.
    const std::string kind = erd && m.edges == EdgeKind::hard ? "; edges hard: a pixel is the surface at its centre" : "";
    if (options.format == MeshFormat::obj) {
        out->append("# erd mesh: x, y in pixels (y up), z = value * " + std::to_string(zs) + kind + "\n");
        for (const auto& p : pos) append(out, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
        for (const auto& t : face_idx) append_face(out, "f %u %u %u\n", t[0] + 1, t[2] + 1, t[1] + 1);
    } else {
        out->append("ply\nformat ascii 1.0\ncomment erd mesh: x, y in pixels (y up), z = value * " + std::to_string(zs) + kind + "\n");
        out->append("element vertex " + std::to_string(pos.size()) + "\nproperty double x\nproperty double y\nproperty double z\n");
        out->append("element face " + std::to_string(face_idx.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n");
        for (const auto& p : pos) append(out, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
        for (const auto& t : face_idx) append_face(out, "3 %u %u %u\n", t[0], t[2], t[1]);
    }
    if (counts) {
        counts->vertices = pos.size();
        counts->faces = face_idx.size();
    }
    return Status::success();
}

}  // namespace erd
