#include "algorithms/imaging/real_image.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace erd {

namespace {

// Fills every nodata pixel of im (valid[i] == 0) with the values of a valid pixel nearest to it in
// 4-neighbour steps: a breadth-first sweep from the valid pixels that border nodata, in index
// order, each pixel filled from the one that reached it first.
void fill_nodata(Image* im) {
    const std::size_t W = std::size_t(im->width), H = std::size_t(im->height), C = std::size_t(im->channels);
    std::vector<std::uint32_t> queue;
    std::vector<std::uint8_t> done(im->valid);
    for (std::size_t i = 0; i < W * H; ++i) {
        if (!done[i]) continue;
        const std::size_t x = i % W, y = i / W;
        if ((x > 0 && !done[i - 1]) || (x + 1 < W && !done[i + 1]) || (y > 0 && !done[i - W]) || (y + 1 < H && !done[i + W]))
            queue.push_back(std::uint32_t(i));
    }
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const std::size_t i = queue[k], x = i % W, y = i / W;
        const auto reach = [&](std::size_t n) {
            if (done[n]) return;
            done[n] = 1;
            for (std::size_t c = 0; c < C; ++c) im->reals[n * C + c] = im->reals[i * C + c];
            queue.push_back(std::uint32_t(n));
        };
        if (x > 0) reach(i - 1);
        if (x + 1 < W) reach(i + 1);
        if (y > 0) reach(i - W);
        if (y + 1 < H) reach(i + W);
    }
}

}  // namespace

void make_proxy(Image* im) {
    im->maxval = 65535;
    im->samples.resize(im->reals.size());
    // In halves, so that no difference of two finite values overflows; NaN never reaches the cast.
    const double lo = 0.5 * im->lo, half_span = 0.5 * im->hi - lo;
    const double k = half_span > 0 ? 65535.0 / half_span : 0.0;
    for (std::size_t i = 0; i < im->reals.size(); ++i) {
        const double q = (0.5 * im->reals[i] - lo) * k + 0.5;
        im->samples[i] = std::uint16_t(q > 0 ? (q >= 65535.0 ? 65535.0 : q) : 0.0);
    }
}

Status make_real_image(int w, int h, int channels, std::vector<double> values, const RasterMeta& meta, Image* out) {
    const std::size_t W = std::size_t(w), C = std::size_t(channels), n = W * std::size_t(h);
    if (values.size() != n * C) return Status::failure("real image: " + std::to_string(values.size()) + " values for " + std::to_string(n * C) + " samples");
    Image im;
    im.width = w;
    im.height = h;
    im.channels = channels;
    im.meta = meta;
    im.reals = std::move(values);
    std::size_t holes = 0;
    bool any = false;
    double lo = 0, hi = 0;
    std::vector<std::uint8_t> valid(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < C; ++c) {
            const double v = im.reals[i * C + c];
            if (std::isnan(v)) {
                valid[i] = 0;
                continue;
            }
            if (std::isinf(v))
                return Status::bad_input("sample (" + std::to_string(i % W) + ", " + std::to_string(i / W) + ") is " + (v > 0 ? "+" : "-") +
                                         "infinity (only finite values and nodata can be meshed)");
        }
        if (!valid[i]) {
            ++holes;
            continue;
        }
        for (std::size_t c = 0; c < C; ++c) {
            const double v = im.reals[i * C + c];
            if (!any) lo = hi = v;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
            any = true;
        }
    }
    if (!any) return Status::bad_input("every pixel is nodata (nothing to mesh)");
    im.lo = lo;
    im.hi = hi;
    if (holes) {
        im.valid = std::move(valid);
        fill_nodata(&im);
    }
    make_proxy(&im);
    *out = std::move(im);
    return Status::success();
}

Image real_copy(const Image& im) {
    if (im.real()) return im;
    Image r = im;
    r.reals.assign(im.samples.begin(), im.samples.end());
    r.lo = 0;
    r.hi = im.maxval;
    return r;
}

Image real_luma(const Image& im) {
    if (im.channels != 3) return im;
    Image g;
    g.width = im.width;
    g.height = im.height;
    g.meta = im.meta;
    g.valid = im.valid;
    const std::size_t n = im.pixels();
    g.reals.resize(n);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
        const double* p = &im.reals[3 * i];
        const double y = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
        g.reals[i] = y;
        if (!pixel_valid(im, i)) continue;
        g.lo = any ? std::min(g.lo, y) : y;
        g.hi = any ? std::max(g.hi, y) : y;
        any = true;
    }
    make_proxy(&g);
    return g;
}

double lattice_value_between(const Image& im, LatticePoint p, int c) {
    const std::size_t W = std::size_t(im.width), C = std::size_t(im.channels);
    const int x0 = p.x / 2, y0 = p.y / 2, x1 = (p.x + 1) / 2, y1 = (p.y + 1) / 2;
    double sum = 0, all = 0;
    int n = 0, m = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const std::size_t i = std::size_t(y) * W + std::size_t(x);
            const double v = im.reals[i * C + std::size_t(c)];
            all += v;
            ++m;
            if (pixel_valid(im, i)) {
                sum += v;
                ++n;
            }
        }
    return n ? sum / n : all / m;
}

std::size_t valid_pixels(const Image& im) {
    if (im.valid.empty()) return im.pixels();
    return std::size_t(std::count(im.valid.begin(), im.valid.end(), std::uint8_t(1)));
}

}  // namespace erd
