// The header block of .model and .erd files: the keys of every model, of real models, of models
// with holes and of a raster's georeferencing (model_io.h), and percent_encode, its writer's half.
#include "algorithms/model/model_header.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model_io.h"

namespace erd {

using namespace model_text;

namespace {

// A double of any finite size, or nan (the header's values: "nodata nan").
Status header_number(Tokens& tk, const char* what, bool nan_ok, double* v) {
    std::string_view t;
    if (!tk.next(&t)) return Status::bad_input(std::string("file ends early: expected ") + what);
    if (nan_ok && (t == "nan" || t == "NaN")) {
        *v = std::numeric_limits<double>::quiet_NaN();
        return Status::success();
    }
    double x = 0;
    const char* b = t.data();
    if (!t.empty() && t[0] == '+') ++b;
    const auto r = read_double(b, t.data() + t.size(), &x);
    if (t.empty() || r.ptr != t.data() + t.size() || r.ec != std::errc() || !std::isfinite(x))
        return Status::bad_input(tk.where() + what + " '" + show(t) + "' is not a finite number");
    *v = x;
    return Status::success();
}

// "geo-... N v1 .. vN": a count and that many numbers.
template <class T>
Status header_list(Tokens& tk, const char* key, std::vector<T>* out) {
    std::uint64_t n = 0;
    if (Status s = tk.uint([&] { return std::string("the count of ") + key; }, 1, 65536, &n); !s) return s;
    out->clear();
    for (std::uint64_t i = 0; i < n; ++i) {
        if constexpr (std::is_same_v<T, double>) {
            double v = 0;
            if (Status s = header_number(tk, key, false, &v); !s) return s;
            out->push_back(v);
        } else {
            std::uint64_t v = 0;
            if (Status s = tk.uint(key, 0, 65535, &v); !s) return s;
            out->push_back(T(v));
        }
    }
    return Status::success();
}

bool percent_decode(std::string_view t, std::string* out) {
    out->clear();
    const auto val = [](char c) { return c >= '0' && c <= '9' ? c - '0' : c >= 'A' && c <= 'F' ? c - 'A' + 10 : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1; };
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] != '%') {
            *out += t[i];
            continue;
        }
        if (i + 2 >= t.size()) return false;
        const int a = val(t[i + 1]), b = val(t[i + 2]);
        if (a < 0 || b < 0) return false;
        *out += char(a * 16 + b);
        i += 2;
    }
    return true;
}

SampleType type_of(std::string_view t, bool* ok) {
    static const SampleType kAll[] = {SampleType::u8, SampleType::u16, SampleType::u32, SampleType::i16,
                                      SampleType::i32, SampleType::f32, SampleType::f64};
    for (SampleType k : kAll)
        if (t == sample_type_name(k)) {
            *ok = true;
            return k;
        }
    *ok = false;
    return SampleType::u8;
}

// The header keys of a real model, a model with holes and a raster's georeferencing (model_io.h):
// true when t is one (its value read into *m and *facts, or *r the problem).
constexpr const char* kRasterKeys = "type, range, nodata, holes, doubled, geo-pixel-scale, geo-tiepoints, geo-transform, geo-keys, geo-doubles, geo-ascii";

bool raster_key(Tokens& tk, std::string_view t, Model* m, HeaderFacts* hf, Status* r) {
    static const char* const kKeys[] = {"type", "range", "nodata", "holes", "doubled", "geo-pixel-scale",
                                        "geo-tiepoints", "geo-transform", "geo-keys", "geo-doubles", "geo-ascii"};
    std::size_t k = 0;
    while (k < sizeof kKeys / sizeof kKeys[0] && t != kKeys[k]) ++k;
    if (k == sizeof kKeys / sizeof kKeys[0]) return false;
    const std::string key = kKeys[k];
    if (hf->seen[k]) {
        *r = Status::bad_input(tk.where() + "header key '" + key + "' given twice");
        return true;
    }
    hf->seen[k] = true;
    Status& s = *r;
    if (key == "type") {
        if (!tk.next(&t)) return s = Status::bad_input("file ends early: expected the value of 'type'"), true;
        bool ok = false;
        m->meta.type = type_of(t, &ok);
        if (!ok)
            s = Status::bad_input(tk.where() + "type must be uint8, uint16, uint32, int16, int32, float32 or float64, found '" + show(t) + "'");
        hf->type = true;
    } else if (key == "range") {
        if ((s = header_number(tk, "range low", false, &m->lo)) && (s = header_number(tk, "range high", false, &m->hi)) && m->lo > m->hi)
            s = Status::bad_input(tk.where() + "range low is above range high");
        m->real = true;
        hf->range = true;
    } else if (key == "nodata") {
        s = header_number(tk, "nodata", true, &m->meta.nodata);
        m->meta.has_nodata = true;
    } else if (key == "holes") {
        std::uint64_t w = 0, h = 0;
        if ((s = tk.uint("holes width", 2, kMaxImageSide, &w)) && (s = tk.uint("holes height", 2, kMaxImageSide, &h)) &&
            std::int64_t(w * h) > kMaxImagePixels)
            s = Status::bad_input(tk.where() + "image " + std::to_string(w) + " x " + std::to_string(h) + " is larger than the limit");
        m->width = int(w);
        m->height = int(h);
        m->holes = true;
        hf->holes = true;
    } else if (key == "doubled") {
        hf->doubled = true;
    } else if (key == "geo-pixel-scale") {
        s = header_list(tk, kKeys[k], &m->meta.geo.pixel_scale);
    } else if (key == "geo-tiepoints") {
        s = header_list(tk, kKeys[k], &m->meta.geo.tiepoints);
    } else if (key == "geo-transform") {
        s = header_list(tk, kKeys[k], &m->meta.geo.transform);
    } else if (key == "geo-keys") {
        s = header_list(tk, kKeys[k], &m->meta.geo.keys);
    } else if (key == "geo-doubles") {
        s = header_list(tk, kKeys[k], &m->meta.geo.doubles);
    } else {  // geo-ascii
        if (!tk.next(&t)) s = Status::bad_input("file ends early: expected the value of 'geo-ascii'");
        else if (!percent_decode(t, &m->meta.geo.ascii)) s = Status::bad_input(tk.where() + "geo-ascii has a bad %XX escape");
    }
    return true;
}

}  // namespace

