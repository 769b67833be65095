#include "algorithms/imaging/colour.h"

#include <algorithm>

#include "algorithms/imaging/mmsodd.h"
#include "algorithms/imaging/real_image.h"

namespace erd {

Image luma_of(const Image& im) {
    if (im.channels != 3) return im;
    if (im.real()) return real_luma(im);
    Image g(im.width, im.height, im.maxval);
    for (std::size_t i = 0; i < g.samples.size(); ++i) {
        const std::uint16_t* s = &im.samples[3 * i];
        const std::uint64_t y = 299u * std::uint64_t(s[0]) + 587u * std::uint64_t(s[1]) + 114u * std::uint64_t(s[2]);
        g.samples[i] = std::uint16_t((y + 500u) / 1000u);
    }
    return g;
}

Grid<double> colour_mmsodd(const Image& im, int smoothing_order, ColourDensity how, int threads) {
    if (im.channels == 1) return mmsodd(im, smoothing_order, threads);
    if (how == ColourDensity::luma) return mmsodd(luma_of(im), smoothing_order, threads);
    Grid<double> d = mmsodd_channel(im, 0, smoothing_order, threads);
    for (int c = 1; c < im.channels; ++c)
        mmsodd_channel_into(im, c, smoothing_order, how == ColourDensity::sum ? MmsoddInto::add : MmsoddInto::max, &d,
                            threads);
    return d;
}

}  // namespace erd
