#include "algorithms/imaging/synth.h"

#include <string>
#include <utility>

#include "algorithms/imaging/splitmix.h"

namespace erd {

namespace {

std::int64_t orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx, std::int64_t cy) {
    return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

}  // namespace

Status synth(const SynthParams& p, Image* out) {
    if (p.width < 1 || p.height < 1 || p.width > kMaxImageSide || p.height > kMaxImageSide)
        return Status::bad_input("synth: width and height must be 1 to " + std::to_string(kMaxImageSide));
    if (std::int64_t(p.width) * p.height > kMaxImagePixels)
        return Status::bad_input("synth: " + std::to_string(p.width) + " x " + std::to_string(p.height) +
                                 " is above the limit of " + std::to_string(kMaxImagePixels) + " pixels");
    if (p.bits < 1 || p.bits > 16) return Status::bad_input("synth: bits must be 1 to 16");

    const std::int64_t W = p.width, H = p.height, S = W < H ? W : H;
    const std::uint32_t maxval = (std::uint32_t(1) << p.bits) - 1;
    Image im(p.width, p.height, maxval);

    // Shapes, in integer pixel coordinates scaled from the image size.
    const std::int64_t d1x = W * 30 / 100, d1y = H * 35 / 100, d1r = S * 18 / 100;  // bright disc
    const std::int64_t d2x = W * 72 / 100, d2y = H * 70 / 100, d2r = S * 13 / 100;  // dark shaded disc
    const std::int64_t t0x = W * 12 / 100, t0y = H * 92 / 100;                      // triangle
    const std::int64_t t1x = W * 52 / 100, t1y = H * 96 / 100;
    const std::int64_t t2x = W * 42 / 100, t2y = H * 55 / 100;
    const std::int64_t bx = W * 70 / 100, by = H * 28 / 100, br = S * 30 / 100;     // smooth bump
    const double amp = maxval >= 128 ? double(maxval / 128) : 1.0;

    SplitMix rng{p.seed};
    for (std::int64_t y = 0; y < H; ++y) {
        for (std::int64_t x = 0; x < W; ++x) {
            const double fx = double(x) / double(W), fy = double(y) / double(H);
            double v = 0.22 + 0.38 * fx + 0.14 * fy;  // ramp
            const std::int64_t ex = x - bx, ey = y - by;
            if (br > 0 && ex * ex + ey * ey < br * br) {
                // (1 - r^2/R^2)^2: smooth, with zero slope at its rim.
                double t = 1.0 - double(ex * ex + ey * ey) / double(br * br);
                v += 0.2 * t * t;
            }
            if (x * 4 + y > W * 4 * 88 / 100) v += 0.25;  // slanted step near the right border
            if ((x - d1x) * (x - d1x) + (y - d1y) * (y - d1y) <= d1r * d1r) v = 0.88;
            if ((x - d2x) * (x - d2x) + (y - d2y) * (y - d2y) <= d2r * d2r) v = 0.08 + 0.12 * fy;
            const std::int64_t o0 = orient(t0x, t0y, t1x, t1y, x, y), o1 = orient(t1x, t1y, t2x, t2y, x, y),
                               o2 = orient(t2x, t2y, t0x, t0y, x, y);
            if (((o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0)) && (o0 | o1 | o2) != 0)
                v = 0.62 - 0.2 * fx;
            double s = v * double(maxval);
            if (p.noise) {
                // Uniform integer noise in [-amp, amp] from the top bits of the generator.
                std::uint64_t r = rng.next() >> 11;
                std::uint64_t span = std::uint64_t(2 * amp + 1);
                s += double(std::int64_t(r % span)) - amp;
            }
            if (s < 0) s = 0;
            if (s > double(maxval)) s = double(maxval);
            im.at(int(x), int(y)) = std::uint16_t(std::uint32_t(s + 0.5));
        }
    }
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd
