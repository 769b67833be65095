// The merged mesh of `erd tiles` (tiles_merge.h), written as it is made.
#include "cli/tiles_merge.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <unordered_map>
#include <vector>

#include "algorithms/methods/methods.h"
#include "algorithms/model/model.h"
#include "cli/model_file.h"
#include "kernel/file_name.h"

namespace erd::cli {

namespace {

// Bytes to a descriptor through a buffer; the first failure is kept.
class FdOut {
public:
    explicit FdOut(int fd) : fd_(fd) { buf_.reserve(kSize); }
    void put(const void* p, std::size_t n) {
        const char* c = static_cast<const char*>(p);
        buf_.insert(buf_.end(), c, c + n);
        if (buf_.size() >= kSize) flush();
    }
    void text(const char* s) { put(s, std::strlen(s)); }
    void f32(float v) { put(&v, 4); }  // little-endian hosts only (as the STL and glTF writers)
    void u32(std::uint32_t v) { put(&v, 4); }
    bool flush() {
        std::size_t at = 0;
        while (ok_ && at < buf_.size()) {
            const ssize_t k = ::write(fd_, buf_.data() + at, buf_.size() - at);
            if (k < 0 && errno == EINTR) continue;
            if (k <= 0) ok_ = false;
            else at += std::size_t(k);
        }
        buf_.clear();
        return ok_;
    }

private:
    static constexpr std::size_t kSize = std::size_t(1) << 20;
    int fd_;
    bool ok_ = true;
    std::vector<char> buf_;
};

struct Vertex {
    double x, y, z;
};

// One walk over the tiles in task order: each new vertex (in the order of its index) and each face
// (its three indices and corners, counter-clockwise seen from +z). Side vertices are shared by
// their lattice point in the whole raster; the same walk gives the same indices every time.
class Walker {
public:
    Walker(const TilesPlan& plan, const std::string& dir, double zscale) : plan_(plan), dir_(dir), zs_(zscale) {
        const MethodInfo* m = find_method(plan.method);
        ext_ = m && m->model == ModelKind::erd ? ".erd" : ".model";
    }
    Status walk(const std::function<void(const Vertex&)>& on_vertex,
                const std::function<void(const std::uint32_t*, const Vertex*)>& on_face) {
        // Side vertices by lattice point (ERD: and value: a crossing's two sides are two copies).
        std::unordered_map<std::uint64_t, std::vector<std::pair<double, std::uint32_t>>> side;
        std::uint32_t next = 0;
        const int H = plan_.grid.height;
        for (int k = 0; k < plan_.grid.count(); ++k) {
            int x0, y0, x1, y1;
            plan_.window(k, &x0, &y0, &x1, &y1);
            const std::string path = dir_ + "/" + plan_.tile_name(k) + ext_;
            Model m;
            std::string warning;
            Status st = load_model_file(path, &m, &warning);
            if (!st) return Status::bad_input(path + ": " + st.message);
            if (m.width != x1 - x0 + 1 || m.height != y1 - y0 + 1 || m.channels != 1)
                return Status::bad_input(path + ": not the model of this tile (" + std::to_string(x1 - x0 + 1) + " x " +
                                         std::to_string(y1 - y0 + 1) + ", gray)");
            const std::int32_t mx = 2 * (x1 - x0), my = 2 * (y1 - y0);
            const bool erd = m.kind == ModelKind::erd;
            // Per vertex: its copies (value, index) made so far in this tile.
            std::vector<std::vector<std::pair<double, std::uint32_t>>> copies(m.vertices.size());
            auto index_of = [&](std::uint32_t v, double value, Vertex* out) {
                const LatticePoint p = m.vertices[v];
                const std::int64_t gx = 2 * std::int64_t(x0) + p.x, gy = 2 * std::int64_t(y0) + p.y;
                const Vertex here{double(gx) / 2.0, double(H - 1) - double(gy) / 2.0, value * zs_};
                for (const auto& c : copies[v])
                    if (c.first == value) return *out = here, c.second;
                std::uint32_t id;
                const bool on_side = p.x == 0 || p.y == 0 || p.x == mx || p.y == my;
                const std::uint64_t key = std::uint64_t(gy) << 32 | std::uint64_t(gx);
                auto found = on_side ? side.find(key) : side.end();
                const std::pair<double, std::uint32_t>* same = nullptr;
                if (found != side.end())
                    for (const auto& c : found->second)
                        if (!erd || c.first == value) same = &c;
                if (same) {
                    id = same->second;
                } else {
                    id = next++;
                    on_vertex(here);
                    if (on_side) side[key].push_back({value, id});
                }
                copies[v].push_back({value, id});
                *out = here;
                return id;
            };
            for (std::size_t f = 0; f < m.faces.size(); ++f) {
                std::uint32_t ids[3];
                Vertex corners[3];
                // The model's faces are counter-clockwise in (X, Y); y flipped, (a, c, b) is.
                const int order[3] = {0, 2, 1};
                for (int c = 0; c < 3; ++c) {
                    const int k3 = order[c];
                    const std::uint32_t v = m.faces[f][std::size_t(k3)];
                    const double value = erd ? m.corner_values[f][std::size_t(k3)] : m.values[v];
                    ids[c] = index_of(v, value, &corners[c]);
                }
                on_face(ids, corners);
            }
        }
        return Status::success();
    }

private:
    const TilesPlan& plan_;
    std::string dir_, ext_;
    double zs_;
};

std::string g9(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

}  // namespace

bool merge_format_known(const std::string& path) {
    return has_extension(path, ".obj") || has_extension(path, ".ply") || has_extension(path, ".stl") ||
           has_extension(path, ".glb");
}

Status write_merged(const TilesPlan& plan, const std::string& dir, const std::string& path, double zscale, int fd,
                    MergeCounts* counts) {
    Walker walker(plan, dir, zscale);
    FdOut out(fd);
    char line[160];
    MergeCounts n;
    if (has_extension(path, ".obj")) {
        out.text("# erd tiles: merged mesh\n");
        Status st = walker.walk(
            [&](const Vertex& v) {
                std::snprintf(line, sizeof line, "v %s %s %s\n", g9(v.x).c_str(), g9(v.y).c_str(), g9(v.z).c_str());
                out.text(line);
                ++n.vertices;
            },
            [&](const std::uint32_t* id, const Vertex*) {
                std::snprintf(line, sizeof line, "f %u %u %u\n", id[0] + 1, id[1] + 1, id[2] + 1);
                out.text(line);
                ++n.faces;
            });
        if (!st) return st;
    } else {
        // First pass: the counts (and glTF's bounds).
        float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
        float hi[3] = {-lo[0], -lo[1], -lo[2]};
        Status st = walker.walk(
            [&](const Vertex& v) {
                ++n.vertices;
                const float g[3] = {float(v.x), float(v.z), float(-v.y)};  // glTF: y up
                for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], g[c]), hi[c] = std::max(hi[c], g[c]);
            },
            [&](const std::uint32_t*, const Vertex*) { ++n.faces; });
        if (!st) return st;
        auto no_vertex = [](const Vertex&) {};
        auto no_face = [](const std::uint32_t*, const Vertex*) {};
        if (has_extension(path, ".ply")) {
            out.text(("ply\nformat ascii 1.0\ncomment erd tiles: merged mesh\nelement vertex " + std::to_string(n.vertices) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(n.faces) +
                      "\nproperty list uchar int vertex_indices\nend_header\n")
                         .c_str());
            st = walker.walk(
                [&](const Vertex& v) {
                    std::snprintf(line, sizeof line, "%s %s %s\n", g9(v.x).c_str(), g9(v.y).c_str(), g9(v.z).c_str());
                    out.text(line);
                },
                no_face);
            if (st)
                st = walker.walk(no_vertex, [&](const std::uint32_t* id, const Vertex*) {
                    std::snprintf(line, sizeof line, "3 %u %u %u\n", id[0], id[1], id[2]);
                    out.text(line);
                });
        } else if (has_extension(path, ".stl")) {
            char header[80] = {};
            std::snprintf(header, sizeof header, "erd tiles: merged mesh, %llu facets", (unsigned long long)n.faces);
            out.put(header, 80);
            if (n.faces > 0xffffffffull) return Status::bad_input(path + ": more than 2^32 facets for binary STL");
            out.u32(std::uint32_t(n.faces));
            st = walker.walk(no_vertex, [&](const std::uint32_t*, const Vertex* c) {
                const double ux = c[1].x - c[0].x, uy = c[1].y - c[0].y, uz = c[1].z - c[0].z;
                const double vx = c[2].x - c[0].x, vy = c[2].y - c[0].y, vz = c[2].z - c[0].z;
                double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
                const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
                if (len > 0) nx /= len, ny /= len, nz /= len;
                out.f32(float(nx)), out.f32(float(ny)), out.f32(float(nz));
                for (int k = 0; k < 3; ++k) out.f32(float(c[k].x)), out.f32(float(c[k].y)), out.f32(float(c[k].z));
                const std::uint16_t attr = 0;
                out.put(&attr, 2);
            });
        } else if (has_extension(path, ".glb")) {
            if (n.vertices > 0xffffffffull || 3 * n.faces > 0xffffffffull)
                return Status::bad_input(path + ": too large for one glTF buffer of 32-bit indices");
            const std::uint64_t pos_bytes = 12 * n.vertices, idx_bytes = 12 * n.faces, bin = pos_bytes + idx_bytes;
            std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"erd tiles\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
                               "\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
                               "\"mode\":4}]}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":" +
                               std::to_string(n.vertices) + ",\"type\":\"VEC3\",\"min\":[" + g9(lo[0]) + "," + g9(lo[1]) + "," +
                               g9(lo[2]) + "],\"max\":[" + g9(hi[0]) + "," + g9(hi[1]) + "," + g9(hi[2]) +
                               "]},{\"bufferView\":1,\"componentType\":5125,\"count\":" + std::to_string(3 * n.faces) +
                               ",\"type\":\"SCALAR\"}],\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" +
                               std::to_string(pos_bytes) + ",\"target\":34962},{\"buffer\":0,\"byteOffset\":" +
                               std::to_string(pos_bytes) + ",\"byteLength\":" + std::to_string(idx_bytes) +
                               ",\"target\":34963}],\"buffers\":[{\"byteLength\":" + std::to_string(bin) + "}]}";
            while (json.size() % 4) json += ' ';
            const std::uint64_t total = 12 + 8 + json.size() + 8 + bin;
            if (total > 0xffffffffull) return Status::bad_input(path + ": more than 4 GiB for one .glb");
            out.text("glTF");
            out.u32(2);
            out.u32(std::uint32_t(total));
            out.u32(std::uint32_t(json.size()));
            out.u32(0x4E4F534Au);
            out.put(json.data(), json.size());
            out.u32(std::uint32_t(bin));
            out.u32(0x004E4942u);
            st = walker.walk([&](const Vertex& v) { out.f32(float(v.x)), out.f32(float(v.z)), out.f32(float(-v.y)); }, no_face);
            if (st) st = walker.walk(no_vertex, [&](const std::uint32_t* id, const Vertex*) { out.u32(id[0]), out.u32(id[1]), out.u32(id[2]); });
        } else {
            return Status::bad_input(path + ": --merge writes .obj, .ply, .stl or .glb");
        }
        if (!st) return st;
    }
    if (!out.flush()) return Status::failure(path + ": " + std::strerror(errno));
    if (counts) *counts = n;
    return Status::success();
}

}  // namespace erd::cli
