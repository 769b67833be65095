// The plan file of `erd tiles` (tiles_plan.h): written and read.
#include "cli/tiles_plan.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace erd::cli {

void TilesPlan::window(int k, int* x0, int* y0, int* x1, int* y1) const {
    const int i = k % grid.nx, j = k / grid.nx;
    *x0 = grid.column(i);
    *x1 = grid.column(i + 1);
    *y0 = grid.row(j);
    *y1 = grid.row(j + 1);
}

namespace {

using Lines = std::vector<std::vector<std::vector<int>>>;

// Tile k's entries of v (its left and right vertical lines) and h (its top and bottom lines) as
// points on its sides, doubled: offset o at 2 o + odd.
std::vector<LatticePoint> on_sides(const TilesPlan& p, int k, const Lines& v, const Lines& h, int odd) {
    const int i = k % p.grid.nx, j = k / p.grid.nx;
    int x0, y0, x1, y1;
    p.window(k, &x0, &y0, &x1, &y1);
    const std::int32_t mx = 2 * (x1 - x0), my = 2 * (y1 - y0);
    std::vector<LatticePoint> pts;
    if (v.empty()) return pts;
    for (int o : v[std::size_t(i)][std::size_t(j)]) pts.push_back({0, 2 * o + odd});
    for (int o : v[std::size_t(i + 1)][std::size_t(j)]) pts.push_back({mx, 2 * o + odd});
    for (int o : h[std::size_t(j)][std::size_t(i)]) pts.push_back({2 * o + odd, 0});
    for (int o : h[std::size_t(j + 1)][std::size_t(i)]) pts.push_back({2 * o + odd, my});
    return pts;
}

}  // namespace

std::vector<LatticePoint> TilesPlan::side_points(int k) const { return on_sides(*this, k, vborder, hborder, 0); }

std::vector<LatticePoint> TilesPlan::side_crossings(int k) const { return on_sides(*this, k, vcross, hcross, 1); }

std::string TilesPlan::tile_name(int k) const {
    return "tile_" + std::to_string(k / grid.nx) + "_" + std::to_string(k % grid.nx);
}

namespace {

std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

void list(std::string* out, const char* key, const std::vector<double>& v) {
    if (v.empty()) return;
    *out += key;
    for (double d : v) *out += " " + num(d);
    *out += "\n";
}

}  // namespace

std::string plan_text(const TilesPlan& p) {
    std::string s = "erd-tiles-plan 1\n";
    s += "raster " + p.raster + "\n";
    s += "size " + std::to_string(p.grid.width) + " " + std::to_string(p.grid.height) + "\n";
    s += "tile " + std::to_string(p.grid.tile) + "\n";
    s += "grid " + std::to_string(p.grid.nx) + " " + std::to_string(p.grid.ny) + "\n";
    s += "method " + p.method + "\n";
    s += "format " + (p.format.empty() ? std::string("-") : p.format) + "\n";
    s += p.real ? "values real " + num(p.lo) + " " + num(p.hi) + "\n" : "values int " + std::to_string(p.maxval) + "\n";
    list(&s, "geo-scale", p.geo.pixel_scale);
    list(&s, "geo-tie", p.geo.tiepoints);
    list(&s, "geo-transform", p.geo.transform);
    for (const std::string& a : p.args) s += "arg " + a + "\n";
    for (int i = 0; i <= p.grid.nx; ++i)
        for (int j = 0; j < p.grid.ny; ++j) {
            const std::vector<int>& v = p.vborder[std::size_t(i)][std::size_t(j)];
            s += "vborder " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(v.size());
            for (int o : v) s += " " + std::to_string(o);
            s += "\n";
        }
    for (int j = 0; j <= p.grid.ny; ++j)
        for (int i = 0; i < p.grid.nx; ++i) {
            const std::vector<int>& v = p.hborder[std::size_t(j)][std::size_t(i)];
            s += "hborder " + std::to_string(j) + " " + std::to_string(i) + " " + std::to_string(v.size());
            for (int o : v) s += " " + std::to_string(o);
            s += "\n";
        }
    auto crossings = [&](const char* key, int a, int b, const std::vector<int>& v) {
        if (v.empty()) return;
        s += std::string(key) + " " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(v.size());
        for (int o : v) s += " " + std::to_string(o);
        s += "\n";
    };
    for (std::size_t i = 0; i < p.vcross.size(); ++i)
        for (std::size_t j = 0; j < p.vcross[i].size(); ++j) crossings("vcross", int(i), int(j), p.vcross[i][j]);
    for (std::size_t j = 0; j < p.hcross.size(); ++j)
        for (std::size_t i = 0; i < p.hcross[j].size(); ++i) crossings("hcross", int(j), int(i), p.hcross[j][i]);
    for (int k = 0; k < p.grid.count(); ++k)
        s += "task " + std::to_string(k) + " " + std::to_string(k % p.grid.nx) + " " + std::to_string(k / p.grid.nx) + " " +
             std::to_string(p.points[std::size_t(k)]) + " " + std::to_string(p.triangles[std::size_t(k)]) + "\n";
    s += "end\n";
    return s;
}

namespace {

// The words of a line after its key, read one at a time (no streams: C stdio's parsers).
class Words {
public:
    explicit Words(const std::string& s) : s_(s) {}
    bool ok() const { return ok_; }
    std::string word() {
        while (at_ < s_.size() && s_[at_] == ' ') ++at_;
        const std::size_t b = at_;
        while (at_ < s_.size() && s_[at_] != ' ') ++at_;
        if (b == at_) ok_ = false;
        return s_.substr(b, at_ - b);
    }
    long long integer() {
        const std::string w = word();
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(w.c_str(), &end, 10);
        if (w.empty() || *end || errno) ok_ = false;
        return v;
    }
    double real() {
        const std::string w = word();
        char* end = nullptr;
        const double v = std::strtod(w.c_str(), &end);
        if (w.empty() || *end) ok_ = false;
        return v;
    }
    bool more() {
        while (at_ < s_.size() && s_[at_] == ' ') ++at_;
        return at_ < s_.size();
    }

private:
    const std::string& s_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

}  // namespace

Status parse_plan(const std::string& text, TilesPlan* p) {
    *p = TilesPlan();
    int n = 0;
    bool ended = false, sized = false;
    auto bad = [&](const std::string& why) { return Status::bad_input("line " + std::to_string(n) + ": " + why); };
    std::size_t pos = 0;
    while (pos < text.size() && !ended) {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string::npos) eol = text.size();
        const std::string line = text.substr(pos, eol - pos);
        pos = eol + 1;
        ++n;
        if (n == 1) {
            if (line != "erd-tiles-plan 1") return bad("not an erd tiles plan (erd-tiles-plan 1)");
            continue;
        }
        const std::size_t sp = line.find(' ');
        const std::string key = line.substr(0, sp), rest = sp == std::string::npos ? "" : line.substr(sp + 1);
        Words f(rest);
        auto doubles = [&](std::vector<double>* v) {
            while (f.more()) v->push_back(f.real());
        };
        if (key == "raster") p->raster = rest;
        else if (key == "size") p->grid.width = int(f.integer()), p->grid.height = int(f.integer());
        else if (key == "tile") p->grid.tile = int(f.integer());
        else if (key == "grid") {
            p->grid.nx = int(f.integer());
            p->grid.ny = int(f.integer());
            if (!f.ok() || p->grid.width < 2 || p->grid.height < 2 || p->grid.tile < 2) return bad("grid before size and tile");
            const TileGrid g = make_tile_grid(p->grid.width, p->grid.height, p->grid.tile);
            if (g.nx != p->grid.nx || g.ny != p->grid.ny) return bad("the grid does not match the size and the tile");
            p->vborder.assign(std::size_t(g.nx + 1), std::vector<std::vector<int>>(std::size_t(g.ny)));
            p->hborder.assign(std::size_t(g.ny + 1), std::vector<std::vector<int>>(std::size_t(g.nx)));
            p->vcross = p->vborder;
            p->hcross = p->hborder;
            p->points.assign(std::size_t(g.count()), -1);
            p->triangles.assign(std::size_t(g.count()), 0);
            sized = true;
        } else if (key == "method") p->method = rest;
        else if (key == "format") p->format = rest == "-" ? "" : rest;
        else if (key == "values") {
            const std::string kind = f.word();
            if (kind == "int") p->maxval = std::uint32_t(f.integer());
            else if (kind == "real") p->real = true, p->lo = f.real(), p->hi = f.real();
            else return bad("values int or real");
        } else if (key == "geo-scale") doubles(&p->geo.pixel_scale);
        else if (key == "geo-tie") doubles(&p->geo.tiepoints);
        else if (key == "geo-transform") doubles(&p->geo.transform);
        else if (key == "arg") p->args.push_back(rest);
        else if (key == "vborder" || key == "hborder" || key == "vcross" || key == "hcross" || key == "task") {
            if (!sized) return bad(key + " before grid");
            const long long a = f.integer(), b = f.integer(), c = f.integer();
            if (key == "task") {
                const long long pts = f.integer(), tri = f.integer();
                if (!f.ok() || a < 0 || a >= p->grid.count() || b != a % p->grid.nx || c != a / p->grid.nx || pts < 0 || tri < 0)
                    return bad("bad task line");
                p->points[std::size_t(a)] = pts;
                p->triangles[std::size_t(a)] = tri;
                continue;
            }
            const bool v = key[0] == 'v', cross = key[1] == 'c';
            const long long lines = v ? p->grid.nx : p->grid.ny, cells = v ? p->grid.ny : p->grid.nx;
            // Crossings: on a line between two tiles, strictly between the border's ends.
            if (!f.ok() || a < (cross ? 1 : 0) || a > (cross ? lines - 1 : lines) || b < 0 || b >= cells || c < (cross ? 1 : 2))
                return bad("bad " + key + " line");
            const int len = v ? p->grid.row(int(b) + 1) - p->grid.row(int(b)) : p->grid.column(int(b) + 1) - p->grid.column(int(b));
            if (c > len + 1) return bad("bad " + key + " line");
            std::vector<int>& out = (v ? (cross ? p->vcross : p->vborder) : (cross ? p->hcross : p->hborder))[std::size_t(a)][std::size_t(b)];
            out.clear();
            for (long long k = 0; k < c; ++k) {
                const long long o = f.integer();
                if (!f.ok() || o < 0 || o > len || (!out.empty() && o <= out.back()) || (cross && (o < 1 || o + 2 > len)))
                    return bad("bad offset in " + key);
                out.push_back(int(o));
            }
            if (!cross && (out.front() != 0 || out.back() != len)) return bad(key + " must start and end at the tile corners");
        } else if (key == "end") {
            ended = true;
        } else return bad("unknown key '" + key + "'");
        if (!f.ok()) return bad("bad " + key + " line");
    }
    if (!ended) return Status::bad_input("the plan is cut short (no end line)");
    if (p->raster.empty() || p->method.empty() || !sized) return Status::bad_input("the plan lacks its raster, method or grid");
    for (std::int64_t pts : p->points)
        if (pts < 0) return Status::bad_input("the plan lacks a task");
    for (const auto& l : p->vborder)
        for (const auto& b : l)
            if (b.empty()) return Status::bad_input("the plan lacks a vertical border");
    for (const auto& l : p->hborder)
        for (const auto& b : l)
            if (b.empty()) return Status::bad_input("the plan lacks a horizontal border");
    return Status::success();
}

}  // namespace erd::cli
