#include "algorithms/imaging/synth_dem.h"

#include <cmath>
#include <limits>

#include "algorithms/imaging/splitmix.h"

namespace erd {

namespace {

// A hashed value in [0, 1) at lattice point (i, j) of octave k.
double lattice(std::int64_t i, std::int64_t j, int k, std::uint64_t seed) {
    SplitMix m{seed * 0x9e3779b97f4a7c15ull ^ (std::uint64_t(i) * 0xd6e8feb86659fd93ull) ^ (std::uint64_t(j) * 0xa0761d6478bd642full) ^
               (std::uint64_t(k) << 56)};
    return double(m.next() >> 11) * (1.0 / 9007199254740992.0);
}

// Value noise of octave k with cells of `cell` pixels at pixel (x, y): the lattice values blended
// by the smoothstep 3t^2 - 2t^3 in x and y.
double noise(std::int64_t x, std::int64_t y, std::int64_t cell, int k, std::uint64_t seed) {
    const std::int64_t i = x / cell, j = y / cell;
    const double tx = double(x - i * cell) / double(cell), ty = double(y - j * cell) / double(cell);
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    const double a = lattice(i, j, k, seed), b = lattice(i + 1, j, k, seed), c = lattice(i, j + 1, k, seed),
                 d = lattice(i + 1, j + 1, k, seed);
    const double top = a + (b - a) * sx, bottom = c + (d - c) * sx;
    return top + (bottom - top) * sy;
}

std::int64_t orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx, std::int64_t cy) {
    return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

}  // namespace

void dem_row(const DemParams& p, int yy, double* row) {
    const std::int64_t W = p.width, H = p.height, S = W < H ? W : H, y = yy;
    // Faults: lines through two points (per mille of the size), a jump in metres on their left.
    struct Fault {
        std::int64_t ax, ay, bx, by;
    };
    const Fault faults[3] = {{W * 100 / 1000, H * 0, W * 450 / 1000, H}, {0, H * 620 / 1000, W, H * 380 / 1000},
                             {W * 700 / 1000, 0, W * 950 / 1000, H * 550 / 1000}};
    const double jumps[3] = {45.0, -70.0, 110.0};
    const std::int64_t mx = W * 28 / 100, my = H * 74 / 100, mr = S * 9 / 100;  // mesa
    const std::int64_t lakes[5][3] = {{W * 62 / 100, H * 22 / 100, S * 5 / 100}, {W * 40 / 100, H * 45 / 100, S * 3 / 100},
                                      {W * 82 / 100, H * 80 / 100, S * 6 / 100}, {W * 15 / 100, H * 30 / 100, S * 2 / 100},
                                      {W * 55 / 100, H * 88 / 100, S * 4 / 100}};
    for (std::int64_t x = 0; x < W; ++x) {
        // Relief: six octaves of value noise, cells from S/3 down by halves, amplitudes 640 m down.
        double h = 280.0, amp = 640.0;
        std::int64_t cell = S / 3 > 8 ? S / 3 : 8;
        for (int k = 0; k < 6 && cell >= 2; ++k) {
            h += amp * noise(x, y, cell, k, p.seed);
            amp *= 0.45;
            cell /= 2;
        }
        for (int f = 0; f < 3; ++f)
            if (orient(faults[f].ax, faults[f].ay, faults[f].bx, faults[f].by, x, y) > 0) h += jumps[f];
        const std::int64_t dx = x - mx, dy = y - my;
        if (dx * dx + dy * dy <= mr * mr) h = 1250.0 + 0.02 * double(dx);  // a flat mesa, cliffs all round
        double v = double(float(h));
        if (p.holes) {
            for (const auto& l : lakes)
                if ((x - l[0]) * (x - l[0]) + (y - l[1]) * (y - l[1]) <= l[2] * l[2]) v = std::numeric_limits<double>::quiet_NaN();
            // The unsurveyed corner: below a wavy line near the bottom right.
            const std::int64_t edge = W + H - S * 22 / 100 + std::int64_t(double(S) * 0.03 * noise(x, y, S / 8 > 2 ? S / 8 : 2, 7, p.seed));
            if (x + y > edge) v = std::numeric_limits<double>::quiet_NaN();
        }
        row[x] = v;
    }
}

}  // namespace erd
