#include "algorithms/imaging/drawings.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "algorithms/imaging/splitmix.h"

namespace erd {

namespace {

using i64 = std::int64_t;

struct Pt {
    i64 x, y;
};

// A paint: value a + gx * x / W + gy * y / H (x, y in pixels), in [0, 1] before clamping.
struct Paint {
    double a, gx = 0, gy = 0;
};

// Paints shapes in order onto a W x H canvas of values in [0, 1]; a pixel belongs to a shape
// when its centre (x, y) does, tested in integers. Coordinates are given in a 320 x 240 design
// space and scaled to the canvas (S), so every size shows the same picture.
class Canvas {
public:
    Canvas(int w, int h) : W(w), H(h), v(std::size_t(w) * std::size_t(h), 0.0) {}
    i64 sx(i64 x) const { return x * W / 320; }
    i64 sy(i64 y) const { return y * H / 240; }
    i64 sr(i64 r) const { return std::max<i64>(1, r * std::min<i64>(W * 240, H * 320) / (320 * 240)); }
    Pt s(i64 x, i64 y) const { return {sx(x), sy(y)}; }

    double value(const Paint& p, i64 x, i64 y) const { return p.a + p.gx * double(x) / double(W) + p.gy * double(y) / double(H); }
    void put(i64 x, i64 y, const Paint& p) { v[std::size_t(y) * std::size_t(W) + std::size_t(x)] = value(p, x, y); }

    template <class Inside>
    void fill(i64 x0, i64 y0, i64 x1, i64 y1, const Paint& p, Inside inside) {
        for (i64 y = std::max<i64>(0, y0); y <= std::min<i64>(H - 1, y1); ++y)
            for (i64 x = std::max<i64>(0, x0); x <= std::min<i64>(W - 1, x1); ++x)
                if (inside(x, y)) put(x, y, p);
    }
    void all(const Paint& p) { rect({0, 0}, {W, H}, p); }
    // Pixels with a <= centre < b, design coordinates already scaled.
    void rect(Pt a, Pt b, const Paint& p) {
        fill(a.x, a.y, b.x - 1, b.y - 1, p, [](i64, i64) { return true; });
    }
    void ellipse(Pt c, i64 rx, i64 ry, const Paint& p) {
        fill(c.x - rx, c.y - ry, c.x + rx, c.y + ry, p, [&](i64 x, i64 y) {
            return (x - c.x) * (x - c.x) * ry * ry + (y - c.y) * (y - c.y) * rx * rx <= rx * rx * ry * ry;
        });
    }
    void disc(Pt c, i64 r, const Paint& p) { ellipse(c, r, r, p); }
    void ring(Pt c, i64 r0, i64 r1, const Paint& p) {
        fill(c.x - r1, c.y - r1, c.x + r1, c.y + r1, p, [&](i64 x, i64 y) {
            const i64 d = (x - c.x) * (x - c.x) + (y - c.y) * (y - c.y);
            return d >= r0 * r0 && d <= r1 * r1;
        });
    }
    // A convex polygon, either orientation; pixels on its boundary belong to it.
    void polygon(const std::vector<Pt>& q, const Paint& p) {
        i64 x0 = W, y0 = H, x1 = 0, y1 = 0;
        for (const Pt& a : q) x0 = std::min(x0, a.x), y0 = std::min(y0, a.y), x1 = std::max(x1, a.x), y1 = std::max(y1, a.y);
        fill(x0, y0, x1, y1, p, [&](i64 x, i64 y) {
            bool pos = false, neg = false;
            for (std::size_t i = 0; i < q.size(); ++i) {
                const Pt& a = q[i];
                const Pt& b = q[(i + 1) % q.size()];
                const i64 o = (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
                pos |= o > 0;
                neg |= o < 0;
            }
            return !(pos && neg);
        });
    }
    // Pixels within width/2 of segment a-b (width in pixels).
    void line(Pt a, Pt b, i64 width, const Paint& p) {
        const i64 dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy, r = width;  // compare 4 d^2 <= w^2
        fill(std::min(a.x, b.x) - width, std::min(a.y, b.y) - width, std::max(a.x, b.x) + width, std::max(a.y, b.y) + width, p,
             [&](i64 x, i64 y) {
                 const i64 ex = x - a.x, ey = y - a.y, t = ex * dx + ey * dy;
                 if (t <= 0 || len2 == 0) return 4 * (ex * ex + ey * ey) <= r * r;
                 if (t >= len2) return 4 * ((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) <= r * r;
                 const i64 c = dx * ey - dy * ex;
                 return 4 * c * c <= r * r * len2;
             });
    }
    void polyline(const std::vector<Pt>& q, i64 width, const Paint& p) {
        for (std::size_t i = 0; i + 1 < q.size(); ++i) line(q[i], q[i + 1], width, p);
    }

    int W, H;
    std::vector<double> v;
};

Paint flat(double a) { return {a, 0, 0}; }

void draw_drawing(Canvas& c) {
    c.all({0.2, 0.5, 0.15});
    c.disc(c.s(95, 90), c.sr(55), flat(0.85));
    c.rect(c.s(175, 40), c.s(290, 120), flat(0.1));
    c.polygon({c.s(160, 220), c.s(300, 215), c.s(230, 140)}, flat(0.55));
    c.rect(c.s(30, 170), c.s(120, 225), {0.7, -0.4, 0.0});
}

void draw_cartoon(Canvas& c) {
    const Paint ink = flat(0.05);
    c.all({0.85, 0, -0.35});                             // sky, lighter at the top
    c.disc(c.s(260, 50), c.sr(30), ink);
    c.disc(c.s(260, 50), c.sr(27), flat(0.97));          // sun
    c.ellipse(c.s(80, 260), c.sr(150), c.sr(110), ink);  // hills
    c.ellipse(c.s(80, 260), c.sr(147), c.sr(107), flat(0.45));
    c.ellipse(c.s(270, 270), c.sr(140), c.sr(100), ink);
    c.ellipse(c.s(270, 270), c.sr(137), c.sr(97), flat(0.6));
    c.rect(c.s(150, 120), c.s(226, 196), ink);            // house
    c.rect(c.s(153, 123), c.s(223, 193), flat(0.75));
    c.polygon({c.s(142, 122), c.s(234, 122), c.s(188, 76)}, ink);
    c.polygon({c.s(149, 119), c.s(227, 119), c.s(188, 80)}, flat(0.3));
    c.rect(c.s(178, 150), c.s(198, 193), flat(0.25));      // door
    c.rect(c.s(160, 132), c.s(174, 146), ink);
    c.rect(c.s(162, 134), c.s(172, 144), flat(0.9));
    c.rect(c.s(202, 132), c.s(216, 146), ink);
    c.rect(c.s(204, 134), c.s(214, 144), flat(0.9));
    c.ellipse(c.s(60, 60), c.sr(35), c.sr(14), flat(0.98));  // cloud
    c.ellipse(c.s(85, 52), c.sr(25), c.sr(14), flat(0.98));
}

// 5 x 7 glyphs from a fixed generator, strokes one pixel wide at 320 x 240.
void text(Canvas& c, SplitMix& rng, i64 x, i64 y, int chars, const Paint& p) {
    for (int k = 0; k < chars; ++k, x += 6) {
        if (rng.below(6) == 0) continue;  // a space
        const std::uint64_t bits = rng.next();
        for (int gy = 0; gy < 7; ++gy)
            for (int gx = 0; gx < 5; ++gx)
                if ((bits >> (gy * 5 + gx)) & 1u) c.rect(c.s(x + gx, y + gy), c.s(x + gx + 1, y + gy + 1), p);
    }
}

void draw_screenshot(Canvas& c) {
    SplitMix rng{15};
    c.all(flat(0.45));
    c.rect(c.s(20, 16), c.s(300, 226), flat(0.15));  // window frame
    c.rect(c.s(21, 17), c.s(299, 225), flat(0.94));
    c.rect(c.s(21, 17), c.s(299, 33), {0.25, 0.2, 0});  // title bar
    text(c, rng, 28, 21, 14, flat(0.95));
    for (int i = 0; i < 3; ++i) c.disc(c.s(288 - 12 * i, 25), c.sr(4), flat(0.6 + 0.12 * i));
    c.rect(c.s(21, 33), c.s(90, 225), flat(0.84));  // side bar
    for (int i = 0; i < 8; ++i) text(c, rng, 26, 42 + 16 * i, 9, flat(0.2));
    c.rect(c.s(21, 41 + 16 * 2), c.s(90, 55 + 16 * 2), flat(0.55));
    for (int i = 0; i < 9; ++i) text(c, rng, 100, 44 + 12 * i, 30, flat(0.1));
    for (int i = 0; i < 3; ++i) {  // buttons
        const i64 x = 150 + 48 * i;
        c.rect(c.s(x, 180), c.s(x + 42, 200), flat(0.3));
        c.rect(c.s(x + 1, 181), c.s(x + 41, 199), {0.8, 0, -0.2});
        text(c, rng, x + 6, 186, 5, flat(0.05));
    }
    c.rect(c.s(100, 208), c.s(290, 218), flat(0.7));  // progress bar
    c.rect(c.s(100, 208), c.s(215, 218), flat(0.35));
}

void draw_icons(Canvas& c) {
    c.all(flat(0.92));
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const i64 x = 20 + 76 * i, y = 16 + 76 * j, k = 4 * j + i;
            const Paint bg = flat(0.15 + 0.06 * double(k));
            const Paint fg = flat(k % 2 ? 0.97 : 0.03);
            c.rect(c.s(x, y), c.s(x + 60, y + 60), bg);
            const Pt m = c.s(x + 30, y + 30);
            switch (k % 6) {
                case 0: c.disc(m, c.sr(18), fg); break;
                case 1: c.line(c.s(x + 12, y + 12), c.s(x + 48, y + 48), c.sr(8), fg);
                        c.line(c.s(x + 48, y + 12), c.s(x + 12, y + 48), c.sr(8), fg); break;
                case 2: c.polygon({c.s(x + 10, y + 50), c.s(x + 50, y + 50), c.s(x + 30, y + 10)}, fg); break;
                case 3: c.ring(m, c.sr(12), c.sr(20), fg); break;
                case 4: c.rect(c.s(x + 10, y + 24), c.s(x + 34, y + 36), fg);
                        c.polygon({c.s(x + 34, y + 12), c.s(x + 52, y + 30), c.s(x + 34, y + 48)}, fg); break;
                default: c.rect(c.s(x + 12, y + 12), c.s(x + 48, y + 48), fg);
                         c.rect(c.s(x + 20, y + 20), c.s(x + 40, y + 40), bg); break;
            }
        }
}

void draw_map(Canvas& c) {
    SplitMix rng{7};
    std::vector<Pt> seeds;
    std::vector<double> level;
    for (int i = 0; i < 14; ++i) {
        seeds.push_back(c.s(rng.below(320), rng.below(240)));
        level.push_back(0.3 + 0.05 * double(rng.below(11)));
    }
    for (i64 y = 0; y < c.H; ++y)
        for (i64 x = 0; x < c.W; ++x) {
            std::size_t best = 0;
            i64 bd = -1;
            for (std::size_t i = 0; i < seeds.size(); ++i) {
                const i64 d = (x - seeds[i].x) * (x - seeds[i].x) + (y - seeds[i].y) * (y - seeds[i].y);
                if (bd < 0 || d < bd) bd = d, best = i;
            }
            c.put(x, y, flat(level[best]));
        }
    c.polyline({c.s(0, 60), c.s(70, 80), c.s(130, 140), c.s(210, 150), c.s(320, 210)}, c.sr(7), flat(0.12));  // river
    const std::vector<Pt> road = {c.s(40, 240), c.s(90, 150), c.s(180, 90), c.s(320, 70)};
    c.polyline(road, c.sr(6), flat(0.05));
    c.polyline(road, c.sr(3), flat(0.98));
    c.polyline({c.s(250, 0), c.s(230, 120), c.s(270, 240)}, c.sr(4), flat(0.9));
    c.disc(c.s(180, 90), c.sr(6), flat(0.05));
    c.disc(c.s(90, 150), c.sr(6), flat(0.05));
}

// A rendered scene without anti-aliasing: perspective checkerboard floor, a Lambert-shaded
// sphere and a box with three flat-shaded faces, under a sky gradient.
void draw_scene(Canvas& c) {
    const i64 horizon = c.sy(100), cx = c.W / 2;
    for (i64 y = 0; y < c.H; ++y)
        for (i64 x = 0; x < c.W; ++x) {
            if (y <= horizon) {
                c.put(x, y, {0.75, 0, -0.6});
                continue;
            }
            const double depth = double(c.H) / double(y - horizon);  // distance along the floor
            const double u = double(x - cx) * depth / double(c.W) * 8.0, w = depth * 2.0;
            const bool odd = (i64(std::floor(u)) + i64(std::floor(w))) % 2 != 0;
            c.put(x, y, flat((odd ? 0.25 : 0.7) - 0.1 * std::min(1.0, 4.0 / depth)));
        }
    const Pt sc = c.s(215, 130);
    const i64 r = c.sr(50);
    c.fill(sc.x - r, sc.y - r, sc.x + r, sc.y + r, flat(0), [&](i64 x, i64 y) {
        const i64 dx = x - sc.x, dy = y - sc.y;
        if (dx * dx + dy * dy > r * r) return false;
        const double nx = double(dx) / double(r), ny = double(dy) / double(r);
        const double nz = std::sqrt(std::max(0.0, 1.0 - nx * nx - ny * ny));
        const double lambert = std::max(0.0, -0.5 * nx - 0.6 * ny + 0.62 * nz);
        c.v[std::size_t(y) * std::size_t(c.W) + std::size_t(x)] = 0.1 + 0.85 * lambert;
        return false;
    });
    c.polygon({c.s(50, 120), c.s(110, 120), c.s(110, 195), c.s(50, 195)}, {0.55, 0.3, 0});   // box front
    c.polygon({c.s(110, 120), c.s(140, 100), c.s(140, 175), c.s(110, 195)}, {0.35, 0, -0.2});  // side
    c.polygon({c.s(50, 120), c.s(80, 100), c.s(140, 100), c.s(110, 120)}, flat(0.9));          // top
}

void draw_chart(Canvas& c) {
    c.all(flat(0.98));
    for (int i = 0; i <= 5; ++i) c.rect(c.s(40, 30 + 36 * i), c.s(300, 31 + 36 * i), flat(0.82));  // grid lines
    const double bars[] = {0.3, 0.55, 0.8, 0.45, 0.65, 0.9, 0.25};
    for (int i = 0; i < 7; ++i) {
        const i64 top = 210 - i64(bars[i] * 180.0);
        c.rect(c.s(50 + 36 * i, top), c.s(74 + 36 * i, 210), flat(0.2 + 0.08 * i));
    }
    std::vector<Pt> curve;
    for (int i = 0; i <= 12; ++i) curve.push_back(c.s(45 + 21 * i, 120 - (i * 37 % 70) + (i % 3) * 20));
    c.polyline(curve, c.sr(3), flat(0.05));
    c.rect(c.s(38, 30), c.s(40, 212), flat(0));  // axes
    c.rect(c.s(38, 210), c.s(302, 212), flat(0));
    c.rect(c.s(230, 10), c.s(300, 26), flat(0.3));
    c.rect(c.s(232, 12), c.s(298, 24), flat(0.96));
}

// Pixel art: a 40 x 30 picture of blocks, shown with square cells of 8 x 8 pixels (at 320 x 240).
void draw_pixelart(Canvas& c) {
    SplitMix rng{3};
    Canvas small(40, 30);
    small.all({0.3, 0.3, 0.2});
    for (int i = 0; i < 12; ++i) {
        const Pt a = {rng.below(36), rng.below(26)};
        const Pt b = {a.x + 2 + rng.below(8), a.y + 2 + rng.below(6)};
        small.rect(a, b, flat(0.1 + 0.07 * double(i)));
    }
    small.disc({20, 15}, 7, flat(0.95));
    small.disc({18, 13}, 2, flat(0.05));
    small.disc({23, 13}, 2, flat(0.05));
    small.rect({17, 18}, {24, 19}, flat(0.05));
    for (i64 y = 0; y < c.H; ++y)
        for (i64 x = 0; x < c.W; ++x) c.v[std::size_t(y) * std::size_t(c.W) + std::size_t(x)] = small.v[std::size_t(y * 30 / c.H) * 40 + std::size_t(x * 40 / c.W)];
}

// Cel shading: flat bands of light on smooth shapes, outlined.
void draw_cel(Canvas& c) {
    c.all({0.6, -0.2, 0.2});
    const Pt a = c.s(110, 120), b = c.s(230, 110);
    const i64 ra = c.sr(80), rb = c.sr(60);
    c.disc(a, ra + c.sr(3), flat(0.02));
    c.disc(b, rb + c.sr(3), flat(0.02));
    const auto bands = [&](Pt m, i64 r, double base) {
        c.fill(m.x - r, m.y - r, m.x + r, m.y + r, flat(0), [&](i64 x, i64 y) {
            const i64 dx = x - m.x, dy = y - m.y;
            if (dx * dx + dy * dy > r * r) return false;
            const double nx = double(dx) / double(r), ny = double(dy) / double(r);
            const double nz = std::sqrt(std::max(0.0, 1.0 - nx * nx - ny * ny));
            const double l = -0.5 * nx - 0.6 * ny + 0.62 * nz;
            c.v[std::size_t(y) * std::size_t(c.W) + std::size_t(x)] = l > 0.7 ? base + 0.3 : l > 0.3 ? base + 0.12 : base;
            return false;
        });
    };
    bands(a, ra, 0.35);
    bands(b, rb, 0.5);
    c.polygon({c.s(20, 230), c.s(300, 230), c.s(290, 200), c.s(30, 205)}, flat(0.15));
}

struct Kind {
    const char* name;
    void (*draw)(Canvas&);
};

constexpr Kind kKinds[] = {
    {"drawing", draw_drawing}, {"cartoon", draw_cartoon}, {"screenshot", draw_screenshot}, {"icons", draw_icons},
    {"map", draw_map},         {"scene", draw_scene},     {"chart", draw_chart},           {"pixelart", draw_pixelart},
    {"cel", draw_cel},
};

}  // namespace

const std::vector<std::string>& drawing_kinds() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Kind& k : kKinds) n.push_back(k.name);
        return n;
    }();
    return names;
}

void binomial_blur(Image* im, int passes) {
    const int W = im->width, H = im->height;
    std::vector<std::uint32_t> row;
    for (int pass = 0; pass < passes; ++pass) {
        for (int y = 0; y < H; ++y) {
            row.assign(im->samples.begin() + std::ptrdiff_t(y) * W, im->samples.begin() + std::ptrdiff_t(y + 1) * W);
            for (int x = 0; x < W; ++x) {
                const std::uint32_t l = row[std::size_t(x > 0 ? x - 1 : 0)], r = row[std::size_t(x + 1 < W ? x + 1 : W - 1)];
                im->at(x, y) = std::uint16_t((l + 2 * row[std::size_t(x)] + r + 2) / 4);
            }
        }
        for (int x = 0; x < W; ++x) {
            row.resize(std::size_t(H));
            for (int y = 0; y < H; ++y) row[std::size_t(y)] = im->at(x, y);
            for (int y = 0; y < H; ++y) {
                const std::uint32_t u = row[std::size_t(y > 0 ? y - 1 : 0)], d = row[std::size_t(y + 1 < H ? y + 1 : H - 1)];
                im->at(x, y) = std::uint16_t((u + 2 * row[std::size_t(y)] + d + 2) / 4);
            }
        }
    }
}

Status draw_picture(const DrawingParams& p, Image* out) {
    const Kind* kind = nullptr;
    for (const Kind& k : kKinds)
        if (p.kind == k.name) kind = &k;
    if (!kind) {
        std::string list;
        for (const Kind& k : kKinds) list += std::string(list.empty() ? "" : ", ") + k.name;
        return Status::bad_input("synth: unknown kind '" + p.kind + "' (kinds: mixed, " + list + ")");
    }
    if (p.width < 8 || p.height < 8 || p.width > kMaxImageSide || p.height > kMaxImageSide)
        return Status::bad_input("synth: a drawing's width and height must be 8 to " + std::to_string(kMaxImageSide));
    if (std::int64_t(p.width) * p.height > kMaxImagePixels)
        return Status::bad_input("synth: " + std::to_string(p.width) + " x " + std::to_string(p.height) + " is above the limit of " +
                                 std::to_string(kMaxImagePixels) + " pixels");
    if (p.bits < 1 || p.bits > 16) return Status::bad_input("synth: bits must be 1 to 16");
    if (p.blur < 0 || p.blur > 64) return Status::bad_input("synth: blur must be 0 to 64");
    Canvas c(p.width, p.height);
    kind->draw(c);
    const std::uint32_t maxval = (std::uint32_t(1) << p.bits) - 1;
    Image im(p.width, p.height, maxval);
    for (std::size_t i = 0; i < im.samples.size(); ++i) {
        const double s = std::min(1.0, std::max(0.0, c.v[i])) * double(maxval);
        im.samples[i] = std::uint16_t(std::uint32_t(s + 0.5));
    }
    binomial_blur(&im, p.blur);
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd
