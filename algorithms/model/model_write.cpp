// Writers of .model, .erd, -t and -p files (formats in model_io.h; readers in model_io.cpp).
//
// Every record is assembled in a small stack buffer with the number formatters below and
// appended to the output once: no temporary strings per number (building and concatenating
// std::strings was most of the writer's time; docs/DECISIONS.md "Model files").
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/model/edge_kinds.h"
#include "algorithms/model/float_chars.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "kernel/predicates.h"

namespace erd {
namespace {

// A value as put_value prints it is at most 24 characters ("-2.2250738585072014e-308").
constexpr std::size_t kValueBytes = 32;
// Room for one record: three 20-digit integers, or two integers and up to three values, with
// separators.
constexpr std::size_t kRecordBytes = 2 * 21 + 3 * (kValueBytes + 1);

// Decimal digits of v at p; returns the end. The same text as std::to_string.
char* put_uint(char* p, std::uint64_t v) {
    static const char kPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    char tmp[20];
    char* t = tmp + sizeof tmp;
    while (v >= 100) {
        const std::size_t k = std::size_t(v % 100) * 2;
        v /= 100;
        *--t = kPairs[k + 1];
        *--t = kPairs[k];
    }
    if (v >= 10) {
        *--t = kPairs[2 * v + 1];
        *--t = kPairs[2 * v];
    } else {
        *--t = char('0' + v);
    }
    while (t < tmp + sizeof tmp) *p++ = *t++;  // at most 20 characters: no memcpy call
    return p;
}

char* put_int(char* p, std::int64_t v) {
    if (v < 0) {
        *p++ = '-';
        return put_uint(p, std::uint64_t(0) - std::uint64_t(v));
    }
    return put_uint(p, std::uint64_t(v));
}

// format_value's text at p (at least kValueBytes of room); returns the end. Integral values of
// magnitude below 1e15 print as integers (so -0 prints as "0"); others, infinities and NaN
// included, as std::to_chars prints them (the shortest decimal that reads back to the same
// double). Below 1e15 the cast is exact, so double(i) == v says v == floor(v) without a libm
// call; NaN fails the magnitude test.
char* put_value(char* p, double v) {
    if (std::fabs(v) < 1e15) {
        const std::int64_t i = static_cast<std::int64_t>(v);
        if (double(i) == v) return put_int(p, i);
    }
    return write_double(p, p + kValueBytes, v);
}

// One output line at a time: each field is followed by a space, and end() turns the last space
// into '\n' and appends the line (so a line has at least one field). A line holds at most
// kRecordBytes: three integers, or two and up to three values, as the writers use it.
class Lines {
public:
    explicit Lines(std::string* out) : out_(out) {}
    Lines& num(std::uint64_t v) { return sep(put_uint(p_, v)); }
    Lines& sint(std::int64_t v) { return sep(put_int(p_, v)); }
    Lines& value(double v) { return sep(put_value(p_, v)); }
    Lines& chars(const char* s, std::size_t n) {  // a field already formatted
        for (std::size_t i = 0; i < n; ++i) *p_++ = s[i];
        *p_++ = ' ';
        return *this;
    }
    Lines& text(const char* s) {
        while (*s) *p_++ = *s++;
        *p_++ = ' ';
        return *this;
    }
    void end() {
        p_[-1] = '\n';  // the last separator
        out_->append(buf_, std::size_t(p_ - buf_));
        p_ = buf_;
    }

private:
    Lines& sep(char* end) {
        p_ = end;
        *p_++ = ' ';
        return *this;
    }
    std::string* out_;
    char buf_[kRecordBytes];
    char* p_ = buf_;
};

// Shared checks of the writers: indices, orientation, finite values.
Status check_for_writing(const Model& m, bool values) {
    const std::size_t nv = m.vertices.size(), C = std::size_t(m.channels);
    if (values && m.channels != 1 && m.channels != 3)
        return Status::failure("model has " + std::to_string(m.channels) + " channels (1 or 3 can be written)");
    if (values && m.values.size() != nv * C)
        return Status::failure("model has " + std::to_string(m.values.size()) + " values for " + std::to_string(nv) + " vertices" +
                               (C > 1 ? " in " + std::to_string(C) + " channels" : ""));
    if (values && m.kind == ModelKind::erd && m.corner_values.size() != m.faces.size() * C)
        return Status::failure("ERD model has " + std::to_string(m.corner_values.size()) + " corner value triples for " +
                               std::to_string(m.faces.size()) + " faces" + (C > 1 ? " in " + std::to_string(C) + " channels" : ""));
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        for (std::uint32_t v : m.faces[f])
            if (v >= nv) return Status::failure("face " + std::to_string(f) + ": vertex index out of range");
    if (values) {
        for (double z : m.values)
            if (!std::isfinite(z)) return Status::failure("model has a value that is not a finite number");
        for (const auto& c : m.corner_values)
            for (double z : c)
                if (!std::isfinite(z)) return Status::failure("model has a wedge value that is not a finite number");
    }
    return Status::success();
}

void put_faces(const std::vector<std::array<std::uint32_t, 3>>& faces, Lines* line) {
    line->num(faces.size()).end();
    for (const auto& f : faces) line->num(f[0]).num(f[1]).num(f[2]).end();
}

// The wedge lines of an .erd: for every vertex whose corners do not all carry its vertex-line
// values (every vertex with wedges of different values), one line per corner in half-edge order,
// with a value per channel. Wedges that share one value need none (the vertex line gives it
// back), which keeps write(read(write(m))) stable. Only the corners of each vertex are needed,
// not the twins, so they are bucketed here (the order build_topology gives them) rather than by
// build_topology.
void put_wedge_lines(const Model& m, std::string* o) {
    const std::size_t nv = m.vertices.size(), nh = 3 * m.faces.size(), C = std::size_t(m.channels);
    std::vector<std::uint32_t> begin(nv + 1, 0), corners(nh);
    for (const auto& f : m.faces)
        for (std::uint32_t v : f) ++begin[v + 1];
    for (std::size_t v = 0; v < nv; ++v) begin[v + 1] += begin[v];
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (std::uint32_t h = 0; h < nh; ++h) corners[fill[m.faces[h / 3][h % 3]]++] = h;
    std::string lines;
    Lines line(&lines);
    std::size_t nw = 0;
    // A vertex's corners share its few wedge values: each distinct value (all channels) is
    // formatted once.
    struct Formatted {
        double value[3];
        std::size_t length;
        char text[3 * kValueBytes];
    };
    std::vector<Formatted> seen;
    double z[3] = {0.0, 0.0, 0.0};
    for (std::uint32_t v = 0; v < nv; ++v) {
        const std::uint32_t b = begin[v], e = begin[v + 1];
        bool odd = false;
        for (std::uint32_t i = b; i < e && !odd; ++i)
            for (std::size_t c = 0; c < C && !odd; ++c) odd = corner_value(m, corners[i], int(c)) != m.values[v * C + c];
        if (!odd) continue;
        seen.clear();
        for (std::uint32_t i = b; i < e; ++i) {
            const std::uint32_t h = corners[i];
            for (std::size_t c = 0; c < C; ++c) z[c] = corner_value(m, h, int(c));
            // Finite values: == is identity up to the sign of 0, which prints "0" both ways.
            const auto same = [&](const Formatted& x) {
                for (std::size_t c = 0; c < C; ++c)
                    if (x.value[c] != z[c]) return false;
                return true;
            };
            std::size_t k = 0;
            while (k < seen.size() && !same(seen[k])) ++k;
            if (k == seen.size()) {
                seen.emplace_back();
                char* p = seen[k].text;
                for (std::size_t c = 0; c < C; ++c) {
                    seen[k].value[c] = z[c];
                    if (c > 0) *p++ = ' ';
                    p = put_value(p, z[c]);
                }
                seen[k].length = std::size_t(p - seen[k].text);
            }
            line.num(v).num(h / 3).chars(seen[k].text, seen[k].length).end();
        }
        nw += e - b;
    }
    Lines(o).num(nw).end();
    *o += lines;
}

}  // namespace

std::string format_value(double v) {
    char buf[kValueBytes];
    return std::string(buf, put_value(buf, v));
}

// The header keys of a real model, a model with holes and a raster's meta (model_io.h), in their
// order; nothing for a model of a PGM, PPM, PNG or JPEG image.
void put_raster_keys(const Model& m, bool doubled, std::string* o) {
    const auto num = [](double v) { return format_value(v); };
    if (m.real) {
        *o += std::string("type ") + sample_type_name(m.meta.type) + "\n";
        *o += "range " + num(m.lo) + " " + num(m.hi) + "\n";
    }
    if (m.meta.has_nodata) *o += "nodata " + (std::isnan(m.meta.nodata) ? std::string("nan") : num(m.meta.nodata)) + "\n";
    if (m.holes) *o += "holes " + std::to_string(m.width) + " " + std::to_string(m.height) + "\n";
    if (doubled) *o += "doubled\n";
    const GeoTags& g = m.meta.geo;
    const auto list = [&](const char* key, const auto& v) {
        if (v.empty()) return;
        *o += std::string(key) + " " + std::to_string(v.size());
        for (const auto x : v) *o += " " + num(double(x));
        *o += "\n";
    };
    list("geo-pixel-scale", g.pixel_scale);
    list("geo-tiepoints", g.tiepoints);
    list("geo-transform", g.transform);
    list("geo-keys", g.keys);
    list("geo-doubles", g.doubles);
    if (!g.ascii.empty()) *o += "geo-ascii " + percent_encode(g.ascii) + "\n";
}

Status write_model(const Model& m, std::string* out) {
    if (Status s = check_for_writing(m, true); !s) return s;
    const bool erd = m.kind == ModelKind::erd;
    const std::size_t C = std::size_t(m.channels);
    // A basic model's vertices are pixels, but the outline of a valid region (a model with holes)
    // runs between them: such a file gives doubled coordinates (header "doubled").
    bool doubled = false;
    if (!erd)
        for (const LatticePoint& p : m.vertices)
            if (p.x % 2 != 0 || p.y % 2 != 0) {
                if (!m.holes) return Status::failure("a basic model has a vertex off the pixel lattice");
                doubled = true;
            }
    std::string o;
    o.reserve(m.vertices.size() * (20 + 8 * C) + m.faces.size() * 18);
    Lines line(&o);
    const bool hard = erd && m.edges == EdgeKind::hard;
    const bool listed = erd && !m.kind_exceptions.empty();
    if (listed) {  // a file the reader refuses is never written
        ModelTopology topo;
        Status st = build_topology(m, &topo);
        if (st) st = check_kind_exceptions(m, topo);
        if (!st) return Status::failure(st.message);
    }
    const bool raster = m.real || m.holes || m.meta.has_nodata || !m.meta.geo.empty();
    if (hard || listed || C > 1 || raster) {
        o += "erd-header 1\n";
        if (C > 1) o += "channels " + std::to_string(C) + "\n";
        if (hard || listed) o += hard ? "edges hard\n" : "edges soft\n";
        if (listed) o += std::string(hard ? "soft" : "hard") + "-edges " + std::to_string(m.kind_exceptions.size()) + "\n";
        put_raster_keys(m, doubled, &o);
        o += "end\n";
    }
    line.num(m.real ? 0 : m.maxval).end();
    line.num(m.vertices.size()).end();
    const bool pixels = !erd && !doubled;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const LatticePoint p = m.vertices[i];
        line.sint(pixels ? p.x / 2 : p.x).sint(pixels ? p.y / 2 : p.y);
        for (std::size_t c = 0; c < C; ++c) line.value(m.values[i * C + c]);
        line.end();
    }
    // Positive orientation (corner values follow their vertices).
    Model pos;
    const Model* mm = &m;
    bool flip = false;
    for (const auto& f : m.faces) flip = flip || orient2d(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) < 0;
    if (flip) {
        pos = m;
        for (std::size_t f = 0; f < pos.faces.size(); ++f)
            if (orient2d(pos.vertices[pos.faces[f][0]], pos.vertices[pos.faces[f][1]], pos.vertices[pos.faces[f][2]]) < 0) {
                std::swap(pos.faces[f][1], pos.faces[f][2]);
                if (erd)
                    for (std::size_t c = 0; c < C; ++c) std::swap(pos.corner_values[f * C + c][1], pos.corner_values[f * C + c][2]);
            }
        mm = &pos;
    }
    put_faces(mm->faces, &line);
    if (erd) put_wedge_lines(*mm, &o);
    if (listed)
        for (const auto& e : m.kind_exceptions) line.num(e[0]).num(e[1]).end();
    *out = std::move(o);
    return Status::success();
}

Status write_triangulation(const Model& m, std::string* out) {
    if (Status s = check_for_writing(m, false); !s) return s;
    std::string o;
    Lines line(&o);
    line.text("erd-triangulation").num(1).end();
    line.sint(m.width).sint(m.height).end();
    line.num(m.vertices.size()).end();
    for (const LatticePoint& p : m.vertices) line.sint(p.x).sint(p.y).end();
    std::vector<std::array<std::uint32_t, 3>> faces = m.faces;
    for (auto& f : faces)
        if (orient2d(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) < 0) std::swap(f[1], f[2]);
    put_faces(faces, &line);
    std::vector<std::array<std::uint32_t, 2>> cons = m.constraints;
    for (auto& c : cons)
        if (c[0] > c[1]) std::swap(c[0], c[1]);
    std::sort(cons.begin(), cons.end());
    line.num(cons.size()).end();
    for (const auto& c : cons) line.num(c[0]).num(c[1]).end();
    *out = std::move(o);
    return Status::success();
}

void write_polylines(const std::vector<std::vector<LatticePoint>>& lines, std::string* out) {
    std::string o = "erd-polylines 1\n";
    char buf[kRecordBytes];
    char* p = put_uint(buf, lines.size());
    *p++ = '\n';
    o.append(buf, p);
    for (const auto& l : lines) {
        o.append(buf, put_uint(buf, l.size()));
        for (const LatticePoint q : l) {
            p = buf;
            *p++ = ' ';
            p = put_int(p, q.x);
            *p++ = ' ';
            p = put_int(p, q.y);
            o.append(buf, p);
        }
        o += '\n';
    }
    *out = std::move(o);
}

}  // namespace erd