// The header block (model_io.h): "erd-header 1", then key lines, then "end".
Status read_header(Tokens& tk, Model* m, HeaderFacts* facts) {
    std::string_view t;
    tk.next(&t);  // "erd-header"
    std::uint64_t version = 0;
    if (Status s = tk.uint("header version", 0, ~0ull >> 1, &version); !s) return s;
    if (version != 1)
        return Status::bad_input(tk.where() + "header version " + std::to_string(version) + " is not supported (this reader knows 1)");
    int* edges_line = &facts->edges_line;
    int channels_line = 0;
    for (;;) {
        if (!tk.next(&t)) return Status::bad_input("file ends early: expected a header key or 'end'");
        if (t == "end") {
            if (facts->listed_line && facts->listed_kind == m->edges)
                return Status::bad_input("line " + std::to_string(facts->listed_line) + ": header key '" +
                                         (m->edges == EdgeKind::hard ? "hard" : "soft") + "-edges' lists edges of the kind 'edges' gives them already (" +
                                         (m->edges == EdgeKind::hard ? "hard" : "soft") + ")");
            return Status::success();
        }
        if (t == "hard-edges" || t == "soft-edges") {
            if (facts->listed_line) return Status::bad_input(tk.where() + "header keys 'hard-edges' and 'soft-edges': only one of them, once");
            facts->listed_line = tk.line();
            facts->listed_kind = t == "hard-edges" ? EdgeKind::hard : EdgeKind::soft;
            if (Status s = count(tk, [&] { return "the count of '" + std::string(t) + "'"; }, 0, 4, &facts->listed); !s) return s;
            continue;
        }
        if (t == "channels") {
            if (channels_line) return Status::bad_input(tk.where() + "header key 'channels' given twice");
            channels_line = tk.line();
            if (!tk.next(&t)) return Status::bad_input("file ends early: expected the value of 'channels' (1 or 3)");
            if (t != "1" && t != "3")
                return Status::bad_input(tk.where() + "channels must be 1 (gray) or 3 (RGB), found '" + show(t) + "'");
            m->channels = t == "3" ? 3 : 1;
            continue;
        }
        if (t != "edges") {
            Status r;
            if (raster_key(tk, t, m, facts, &r)) {
                if (!r) return r;
                continue;
            }
            return Status::bad_input(tk.where() + "unknown header key '" + show(t) +
                                     "' (this reader knows: edges, hard-edges, soft-edges, channels, " + kRasterKeys + ")");
        }
        if (*edges_line) return Status::bad_input(tk.where() + "header key 'edges' given twice");
        *edges_line = tk.line();
        if (!tk.next(&t)) return Status::bad_input("file ends early: expected the value of 'edges' (hard or soft)");
        if (t != "hard" && t != "soft")
            return Status::bad_input(tk.where() + "edges must be hard or soft, found '" + show(t) + "'");
        m->edges = t == "hard" ? EdgeKind::hard : EdgeKind::soft;
    }
}

// GeoAsciiParams as one token: bytes outside '!'..'~', '%' and '#' as %XX.
std::string percent_encode(const std::string& s) {
    static const char hex[] = "0123456789ABCDEF";
    std::string o;
    for (unsigned char c : s) {
        if (c > ' ' && c < 0x7f && c != '%' && c != '#') {
            o += char(c);
        } else {
            o += '%';
            o += hex[c >> 4];
            o += hex[c & 15];
        }
    }
    return o;
}

}  // namespace erd
