// Colour to gray: BT.601 luma, the conversion erd applied to every colour input before images had
// channels, kept exactly for `--gray` and for the steps that work on one plane.
#pragma once
#include <cstddef>
#include <cstdint>

#include "algorithms/imaging/image.h"
#include "algorithms/imaging/real_image.h"

namespace erd {

// (299 R + 587 G + 114 B + 500) / 1000 per pixel, in integers (exact for 16-bit samples), so the
// result is the same for an 8-bit and a 16-bit file of the same picture scaled. A gray image is
// returned unchanged.
inline Image luma(const Image& im) {
    if (im.channels != 3) return im;
    if (im.real()) return real_luma(im);
    Image g(im.width, im.height, im.maxval);
    const std::uint16_t* p = im.samples.data();
    for (std::size_t i = 0; i < g.samples.size(); ++i, p += 3)
        g.samples[i] = std::uint16_t((299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u);
    return g;
}

// True when the three channels of a colour image are equal at every pixel (false for gray).
inline bool channels_equal(const Image& im) {
    if (im.channels != 3) return false;
    const std::uint16_t* p = im.samples.data();
    for (std::size_t i = 0, n = im.pixels(); i < n; ++i, p += 3)
        if (p[0] != p[1] || p[0] != p[2]) return false;
    return true;
}

// A colour image whose channels are all equal as the gray image of the same samples.
inline void gray_if_channels_equal(Image* im) {
    if (!channels_equal(*im)) return;
    const std::size_t n = im->pixels();
    for (std::size_t i = 0; i < n; ++i) im->samples[i] = im->samples[3 * i];
    im->samples.resize(n);
    im->samples.shrink_to_fit();
    im->channels = 1;
}

}  // namespace erd
