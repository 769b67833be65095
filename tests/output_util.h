// Helpers shared by the [output] tests: the thesis's A.4.2 example as a Model and as a file,
// counting SVG elements, a small JSON reader for --stats, a synthetic image with an edge.
#pragma once
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "tests/erd_run.h"

namespace output_test {

using erd::Model;
using erd::ModelKind;

// Thesis Appendix A.4.2 (simple.erd), on a 50 x 50 image: the diagonal from vertex 1 to vertex 2
// is constrained, so vertices 1 and 2 have two wedges each (values 73 | 54).
inline Model diagonal_erd() {
    Model m;
    m.kind = ModelKind::erd;
    m.width = m.height = 50;
    m.maxval = 255;
    m.vertices = {{0, 0}, {0, 98}, {98, 0}, {98, 98}};
    m.values = {127, 63.5, 63.5, 90};
    m.faces = {{0, 2, 1}, {1, 2, 3}};
    m.corner_values = {{127, 73, 73}, {54, 54, 90}};
    return m;
}

inline Model diagonal_basic() {
    Model m = diagonal_erd();
    m.kind = ModelKind::basic;
    m.corner_values.clear();
    m.values = {127, 64, 64, 90};
    return m;
}

inline std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + what.size())) ++n;
    return n;
}

// The text between `<g id="ID"` and the next `</g>`.
inline std::string group(const std::string& svg, const std::string& id) {
    std::size_t a = svg.find("<g id=\"" + id + "\"");
    if (a == std::string::npos) return "";
    std::size_t b = svg.find("</g>", a);
    return svg.substr(a, b - a);
}

inline std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.compare(0, prefix.size(), prefix) == 0) out.push_back(line);
    return out;
}

// A small JSON reader, enough for the --stats object: objects, arrays, strings without escapes
// beyond \" and \\, numbers, true/false/null. Fails the test on anything malformed.
struct Json {
    enum Kind { null, boolean, number, string, array, object } kind = null;
    bool b = false;
    double n = 0;
    std::string s;
    std::vector<Json> items;
    std::vector<std::pair<std::string, Json>> fields;

    const Json& operator[](const std::string& key) const {
        for (const auto& f : fields)
            if (f.first == key) return f.second;
        FAIL("missing key " << key);
        return *this;
    }
    bool has(const std::string& key) const {
        for (const auto& f : fields)
            if (f.first == key) return true;
        return false;
    }
};

struct JsonReader {
    const std::string& t;
    std::size_t i = 0;
    void ws() { while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i; }
    bool eat(char c) { ws(); if (i < t.size() && t[i] == c) { ++i; return true; } return false; }
    std::string str() {
        REQUIRE(eat('"'));
        std::string out;
        while (i < t.size() && t[i] != '"') {
            if (t[i] == '\\') ++i;
            REQUIRE(i < t.size());
            out += t[i++];
        }
        REQUIRE(i < t.size());
        ++i;
        return out;
    }
    Json value() {
        ws();
        REQUIRE(i < t.size());
        Json v;
        char c = t[i];
        if (c == '{') {
            v.kind = Json::object;
            ++i;
            if (eat('}')) return v;
            do {
                std::string k = str();
                REQUIRE(eat(':'));
                v.fields.emplace_back(k, value());
            } while (eat(','));
            REQUIRE(eat('}'));
        } else if (c == '[') {
            v.kind = Json::array;
            ++i;
            if (eat(']')) return v;
            do v.items.push_back(value()); while (eat(','));
            REQUIRE(eat(']'));
        } else if (c == '"') {
            v.kind = Json::string;
            v.s = str();
        } else if (t.compare(i, 4, "true") == 0) { v.kind = Json::boolean; v.b = true; i += 4; }
        else if (t.compare(i, 5, "false") == 0) { v.kind = Json::boolean; i += 5; }
        else if (t.compare(i, 4, "null") == 0) { i += 4; }
        else {
            v.kind = Json::number;
            std::size_t used = 0;
            v.n = std::stod(t.substr(i), &used);
            REQUIRE(used > 0);
            i += used;
        }
        return v;
    }
};

inline Json parse_json(const std::string& text) {
    JsonReader r{text};
    Json v = r.value();
    r.ws();
    CHECK(r.i == text.size());
    return v;
}

// The A.4.2 example as an .erd file on the 50 x 50 domain, in the thesis's one-line-per-wedge form.
inline const char* const kDiagonalErd =
    "255\n4\n0 0 127\n0 98 64\n98 0 64\n98 98 90\n2\n0 2 1\n1 2 3\n4\n1 0 73\n1 1 54\n2 0 73\n2 1 54\n";

// Width and height from a PNG's IHDR (bytes 16..23, big-endian).
inline bool png_size(const std::string& png, int* w, int* h) {
    if (png.size() < 24 || png.compare(1, 3, "PNG") != 0) return false;
    auto be = [&](std::size_t i) {
        return (int(std::uint8_t(png[i])) << 24) | (int(std::uint8_t(png[i + 1])) << 16) |
               (int(std::uint8_t(png[i + 2])) << 8) | int(std::uint8_t(png[i + 3]));
    };
    *w = be(16);
    *h = be(20);
    return true;
}

// 40 x 30: smooth waves with a bright disc (an edge for the ERD methods); GPI reaches any N here.
inline erd::Image wave_disc_image() {
    erd::Image im(40, 30, 255);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x)
            im.at(x, y) = std::uint16_t((x - 20) * (x - 20) + (y - 15) * (y - 15) < 64
                                            ? 220
                                            : std::lround(90 + 40 * std::sin(x / 3.0) * std::cos(y / 4.0)));
    return im;
}

}  // namespace output_test
