// The .erdz container: header, the three sections, and the encoder's search for the constraint
// set that makes the rebuilt triangulation the model's own (erdz.h).
#include "algorithms/codec/erdz.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

#include "algorithms/codec/erdz_rebuild.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model_topology.h"

namespace erd {
namespace {

using codec::Chain;
using codec::Rebuilt;

constexpr char kMagic[4] = {'E', 'R', 'D', 'Z'};
// 2 added the flips section, 3 the warm bit models and new contexts (erdz.h); all are read.
constexpr int kVersion = codec::kErdzVersion;
constexpr std::size_t kMaxMethod = 32;

void put_varint(std::string* out, std::uint64_t v) {
    while (v >= 0x80) {
        out->push_back(char((v & 0x7F) | 0x80));
        v >>= 7;
    }
    out->push_back(char(v));
}

struct Reader {
    const std::string& s;
    std::size_t pos = 0;
    bool varint(std::uint64_t* v) {
        *v = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            if (pos >= s.size()) return false;
            const std::uint8_t b = std::uint8_t(s[pos++]);
            *v |= std::uint64_t(b & 0x7F) << shift;
            if (!(b & 0x80)) return shift < 63 || b <= 1;
        }
        return false;
    }
};

// Version 1 had no flips section, version 4 adds the kinds section.
int section_count(int version) { return version == 1 ? 3 : version == 4 ? 5 : 4; }

bool method_ok(const std::string& name) {
    if (name.size() > kMaxMethod) return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
    return true;
}

std::uint64_t key(LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); }

using FaceKey = std::array<std::uint64_t, 3>;
FaceKey face_key(LatticePoint a, LatticePoint b, LatticePoint c) {
    FaceKey k{key(a), key(b), key(c)};
    std::sort(k.begin(), k.end());
    return k;
}
using EdgeKey = std::pair<std::uint64_t, std::uint64_t>;
EdgeKey edge_key(LatticePoint a, LatticePoint b) { return std::minmax(key(a), key(b)); }

Status check_model(const Model& m) {
    if (m.width < 2 || m.height < 2 || m.width > kMaxImageSide || m.height > kMaxImageSide)
        return Status::bad_input("the model's image size " + std::to_string(m.width) + " x " + std::to_string(m.height) +
                                 " is out of range");
    if (m.channels != 1 && m.channels != 3) return Status::bad_input("a model has 1 or 3 channels");
    if (m.real || m.holes)
        return Status::bad_input("a model of a real-valued image (or one with nodata) is not held by .erdz: write .erd or .model");
    if (m.maxval < 1 || m.maxval > 65535) return Status::bad_input("maxval out of range");
    const std::size_t C = std::size_t(m.channels);
    if (m.values.size() != m.vertices.size() * C) return Status::bad_input("the model has the wrong number of values");
    if (m.kind == ModelKind::erd && m.corner_values.size() != m.faces.size() * C)
        return Status::bad_input("the model has the wrong number of corner values");
    const std::int32_t mx = 2 * m.width - 2, my = 2 * m.height - 2;
    int corners = 0;
    for (const LatticePoint p : m.vertices) {
        if (p.x < 0 || p.y < 0 || p.x > mx || p.y > my) return Status::bad_input("a vertex lies outside the image");
        if (m.kind == ModelKind::basic && (p.x % 2 || p.y % 2))
            return Status::bad_input("a basic model's vertex is off the integer lattice");
        corners += (p.x == 0 || p.x == mx) && (p.y == 0 || p.y == my);
    }
    if (corners != 4) return Status::bad_input("the four corners of the image must be vertices, once each");
    const auto finite = [](double v) { return std::isfinite(v) && std::fabs(v) <= 1e9; };
    for (double v : m.values)
        if (!finite(v)) return Status::bad_input("a value is not finite or above 1e9");
    for (const auto& c : m.corner_values)
        for (double v : c)
            if (!finite(v)) return Status::bad_input("a corner value is not finite or above 1e9");
    return Status::success();
}

// How many of the model's edges segment a-b (model vertices, no vertex inside the segment)
// crosses: 0 when it is one of them. Walks the model's faces along the segment; `limit` (or more)
// when it crosses that many or the faces are not a triangulation along it.
std::size_t crossings(const Model& m, const ModelTopology& t, std::uint32_t a, std::uint32_t b, std::size_t limit) {
    const LatticePoint pa = m.vertices[a], pb = m.vertices[b];
    const auto vert = [&](std::uint32_t h) { return m.faces[h / 3][h % 3]; };
    std::uint32_t h = kNoHalfEdge;  // the edge through which a-b leaves the face at a it starts in
    for (std::uint32_t i = t.corner_begin[a]; i < t.corner_begin[a + 1]; ++i) {
        const std::uint32_t c = t.corners[i], w1 = vert(ModelTopology::next(c)), w2 = vert(ModelTopology::prev(c));
        if (w1 == b || w2 == b) return 0;
        if (orient2d(pa, m.vertices[w1], pb) > 0 && orient2d(pa, m.vertices[w2], pb) < 0) h = ModelTopology::next(c);
    }
    if (h == kNoHalfEdge) return limit;
    for (std::size_t n = 1; n < limit; ++n) {
        // h (w1 -> w2) is the n-th edge crossed; its twin o runs w2 -> w1 in the next face, whose
        // third vertex x the segment passes on w1's side or on w2's.
        const std::uint32_t o = t.twin[h];
        if (o == kNoHalfEdge) return limit;
        const std::uint32_t x = vert(ModelTopology::prev(o));
        if (x == b) return n;
        const std::int64_t sx = orient2d(pa, pb, m.vertices[x]), s1 = orient2d(pa, pb, m.vertices[vert(ModelTopology::next(o))]);
        if (sx == 0) return limit;
        h = (sx > 0) == (s1 > 0) ? ModelTopology::prev(o) : ModelTopology::next(o);
    }
    return limit;
}

// The free points and chains of the constraint set `edges`.
void split_points(const Model& m, const std::vector<EdgeKey>& edges, std::vector<LatticePoint>* free_points,
                  std::vector<Chain>* chains) {
    std::vector<std::array<LatticePoint, 2>> segs;
    std::vector<std::uint64_t> on_edge;
    const auto point = [](std::uint64_t k) { return LatticePoint{std::int32_t(k & 0xFFFFFFFFu), std::int32_t(k >> 32)}; };
    for (const EdgeKey& e : edges) {
        segs.push_back({point(e.first), point(e.second)});
        on_edge.push_back(e.first);
        on_edge.push_back(e.second);
    }
    std::sort(on_edge.begin(), on_edge.end());
    *chains = codec::make_chains(segs);
    free_points->clear();
    const std::int32_t mx = 2 * m.width - 2, my = 2 * m.height - 2;
    for (const LatticePoint p : m.vertices) {
        if ((p.x == 0 || p.x == mx) && (p.y == 0 || p.y == my)) continue;
        if (std::binary_search(on_edge.begin(), on_edge.end(), key(p))) continue;
        free_points->push_back(p);
    }
}

void fill_info(int version, const std::string& method, double step, bool full, std::size_t header,
               std::array<std::size_t, 5> sections, std::size_t total, const std::vector<LatticePoint>& free_points,
               const std::vector<Chain>& chains, std::uint64_t flips, std::size_t values, std::size_t kinds, ErdzInfo* info) {
    *info = ErdzInfo();
    info->version = version;
    info->method = method;
    info->step = step;
    info->full_lattice = full;
    info->header_bits = 8 * header;
    info->position_bits = 8 * sections[0];
    info->edge_bits = 8 * sections[1];
    info->flip_bits = 8 * sections[2];
    info->value_bits = 8 * sections[3];
    info->kind_bits = 8 * sections[4];
    info->other_kind_edges = kinds;
    info->total_bits = 8 * total;
    info->free_points = free_points.size();
    info->chains = chains.size();
    for (const Chain& c : chains) info->chain_steps += c.size() - 1;
    info->flips = std::size_t(flips);
    info->coded_values = values;
}

}  // namespace

