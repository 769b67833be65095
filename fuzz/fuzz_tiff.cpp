// libFuzzer target for the TIFF reader (imageio/tiff.h: libtiff behind our checks) and the PFM
// reader (imageio/pfm.h), whichever the bytes start as, with the limits lowered.
//
// Checks: failures are one line with Code::input; an accepted image is well formed (an integer one
// as fuzz_checks::check_image; a real one with a value per sample, a mask of the pixels' size when
// it has holes, its range over its valid values); TIFF and PFM written back from it read back to
// the same values, holes and type; a window of the file reads as the same part of the whole.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/imaging/real_image.h"
#include "fuzz/fuzz_checks.h"
#include "imageio/pfm.h"
#include "imageio/tiff.h"

namespace {

using fuzz_checks::check;

void check_real(const erd::Image& im, const erd::imageio::ImageLimits& limits) {
    check(im.width >= 1 && im.height >= 1 && im.width <= limits.max_side && im.height <= limits.max_side);
    check(std::int64_t(im.width) * im.height <= limits.max_pixels);
    check(im.reals.size() == im.pixels() * std::size_t(im.channels) && im.samples.size() == im.reals.size());
    check(im.valid.empty() || im.valid.size() == im.pixels());
    check(im.lo <= im.hi);
    for (std::size_t i = 0; i < im.reals.size(); ++i) {
        check(std::isfinite(im.reals[i]));
        if (erd::pixel_valid(im, i / std::size_t(im.channels))) check(im.reals[i] >= im.lo && im.reals[i] <= im.hi);
    }
}

bool same(const erd::Image& a, const erd::Image& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.real() != b.real()) return false;
    if (!a.real()) return a.samples == b.samples;
    if (a.valid != b.valid && !(a.valid.empty() && b.valid.empty())) return false;
    for (std::size_t i = 0; i < a.reals.size(); ++i)
        if (erd::pixel_valid(a, i / std::size_t(a.channels)) && a.reals[i] != b.reals[i]) return false;
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const erd::imageio::ImageLimits limits = fuzz_checks::image_limits();
    erd::Image im;
    std::string warning;
    const bool pfm = size >= 2 && data[0] == 'P';
    erd::Status s = pfm ? erd::imageio::decode_pfm(data, size, &im, &warning, limits) : erd::imageio::decode_tiff(data, size, &im, &warning, limits);
    if (!fuzz_checks::accepted(s)) return 0;
    if (im.real()) check_real(im, limits);
    else fuzz_checks::check_image(im, limits);
    // Written back as TIFF (its type) and read again: the same values and holes.
    std::string bytes;
    check(erd::imageio::encode_tiff(im, &bytes).ok());
    erd::Image back;
    std::string w;
    check(erd::imageio::decode_tiff(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &back, &w, limits).ok());
    if (!pfm) check(same(im, back) && back.meta.type == im.meta.type && back.meta.geo == im.meta.geo);
    if (!pfm && im.width > 1 && im.height > 1) {
        // A window reads as the same part of the whole.
        erd::imageio::TiffReader r;
        check(r.open(data, size, limits).ok());
        erd::Image part;
        const int x0 = im.width / 2, y0 = im.height / 3;
        if (r.read(x0, y0, im.width, im.height, &part, &w).ok() && part.channels == im.channels) {
            for (int y = 0; y < part.height; ++y)
                for (int x = 0; x < part.width; ++x) {
                    const std::size_t i = std::size_t(y) * std::size_t(part.width) + std::size_t(x),
                                      j = std::size_t(y + y0) * std::size_t(im.width) + std::size_t(x + x0);
                    check(erd::pixel_valid(part, i) == erd::pixel_valid(im, j));
                    if (erd::pixel_valid(part, i))
                        for (int c = 0; c < im.channels; ++c)
                            check(erd::sample_value(part, i * std::size_t(im.channels) + std::size_t(c)) ==
                                  erd::sample_value(im, j * std::size_t(im.channels) + std::size_t(c)));
                }
        }
    }
    return 0;
}
