// Readers of .model, .erd, -t and -p files (formats in model_io.h; writers in model_write.cpp).
#include "algorithms/model/model_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model_header.h"
#include "algorithms/model/model_tokens.h"
#include "algorithms/model/model_topology.h"
#include "kernel/file_name.h"
#include "kernel/predicates.h"

namespace erd {
namespace {

using namespace model_text;

std::string vname(std::size_t i) { return "vertex " + std::to_string(i); }

// Every vertex must be a corner of some face: a vertex in no face would be accepted, drawn and
// exported as if it belonged to the mesh although nothing of the surface depends on it.
Status check_all_used(const std::vector<LatticePoint>& pts, const std::vector<std::array<std::uint32_t, 3>>& faces,
                      const std::vector<int>& lines, int unit) {
    std::vector<std::uint8_t> used(pts.size(), 0);
    for (const auto& f : faces)
        for (std::uint32_t v : f) used[v] = 1;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!used[i])
            return Status::bad_input("line " + std::to_string(lines[i]) + ": " + vname(i) + " (" + std::to_string(pts[i].x / unit) +
                                     ", " + std::to_string(pts[i].y / unit) + ") belongs to no face");
    return Status::success();
}
std::string fname(std::size_t i) { return "face " + std::to_string(i); }

// Faces: indices in range, three distinct vertices, nonzero area; orientation made positive
// (with the ERD corner values, if any, swapped along).
Status read_faces(Tokens& tk, const std::vector<LatticePoint>& pts, std::vector<std::array<std::uint32_t, 3>>* faces,
                  std::vector<int>* lines) {
    std::uint64_t nf = 0;
    if (Status s = count(tk, "face count", 1, 6, &nf); !s) return s;
    reserve_arriving(faces, nf);
    reserve_arriving(lines, nf);
    const std::uint64_t nv = pts.size();
    for (std::uint64_t f = 0; f < nf; ++f) {
        std::array<std::uint32_t, 3> fc{};
        for (int k = 0; k < 3; ++k) {
            std::uint64_t v = 0;
            const auto what = [&] { return "vertex index " + std::to_string(k + 1) + " of " + fname(f); };
            if (Status s = tk.uint(what, 0, std::uint64_t(1) << 40, &v); !s) return s;
            if (v >= nv)
                return Status::bad_input(tk.where() + fname(f) + ": vertex index " + std::to_string(v) + " out of range (" +
                                         std::to_string(nv) + " vertices)");
            fc[std::size_t(k)] = std::uint32_t(v);
        }
        lines->push_back(tk.line());
        if (fc[0] == fc[1] || fc[1] == fc[2] || fc[0] == fc[2])
            return Status::bad_input(tk.where() + fname(f) + " repeats a vertex");
        const std::int64_t o = orient2d(pts[fc[0]], pts[fc[1]], pts[fc[2]]);
        if (o == 0) return Status::bad_input(tk.where() + fname(f) + " is degenerate (its vertices are collinear)");
        if (o < 0) std::swap(fc[1], fc[2]);
        faces->push_back(fc);
    }
    return Status::success();
}

// Distinct vertices; the domain [0, max] with its four corners as vertices; size limits.
// `unit` converts doubled coordinates back to those of the file for messages (2 for .model).
Status check_vertices(const std::vector<LatticePoint>& pts, const std::vector<int>& lines, bool need_even, int unit, int* w,
                      int* h) {
    const auto at = [unit](LatticePoint p) { return "(" + std::to_string(p.x / unit) + ", " + std::to_string(p.y / unit) + ")"; };
    std::vector<std::uint32_t> order(pts.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return pts[a].y != pts[b].y ? pts[a].y < pts[b].y : pts[a].x != pts[b].x ? pts[a].x < pts[b].x : a < b;
    });
    for (std::size_t i = 1; i < order.size(); ++i)
        if (pts[order[i]] == pts[order[i - 1]])
            return Status::bad_input("line " + std::to_string(lines[order[i]]) + ": vertices " + std::to_string(order[i - 1]) +
                                     " and " + std::to_string(order[i]) + " coincide at " + at(pts[order[i]]));
    std::int32_t mx = 0, my = 0;
    for (const LatticePoint& p : pts) {
        mx = std::max(mx, p.x);
        my = std::max(my, p.y);
    }
    if (need_even && (mx % 2 != 0 || my % 2 != 0))
        return Status::bad_input("the largest coordinates (" + std::to_string(mx) + ", " + std::to_string(my) +
                                 ") are not even: the domain [0, 2W-2] x [0, 2H-2] must end on a pixel");
    const LatticePoint corners[4] = {{0, 0}, {mx, 0}, {0, my}, {mx, my}};
    for (const LatticePoint& c : corners) {
        const auto it = std::lower_bound(order.begin(), order.end(), c, [&](std::uint32_t a, LatticePoint p) {
            return pts[a].y != p.y ? pts[a].y < p.y : pts[a].x < p.x;
        });
        if (it == order.end() || pts[*it] != c)
            return Status::bad_input("corner " + at(c) + " of the image domain is not a vertex");
    }
    *w = mx / 2 + 1;
    *h = my / 2 + 1;
    if (std::int64_t(*w) * *h > kMaxImagePixels)
        return Status::bad_input("image " + std::to_string(*w) + " x " + std::to_string(*h) + " is larger than the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    return Status::success();
}

// A model with holes (header "holes W H"): distinct vertices inside [0, 2W-2] x [0, 2H-2].
Status check_inside(const std::vector<LatticePoint>& pts, const std::vector<int>& lines, int unit, int w, int h) {
    std::vector<std::uint64_t> keys(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const LatticePoint p = pts[i];
        if (p.x > 2 * w - 2 || p.y > 2 * h - 2)
            return Status::bad_input("line " + std::to_string(lines[i]) + ": " + vname(i) + " (" + std::to_string(p.x / unit) + ", " +
                                     std::to_string(p.y / unit) + ") lies outside the " + std::to_string(w) + " x " + std::to_string(h) +
                                     " image of the header");
        keys[i] = (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (keys[i] == keys[i - 1]) return Status::bad_input("two vertices coincide at (" + std::to_string(std::uint32_t(keys[i]) / std::uint32_t(unit)) + ", " + std::to_string(std::uint32_t(keys[i] >> 32) / std::uint32_t(unit)) + ")");
    return Status::success();
}

// Assigns the corner values of an ERD model from its wedge lines (see model_io.h), in every
// channel: a wedge line carries one value per channel, and the fan propagation below moves all
// channels of a corner together.
Status apply_wedges(Tokens& tk, const ModelTopology& topo, Model* m) {
    const std::size_t nv = m->vertices.size(), nf = m->faces.size(), C = std::size_t(m->channels);
    std::uint64_t nw = 0;
    if (Status s = count(tk, "wedge count", 0, 4 + 2 * C, &nw); !s) return s;
    m->corner_values.assign(nf * C, {0.0, 0.0, 0.0});
    // The value of corner h (half-edge 3f + k) in channel c.
    const auto cv = [&](std::size_t h, std::size_t c) -> double& { return m->corner_values[h / 3 * C + c][h % 3]; };
    std::vector<std::uint8_t> set(3 * nf, 0);
    std::vector<std::uint8_t> listed(nv, 0);
    double z[3] = {0.0, 0.0, 0.0};
    for (std::uint64_t i = 0; i < nw; ++i) {
        std::uint64_t v = 0, f = 0;
        if (Status s = tk.uint([&] { return "vertex index of wedge line " + std::to_string(i); }, 0, std::uint64_t(1) << 40, &v); !s) return s;
        if (v >= nv)
            return Status::bad_input(tk.where() + "wedge line " + std::to_string(i) + ": vertex index " + std::to_string(v) +
                                     " out of range (" + std::to_string(nv) + " vertices)");
        if (Status s = tk.uint([&] { return "face index of wedge line " + std::to_string(i); }, 0, std::uint64_t(1) << 40, &f); !s) return s;
        if (f >= nf)
            return Status::bad_input(tk.where() + "wedge line " + std::to_string(i) + ": face index " + std::to_string(f) +
                                     " out of range (" + std::to_string(nf) + " faces)");
        const auto record = [&] { return "wedge line " + std::to_string(i); };
        if (Status s = channel_values(tk, record, "wedge value", m->channels, z); !s) return s;
        int k = -1;
        for (int c = 0; c < 3; ++c)
            if (m->faces[f][std::size_t(c)] == v) k = c;
        if (k < 0)
            return Status::bad_input(tk.where() + "wedge line " + std::to_string(i) + ": face " + std::to_string(f) +
                                     " is not incident on vertex " + std::to_string(v));
        const std::size_t h = 3 * f + std::size_t(k);
        bool same = true;
        for (std::size_t c = 0; c < C; ++c) same = same && cv(h, c) == z[c];
        if (set[h] && !same)
            return Status::bad_input(tk.where() + "wedge line " + std::to_string(i) + ": conflicting values for vertex " +
                                     std::to_string(v) + " in face " + std::to_string(f));
        set[h] = 1;
        listed[v] = 1;
        for (std::size_t c = 0; c < C; ++c) cv(h, c) = z[c];
    }
    std::vector<std::uint32_t> fan;
    for (std::uint32_t v = 0; v < nv; ++v) {
        const std::uint32_t b = topo.corner_begin[v], e = topo.corner_begin[v + 1];
        if (!listed[v]) {
            for (std::uint32_t i = b; i < e; ++i)
                for (std::size_t c = 0; c < C; ++c) cv(topo.corners[i], c) = m->values[v * C + c];
            continue;
        }
        bool complete = true;
        for (std::uint32_t i = b; i < e; ++i) complete = complete && set[topo.corners[i]];
        if (complete) continue;
        // Propagate along the fan: a face takes the values of the nearest listed faces when both
        // sides agree (in every channel), or when only one side exists, at the open end of a
        // border fan.
        bool closed = false;
        std::uint32_t missing = 0;
        for (std::uint32_t i = b; i < e; ++i)
            if (!set[topo.corners[i]]) missing = topo.corners[i] / 3;
        const auto undetermined = [&](std::uint32_t face) {
            return Status::bad_input("the wedge of face " + std::to_string(face) + " at vertex " + std::to_string(v) +
                                     " is undetermined (give a wedge line for every face of a vertex with several wedges)");
        };
        if (!vertex_fan(topo, v, &fan, &closed)) return undetermined(missing);
        const int n = int(fan.size());
        std::vector<double> val(std::size_t(n) * C, 0.0);
        for (int i = 0; i < n; ++i)
            for (std::size_t c = 0; c < C; ++c) val[std::size_t(i) * C + c] = cv(fan[std::size_t(i)], c);
        const auto agree = [&](int x, int y) {
            for (std::size_t c = 0; c < C; ++c)
                if (val[std::size_t(x) * C + c] != val[std::size_t(y) * C + c]) return false;
            return true;
        };
        for (int i = 0; i < n; ++i) {
            const std::uint32_t corner = fan[std::size_t(i)];
            if (set[corner]) continue;
            int before = -1, after = -1;
            for (int d = 1; d < n; ++d) {
                const int j = i - d;
                if (j < 0 && !closed) break;
                const int jj = (j + n) % n;
                if (set[fan[std::size_t(jj)]]) {
                    before = jj;
                    break;
                }
            }
            for (int d = 1; d < n; ++d) {
                const int j = i + d;
                if (j >= n && !closed) break;
                const int jj = j % n;
                if (set[fan[std::size_t(jj)]]) {
                    after = jj;
                    break;
                }
            }
            int from = -1;
            if (before >= 0 && after >= 0 && agree(before, after)) from = before;
            else if (before >= 0 && after < 0) from = before;
            else if (after >= 0 && before < 0) from = after;
            else return undetermined(corner / 3);
            for (std::size_t c = 0; c < C; ++c) cv(corner, c) = val[std::size_t(from) * C + c];
        }
        for (int i = 0; i < n; ++i) set[fan[std::size_t(i)]] = 1;
    }
    // The vertex value of a vertex with wedge lines is the mean of its wedge values; the
    // constraints are the edges across which values jump.
    for (std::uint32_t v = 0; v < nv; ++v)
        if (listed[v])
            for (std::size_t c = 0; c < C; ++c) m->values[v * C + c] = vertex_wedges(*m, topo, v, int(c)).mean;
    m->constraints.clear();
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h)
        if (topo.twin[h] != kNoHalfEdge && h < topo.twin[h] && is_discontinuity(*m, topo, h)) {
            std::uint32_t a = m->faces[h / 3][h % 3], c = m->faces[h / 3][(h + 1) % 3];
            if (a > c) std::swap(a, c);
            m->constraints.push_back({a, c});
        }
    std::sort(m->constraints.begin(), m->constraints.end());
    return Status::success();
}

}  // namespace

// The n edge lines after the wedge lines ("i j": a discontinuity edge of the other kind than the
// model's, hard-edges / soft-edges in the header) into m->kind_exceptions, sorted.
Status read_edge_lines(Tokens& tk, const ModelTopology& topo, std::uint64_t n, Model* m) {
    m->kind_exceptions.clear();
    if (n == 0) return Status::success();
    const std::uint64_t nv = m->vertices.size();
    std::vector<std::pair<std::array<std::uint32_t, 2>, int>> lines;  // the pair and its line
    reserve_arriving(&lines, n);
    for (std::uint64_t i = 0; i < n; ++i) {
        std::uint64_t v[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            if (Status s = tk.uint([&] { return std::string(k ? "second" : "first") + " vertex index of edge line " + std::to_string(i); }, 0,
                                   std::uint64_t(1) << 40, &v[k]);
                !s)
                return s;
            if (v[k] >= nv)
                return Status::bad_input(tk.where() + "edge line " + std::to_string(i) + ": vertex index " + std::to_string(v[k]) +
                                         " out of range (" + std::to_string(nv) + " vertices)");
        }
        lines.push_back({{std::uint32_t(std::min(v[0], v[1])), std::uint32_t(std::max(v[0], v[1]))}, tk.line()});
    }
    std::sort(lines.begin(), lines.end());
    std::vector<std::array<std::uint32_t, 2>> disc;
    for (std::uint32_t h = 0; h < topo.twin.size(); ++h)
        if (topo.twin[h] != kNoHalfEdge && h < topo.twin[h] && is_discontinuity(*m, topo, h)) {
            const std::uint32_t a = m->faces[h / 3][h % 3], b = m->faces[h / 3][(h + 1) % 3];
            disc.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(disc.begin(), disc.end());
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto& e = lines[i].first;
        const std::string edge = "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]);
        if (i > 0 && lines[i - 1].first == e)
            return Status::bad_input("line " + std::to_string(lines[i].second) + ": " + edge + " is listed twice");
        if (!std::binary_search(disc.begin(), disc.end(), e))
            return Status::bad_input("line " + std::to_string(lines[i].second) + ": " + edge +
                                     " is not a discontinuity of the model (no edge of a face, or equal values on both sides)");
        m->kind_exceptions.push_back(e);
    }
    return Status::success();
}

Status require_gray(const Model& m, const std::string& what) {
    if (m.channels == 1) return Status::success();
    return Status::bad_input("a colour model (channels " + std::to_string(m.channels) + "): " + what + " handles gray models only");
}

ModelFileKind model_kind_from_name(const std::string& name) {
    if (has_extension(name, ".model")) return ModelFileKind::basic;
    if (has_extension(name, ".erd")) return ModelFileKind::erd;
    if (has_extension(name, ".tri")) return ModelFileKind::triangulation;
    return ModelFileKind::unknown;
}

Status read_model(const std::string& text, ModelFileKind kind, Model* out, ModelTopology* topo_out) {
    if (kind == ModelFileKind::triangulation) return read_triangulation(text, out);
    Tokens tk(text);
    if (tk.at_end()) return Status::bad_input("empty file");
    Model m;
    HeaderFacts header;
    if (tk.peek_is("erd-header"))
        if (Status s = read_header(tk, &m, &header); !s) return s;
    const int edges_line = header.edges_line ? header.edges_line : header.listed_line;
    std::uint64_t maxval = 0, nv = 0;
    // A real model (header "range") has maxval 0 and values of any finite size.
    if (Status s = header.range ? tk.uint("maxval (0 for a real model)", 0, 0, &maxval) : tk.uint("maxval", 1, 65535, &maxval); !s) return s;
    if (header.range) tk.allow_any_finite();
    if (header.range && !header.type) m.meta.type = SampleType::f64;  // a real model of unknown type keeps every digit
    m.maxval = std::uint32_t(maxval);
    if (Status s = count(tk, "vertex count", 4, 4 + 2 * std::uint64_t(m.channels), &nv); !s) return s;
    const std::size_t C = std::size_t(m.channels);
    reserve_arriving(&m.vertices, nv);
    reserve_arriving(&m.values, nv * C);
    std::vector<int> vlines;
    reserve_arriving(&vlines, nv);
    for (std::uint64_t i = 0; i < nv; ++i) {
        std::int64_t x = 0, y = 0;
        double value[3] = {0.0, 0.0, 0.0};
        if (Status s = tk.sint([&] { return "x coordinate of " + vname(i); }, 0, kMaxDoubled, &x); !s) return s;
        if (Status s = tk.sint([&] { return "y coordinate of " + vname(i); }, 0, kMaxDoubled, &y); !s) return s;
        if (Status s = channel_values(tk, [&] { return vname(i); }, "value", m.channels, value); !s) return s;
        m.vertices.push_back(LatticePoint{std::int32_t(x), std::int32_t(y)});
        m.values.insert(m.values.end(), value, value + C);
        vlines.push_back(tk.line());
    }
    std::vector<int> flines;
    if (Status s = read_faces(tk, m.vertices, &m.faces, &flines); !s) return s;
    if (kind == ModelFileKind::unknown) kind = tk.at_end() ? ModelFileKind::basic : ModelFileKind::erd;
    if (kind == ModelFileKind::basic) {
        m.kind = ModelKind::basic;
        if (edges_line)
            return Status::bad_input("line " + std::to_string(edges_line) + ": header key '" + (header.edges_line ? "edges" : header.listed_kind == EdgeKind::hard ? "hard-edges" : "soft-edges") +
                                     "' is for .erd files only");
        if (Status s = expect_end(tk, "face"); !s) return s;
        // Pixel coordinates in the file, doubled in the model (doubled already with "doubled").
        for (std::size_t i = 0; i < nv && !header.doubled; ++i) {
            LatticePoint& p = m.vertices[i];
            if (p.x > kMaxImageSide - 1 || p.y > kMaxImageSide - 1)
                return Status::bad_input("line " + std::to_string(vlines[i]) + ": " + vname(i) + " (" + std::to_string(p.x) +
                                         ", " + std::to_string(p.y) + ") outside the image (0.." +
                                         std::to_string(kMaxImageSide - 1) + ")");
            p = LatticePoint{2 * p.x, 2 * p.y};
        }
    } else {
        m.kind = ModelKind::erd;
    }
    const bool erd = m.kind == ModelKind::erd;
    const int unit = erd || header.doubled ? 1 : 2;
    if (header.holes) {
        // The size is the header's; the vertices need only lie in it, the corners need not be there.
        if (Status s = check_inside(m.vertices, vlines, unit, m.width, m.height); !s) return s;
    } else if (Status s = check_vertices(m.vertices, vlines, erd || header.doubled, unit, &m.width, &m.height); !s) {
        return s;
    }
    // Faces sharing a directed edge: the same triangle twice, or overlapping faces.
    ModelTopology topo;
    if (Status s = build_topology(m, &topo); !s) {
        for (std::size_t f = 0; f < m.faces.size(); ++f)
            for (std::size_t g = f + 1; g < m.faces.size() && s.message.find("faces " + std::to_string(f) + " and ") == 0; ++g) {
                auto x = m.faces[f], y = m.faces[g];
                std::sort(x.begin(), x.end());
                std::sort(y.begin(), y.end());
                if (x == y)
                    return Status::bad_input("line " + std::to_string(flines[g]) + ": faces " + std::to_string(f) + " and " +
                                             std::to_string(g) + " are the same triangle");
            }
        return Status::bad_input("not a triangulation of the image domain: " + s.message);
    }
    if (Status s = check_all_used(m.vertices, m.faces, vlines, unit); !s) return s;
    if (m.kind == ModelKind::erd) {
        if (Status s = apply_wedges(tk, topo, &m); !s) return s;
        if (Status s = read_edge_lines(tk, topo, header.listed, &m); !s) return s;
        if (Status s = expect_end(tk, header.listed ? "edge line" : "wedge line"); !s) return s;
    }
    *out = std::move(m);
    if (topo_out) *topo_out = std::move(topo);
    return Status::success();
}

Status read_triangulation(const std::string& text, Model* out) {
    Tokens tk(text);
    if (Status s = expect_magic(tk, "erd-triangulation", "an erd triangulation file"); !s) return s;
    std::uint64_t w = 0, h = 0, nv = 0, nc = 0;
    if (Status s = tk.uint("width", 2, kMaxImageSide, &w); !s) return s;
    if (Status s = tk.uint("height", 2, kMaxImageSide, &h); !s) return s;
    if (std::int64_t(w * h) > kMaxImagePixels)
        return Status::bad_input(tk.where() + "image " + std::to_string(w) + " x " + std::to_string(h) + " is larger than the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    Model m;
    m.width = int(w);
    m.height = int(h);
    if (Status s = count(tk, "vertex count", 4, 4, &nv); !s) return s;
    reserve_arriving(&m.vertices, nv);
    std::vector<int> vlines;
    reserve_arriving(&vlines, nv);
    for (std::uint64_t i = 0; i < nv; ++i) {
        std::int64_t x = 0, y = 0;
        if (Status s = tk.sint([&] { return "x coordinate of " + vname(i); }, 0, std::int64_t(2 * w - 2), &x); !s) return s;
        if (Status s = tk.sint([&] { return "y coordinate of " + vname(i); }, 0, std::int64_t(2 * h - 2), &y); !s) return s;
        m.vertices.push_back(LatticePoint{std::int32_t(x), std::int32_t(y)});
        vlines.push_back(tk.line());
    }
    std::vector<int> flines;
    if (Status s = read_faces(tk, m.vertices, &m.faces, &flines); !s) return s;
    int cw = 0, ch = 0;
    if (Status s = check_vertices(m.vertices, vlines, true, 1, &cw, &ch); !s) return s;
    if (cw != m.width || ch != m.height)
        return Status::bad_input("the vertices span " + std::to_string(cw) + " x " + std::to_string(ch) + " pixels, not the " +
                                 std::to_string(w) + " x " + std::to_string(h) + " of the header");
    if (Status s = count(tk, "constraint count", 0, 4, &nc); !s) return s;
    std::vector<std::uint64_t> edges;
    edges.reserve(3 * m.faces.size());
    for (const auto& f : m.faces)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
            edges.push_back((std::min(a, b) << 32) | std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    reserve_arriving(&m.constraints, nc);
    for (std::uint64_t i = 0; i < nc; ++i) {
        std::uint64_t a = 0, b = 0;
        if (Status s = tk.uint([&] { return "first vertex index of constraint " + std::to_string(i); }, 0, std::uint64_t(1) << 40, &a); !s) return s;
        if (Status s = tk.uint([&] { return "second vertex index of constraint " + std::to_string(i); }, 0, std::uint64_t(1) << 40, &b); !s) return s;
        if (a >= nv || b >= nv)
            return Status::bad_input(tk.where() + "constraint " + std::to_string(i) + ": vertex index out of range (" +
                                     std::to_string(nv) + " vertices)");
        if (a > b) std::swap(a, b);
        if (!std::binary_search(edges.begin(), edges.end(), (a << 32) | b))
            return Status::bad_input(tk.where() + "constraint " + std::to_string(i) + " (" + std::to_string(a) + ", " +
                                     std::to_string(b) + ") is not an edge of any face");
        m.constraints.push_back({std::uint32_t(a), std::uint32_t(b)});
    }
    if (Status s = expect_end(tk, "constraint"); !s) return s;
    if (Status s = check_all_used(m.vertices, m.faces, vlines, 1); !s) return s;
    std::sort(m.constraints.begin(), m.constraints.end());
    m.kind = ModelKind::basic;
    *out = std::move(m);
    return Status::success();
}

Status read_polylines(const std::string& text, std::vector<std::vector<LatticePoint>>* out) {
    Tokens tk(text);
    if (Status s = expect_magic(tk, "erd-polylines", "an erd polylines file"); !s) return s;
    std::uint64_t np = 0;
    if (Status s = count(tk, "polyline count", 0, 2, &np); !s) return s;
    std::vector<std::vector<LatticePoint>> lines(np);
    for (std::uint64_t i = 0; i < np; ++i) {
        const auto name = [i] { return "polyline " + std::to_string(i); };
        std::uint64_t n = 0;
        if (Status s = count(tk, [&] { return "point count of " + name(); }, 0, 4, &n); !s) return s;
        lines[i].resize(n);
        for (std::uint64_t k = 0; k < n; ++k) {
            std::int64_t x = 0, y = 0;
            const auto point = [&] { return "point " + std::to_string(k) + " of " + name(); };
            if (Status s = tk.sint([&] { return "x coordinate of " + point(); }, 0, kMaxDoubled, &x); !s) return s;
            if (Status s = tk.sint([&] { return "y coordinate of " + point(); }, 0, kMaxDoubled, &y); !s) return s;
            lines[i][k] = LatticePoint{std::int32_t(x), std::int32_t(y)};
        }
    }
    if (Status s = expect_end(tk, "polyline"); !s) return s;
    *out = std::move(lines);
    return Status::success();
}

}  // namespace erd