bool is_erdz(const std::string& bytes) { return bytes.size() >= 4 && std::memcmp(bytes.data(), kMagic, 4) == 0; }

std::uint64_t erdz_stream_size(const std::string& prefix) {
    if (prefix.size() < 5) return 0;
    if (!is_erdz(prefix)) return prefix.size();
    const int version = std::uint8_t(prefix[4]);
    if (version < 1 || version > kVersion) return prefix.size();
    Reader rd{prefix, 5};
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
        if (!rd.varint(&v)) return rd.pos < prefix.size() ? prefix.size() : 0;
    if (rd.pos >= prefix.size()) return 0;
    rd.pos += 1 + std::size_t(std::uint8_t(prefix[rd.pos]));
    std::uint64_t total = rd.pos;
    for (int i = 0; i < section_count(version); ++i) {
        Reader sec{prefix, std::size_t(total)};
        if (!sec.varint(&v)) return prefix.size() >= total + 10 ? prefix.size() : 0;
        if (v > (std::uint64_t(1) << 40)) return prefix.size();
        total = sec.pos + v;
    }
    return total;
}

Status encode_erdz(const Model& m, const ErdzOptions& options, std::string* out, ErdzInfo* info) {
    Status st = check_model(m);
    if (!st) return st;
    if (!method_ok(options.method)) return Status::bad_input("method name '" + options.method + "' cannot be stored");
    if (!(options.step > 0.0) || options.step > 1e6) return Status::bad_input("the quantisation step must be in (0, 1e6]");
    const std::uint64_t step256 = std::max<std::uint64_t>(1, std::uint64_t(std::llround(options.step * 256.0)));
    const double step = double(step256) / 256.0;
    ModelTopology topo;
    if (!(st = build_topology(m, &topo))) return st;

    // Constraints: the model's own and its discontinuities, then its edges the rebuild lacks.
    // Discontinuities in any channel (corner values differ across the edge at either end).
    const std::size_t C = std::size_t(m.channels);
    std::vector<EdgeKey> edges;
    for (const auto& c : m.constraints) {
        if (c[0] >= m.vertices.size() || c[1] >= m.vertices.size()) return Status::bad_input("a constraint's vertex is out of range");
        edges.push_back(edge_key(m.vertices[c[0]], m.vertices[c[1]]));
    }
    const auto corner = [&](std::uint32_t h, std::size_t c) { return m.corner_values[(h / 3) * C + c][h % 3]; };
    for (std::uint32_t h = 0; m.kind == ModelKind::erd && h < topo.twin.size(); ++h) {
        const std::uint32_t o = topo.twin[h];
        if (o == kNoHalfEdge || o < h) continue;
        bool jump = false;
        for (std::size_t c = 0; c < C && !jump; ++c)
            jump = corner(h, c) != corner(ModelTopology::next(o), c) || corner(ModelTopology::next(h), c) != corner(o, c);
        if (jump)
            edges.push_back(edge_key(m.vertices[m.faces[h / 3][h % 3]], m.vertices[m.faces[h / 3][(h % 3 + 1) % 3]]));
    }
    std::vector<FaceKey> want(m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        want[f] = face_key(m.vertices[m.faces[f][0]], m.vertices[m.faces[f][1]], m.vertices[m.faces[f][2]]);
    std::vector<FaceKey> want_sorted = want;
    std::sort(want_sorted.begin(), want_sorted.end());
    std::vector<std::pair<std::uint64_t, std::uint32_t>> vertex_at(m.vertices.size());
    for (std::uint32_t i = 0; i < m.vertices.size(); ++i) vertex_at[i] = {key(m.vertices[i]), i};
    std::sort(vertex_at.begin(), vertex_at.end());
    for (std::size_t i = 1; i < vertex_at.size(); ++i)
        if (vertex_at[i].first == vertex_at[i - 1].first) return Status::bad_input("two of the model's vertices are the same point");
    const auto model_vertex = [&](LatticePoint p) {
        return std::lower_bound(vertex_at.begin(), vertex_at.end(), std::make_pair(key(p), std::uint32_t(0)))->second;
    };
    Rebuilt r;
    std::vector<LatticePoint> free_points;
    std::vector<Chain> chains;
    std::string flp;
    std::uint64_t flips = 0;
    codec::Lattice lat{m.width, m.height, false};
    for (;;) {
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        split_points(m, edges, &free_points, &chains);
        lat.full = std::any_of(free_points.begin(), free_points.end(), [](LatticePoint p) { return p.x % 2 || p.y % 2; });
        codec::decoder_order(lat, &free_points);  // the decoder's input, in its order: the same CDT
        r = Rebuilt();  // a fresh kernel, as the decoder's: nothing carried over from the last round
        if (!(st = codec::rebuild(m.width, m.height, free_points, chains, &r)))
            return Status::bad_input("the model cannot be rebuilt: " + st.message);
        // Flip where the other diagonal crosses fewer of the model's edges: every flip lowers the
        // crossings between the two triangulations, and while any remain some flip lowers them
        // (Hanke, Ottmann and Schuierer 1996), so the flips end at the model's faces.
        std::vector<std::uint32_t> mv(r.cdt.vertex_count());
        for (VertInd v = 0; v < mv.size(); ++v) mv[v] = model_vertex(r.cdt.point(v));
        const std::size_t limit = m.faces.size() + 1;
        const auto choose = [&](VertInd a, VertInd b, VertInd c, VertInd d) {
            const std::size_t now = crossings(m, topo, mv[a], mv[b], limit);
            return now > 0 && crossings(m, topo, mv[c], mv[d], now) < now;
        };
        flp = codec::encode_flips(&r.cdt, choose, &flips);
        const bool planned = !flp.empty();
        if (flips == 0) flp.clear();  // no flips: an empty section, no bits spent on saying so
        std::vector<FaceKey> got(r.cdt.face_count());
        std::vector<EdgeKey> have;
        for (FaceInd f = 0; f < r.cdt.face_count(); ++f) {
            const LatticePoint a = r.cdt.point(r.cdt.face_vertex(f, 0)), b = r.cdt.point(r.cdt.face_vertex(f, 1)),
                               c = r.cdt.point(r.cdt.face_vertex(f, 2));
            got[f] = face_key(a, b, c);
            have.push_back(edge_key(a, b));
            have.push_back(edge_key(b, c));
            have.push_back(edge_key(c, a));
        }
        std::sort(got.begin(), got.end());
        if (planned && got == want_sorted && r.cdt.vertex_count() == m.vertices.size()) break;
        std::sort(have.begin(), have.end());
        const std::size_t before_count = edges.size();
        for (std::size_t f = 0; f < m.faces.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const EdgeKey e = edge_key(m.vertices[m.faces[f][std::size_t(k)]], m.vertices[m.faces[f][std::size_t((k + 1) % 3)]]);
                if (!std::binary_search(have.begin(), have.end(), e) && !std::binary_search(edges.begin(), edges.end(), e))
                    edges.push_back(e);
            }
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        if (edges.size() == before_count)
            return Status::bad_input("the model's faces are not a triangulation of its vertices over the image");
    }

    codec::number_units(m.kind == ModelKind::erd, &r);

    // The values in the decoder's unit order, from the model vertex or face at the same place.
    std::vector<std::pair<FaceKey, std::uint32_t>> face_at(m.faces.size());
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) face_at[f] = {want[f], f};
    std::sort(face_at.begin(), face_at.end());
    const std::size_t units = r.graph.units();
    std::vector<double> unit_value(units * C, 0.0);
    std::vector<bool> done(units, false);
    for (EdgeInd e = 0; e < 3 * r.cdt.face_count(); ++e) {
        const std::uint32_t u = r.corner_unit[e];
        if (done[u]) continue;
        done[u] = true;
        const VertInd v = r.cdt.org(e);
        const std::uint32_t mv = model_vertex(r.cdt.point(v));
        for (std::size_t c = 0; c < C; ++c) unit_value[u * C + c] = m.values[mv * C + c];
        if (m.kind != ModelKind::erd) continue;
        const FaceInd f = face_of(e);
        const FaceKey fk = face_key(r.cdt.point(r.cdt.face_vertex(f, 0)), r.cdt.point(r.cdt.face_vertex(f, 1)),
                                    r.cdt.point(r.cdt.face_vertex(f, 2)));
        const std::uint32_t mf = std::lower_bound(face_at.begin(), face_at.end(), std::make_pair(fk, std::uint32_t(0)))->second;
        std::size_t k = 0;
        while (m.faces[mf][k] != mv) ++k;
        for (std::size_t c = 0; c < C; ++c) unit_value[u * C + c] = m.corner_values[mf * C + c][k];
    }
    std::vector<std::int64_t> q(units * C);
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = std::int64_t(std::llround(unit_value[i] / step));

    const std::string pos = codec::encode_positions(lat, free_points);
    const std::string edg = codec::encode_chains(chains);
    const std::string val = codec::encode_values(r.graph, m.channels, q);
    std::string knd;
    std::size_t kinds = 0;
    if (m.kind == ModelKind::erd && !m.kind_exceptions.empty()) {
        std::vector<EdgeKey> other;
        for (const auto& e : m.kind_exceptions) {
            if (e[0] >= m.vertices.size() || e[1] >= m.vertices.size()) return Status::bad_input("an edge kind names a vertex out of range");
            other.push_back(edge_key(m.vertices[e[0]], m.vertices[e[1]]));
        }
        std::sort(other.begin(), other.end());
        knd = codec::encode_kinds(r.cdt, r.corner_unit, m.channels, q, [&](VertInd a, VertInd b) {
            return std::binary_search(other.begin(), other.end(), edge_key(r.cdt.point(a), r.cdt.point(b)));
        }, &kinds);
    }
    const int version = knd.empty() ? codec::kErdzPlainVersion : kVersion;

    std::string& o = *out;
    o.assign(kMagic, 4);
    o.push_back(char(version));
    put_varint(&o, std::uint64_t(m.width));
    put_varint(&o, std::uint64_t(m.height));
    put_varint(&o, m.maxval);
    put_varint(&o, std::uint64_t(m.channels));
    put_varint(&o, m.kind == ModelKind::erd ? 1 : 0);
    put_varint(&o, m.kind == ModelKind::erd && m.edges == EdgeKind::hard ? 1 : 0);
    put_varint(&o, step256);
    put_varint(&o, lat.full ? 1 : 0);
    o.push_back(char(options.method.size()));
    o += options.method;
    std::size_t header = o.size();
    for (const std::string* s : {&pos, &edg, static_cast<const std::string*>(&flp), &val, static_cast<const std::string*>(&knd)}) {
        if (s == &knd && version < 4) break;
        const std::size_t before_len = o.size();
        put_varint(&o, s->size());
        header += o.size() - before_len;
        o += *s;
    }
    if (info)
        fill_info(version, options.method, step, lat.full, header, {pos.size(), edg.size(), flp.size(), val.size(), knd.size()},
                  o.size(), free_points, chains, flips, q.size(), kinds, info);
    return Status::success();
}

Status decode_erdz(const std::string& bytes, Model* out, ErdzInfo* info, const ErdzLimits& limits) {
    return decode_erdz_topology(bytes, out, nullptr, info, limits);
}

Status decode_erdz_topology(const std::string& bytes, Model* out, ModelTopology* topo, ErdzInfo* info, const ErdzLimits& limits) {
    const auto bad = [](const std::string& what) { return Status::bad_input(what); };
    if (!is_erdz(bytes)) return bad("not an .erdz file (no ERDZ magic)");
    if (bytes.size() < 5) return bad("the file ends inside its header");
    const int version = std::uint8_t(bytes[4]);
    if (version < 1 || version > kVersion)
        return bad(".erdz version " + std::to_string(version) + " is not supported (this erd reads 1 to " + std::to_string(kVersion) + ")");
    const int nsec = section_count(version);
    Reader rd{bytes, 5};
    std::array<std::uint64_t, 9> h{};
    static const char* const kNames[] = {"width", "height", "maxval", "channels", "kind", "edges", "step", "lattice", ""};
    for (int i = 0; i < 8; ++i)
        if (!rd.varint(&h[std::size_t(i)])) return bad(std::string("the file ends inside its header (") + kNames[i] + ")");
    const std::uint64_t W = h[0], H = h[1];
    if (W < 2 || H < 2 || W > std::uint64_t(kMaxImageSide) || H > std::uint64_t(kMaxImageSide))
        return bad("header: image size " + std::to_string(W) + " x " + std::to_string(H) + " out of range");
    if (W * H > limits.max_pixels) return bad("header: image of " + std::to_string(W * H) + " pixels is above the limit");
    if (h[2] < 1 || h[2] > 65535) return bad("header: maxval " + std::to_string(h[2]) + " out of range");
    if (h[3] != 1 && h[3] != 3) return bad("header: " + std::to_string(h[3]) + " channels (1 or 3)");
    if (h[4] > 1) return bad("header: unknown model kind " + std::to_string(h[4]));
    if (h[5] > 1 || (h[4] == 0 && h[5] != 0)) return bad("header: bad edge kind " + std::to_string(h[5]));
    if (h[6] < 1 || h[6] > (std::uint64_t(1e6) << 8)) return bad("header: quantisation step out of range");
    if (h[7] > 1 || (h[4] == 0 && h[7] != 0)) return bad("header: bad lattice " + std::to_string(h[7]));
    if (rd.pos >= bytes.size()) return bad("the file ends inside its header (method)");
    const std::size_t mlen = std::uint8_t(bytes[rd.pos++]);
    if (mlen > kMaxMethod || mlen > bytes.size() - rd.pos) return bad("header: bad method name");
    const std::string method = bytes.substr(rd.pos, mlen);
    rd.pos += mlen;
    if (!method_ok(method)) return bad("header: bad method name");
    std::size_t header = rd.pos;
    std::array<std::pair<std::size_t, std::size_t>, 5> sec{};  // positions, edges, flips, values, kinds
    static const char* const kSections[] = {"positions", "edges", "flips", "values", "kinds"};
    for (int j = 0; j < nsec; ++j) {
        const int i = nsec == 3 && j == 2 ? 3 : j;  // version 1 has no flips section
        const std::size_t p0 = rd.pos;
        std::uint64_t len = 0;
        if (!rd.varint(&len)) return bad(std::string("the file ends before the ") + kSections[i] + " section");
        if (len > bytes.size() - rd.pos)
            return bad(std::string("the file ends inside the ") + kSections[i] + " section (" + std::to_string(len) +
                       " bytes declared, " + std::to_string(bytes.size() - rd.pos) + " left)");
        header += rd.pos - p0;
        sec[std::size_t(i)] = {rd.pos, std::size_t(len)};
        rd.pos += std::size_t(len);
    }
    if (rd.pos != bytes.size()) return bad(std::to_string(bytes.size() - rd.pos) + " bytes after the last section");
    const auto data = [&](int i) { return reinterpret_cast<const unsigned char*>(bytes.data()) + sec[std::size_t(i)].first; };

    const bool erd = h[4] == 1;
    const int width = int(W), height = int(H), C = int(h[3]);
    const double step = double(h[6]) / 256.0;
    codec::Lattice lat{width, height, h[7] == 1};
    std::vector<LatticePoint> free_points;
    Status st = codec::decode_positions(data(0), sec[0].second, lat, version, &free_points);
    if (!st) return st;
    std::vector<Chain> chains;
    const std::uint64_t max_steps = 3 * std::uint64_t(2 * W - 1) * std::uint64_t(2 * H - 1);
    if (!(st = codec::decode_chains(data(1), sec[1].second, width, height, !erd, max_steps, version, &chains))) return st;
    Rebuilt r;
    if (!(st = codec::rebuild(width, height, free_points, chains, &r))) return st;
    std::uint64_t flips = 0;
    if (sec[2].second > 0 && !(st = codec::decode_flips(data(2), sec[2].second, &r.cdt, &flips))) return st;
    codec::number_units(erd, &r);
    std::vector<std::int64_t> q;
    if (!(st = codec::decode_values(data(3), sec[3].second, r.graph, C, version, &q))) return st;
    for (std::int64_t k : q)
        if (std::fabs(double(k) * step) > 1e9) return bad("values section: a value above 1e9 in magnitude");
    std::vector<std::array<VertInd, 2>> other_kind;
    if (version >= 4) {
        if (!erd) return bad("kinds section: a basic model has no edge kinds");
        if (!(st = codec::decode_kinds(data(4), sec[4].second, r.cdt, r.corner_unit, C, q, &other_kind))) return st;
    }

    Model& m = *out;
    m = Model();
    m.kind = erd ? ModelKind::erd : ModelKind::basic;
    m.width = width;
    m.height = height;
    m.maxval = std::uint32_t(h[2]);
    m.edges = h[5] == 1 ? EdgeKind::hard : EdgeKind::soft;
    m.channels = C;
    const std::size_t nv = r.cdt.vertex_count(), nf = r.cdt.face_count(), uC = std::size_t(C);
    m.vertices.resize(nv);
    m.values.assign(nv * uC, 0.0);
    for (std::size_t k = 0; k < nv; ++k) {
        m.vertices[k] = r.cdt.point(r.order[k]);
        const std::uint32_t b = r.unit_begin[k], e = r.unit_begin[k + 1];
        for (std::size_t c = 0; c < uC; ++c) {
            double sum = 0.0;
            for (std::uint32_t u = b; u < e; ++u) sum += double(q[u * uC + c]) * step;
            m.values[k * uC + c] = e - b == 1 ? double(q[b * uC + c]) * step : sum / double(e - b);
        }
    }
    m.faces.resize(nf);
    if (erd) m.corner_values.assign(nf * uC, {0.0, 0.0, 0.0});
    for (FaceInd f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
            m.faces[f][std::size_t(k)] = r.rank[r.cdt.face_vertex(f, k)];
            if (!erd) continue;
            const std::uint32_t u = r.corner_unit[3 * f + FaceInd(k)];
            for (std::size_t c = 0; c < uC; ++c) m.corner_values[f * uC + c][std::size_t(k)] = double(q[u * uC + c]) * step;
        }
    for (EdgeInd e = 0; e < 3 * nf; ++e) {
        if (!r.cdt.constrained(e) || (!r.cdt.on_hull(e) && r.cdt.org(e) > r.cdt.dest(e))) continue;
        const std::uint32_t a = r.rank[r.cdt.org(e)], b = r.rank[r.cdt.dest(e)];
        m.constraints.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(m.constraints.begin(), m.constraints.end());
    for (const auto& e : other_kind) {
        const std::uint32_t a = r.rank[e[0]], b = r.rank[e[1]];
        m.kind_exceptions.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(m.kind_exceptions.begin(), m.kind_exceptions.end());
    static_assert(noEdge == kNoHalfEdge, "a border half-edge has the same mark in both");
    if (topo) {
        // Model half-edge 3f + k is the kernel's half-edge 3f + k (face f, from its vertex k), so
        // twins carry over (noEdge is kNoHalfEdge); the fans are counted as build_topology does.
        ModelTopology& t = *topo;
        t.twin.resize(3 * nf);
        for (EdgeInd e = 0; e < 3 * nf; ++e) t.twin[e] = r.cdt.twin(e);
        t.corner_begin.assign(nv + 1, 0);
        for (const auto& f : m.faces)
            for (std::uint32_t v : f) ++t.corner_begin[v + 1];
        for (std::size_t v = 0; v < nv; ++v) t.corner_begin[v + 1] += t.corner_begin[v];
        t.corners.assign(3 * nf, 0);
        std::vector<std::uint32_t> fill(t.corner_begin.begin(), t.corner_begin.end() - 1);
        for (std::size_t e = 0; e < 3 * nf; ++e) t.corners[fill[m.faces[e / 3][e % 3]]++] = std::uint32_t(e);
    }
    if (info)
        fill_info(version, method, step, lat.full, header, {sec[0].second, sec[1].second, sec[2].second, sec[3].second, sec[4].second},
                  bytes.size(), free_points, chains, flips, q.size(), other_kind.size(), info);
    return Status::success();
}

}  // namespace erd
