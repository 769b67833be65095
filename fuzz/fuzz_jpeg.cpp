// libFuzzer target for the fenced JPEG reader (imageio/jpeg.h decode_jpeg over third_party/
// stb_glue): our marker walk first (frame header, components, coding, end-of-image marker, the
// samples-per-byte cap), then Debian's stb_image 2.27 with a byte budget. Seeds: fuzz/corpus/
// fuzz_jpeg (fuzz/make_jpeg_seeds.sh), among them a truncated, a CMYK and a progressive huge one.
//
// Checks: failures are one line with Code::input; successes are well-formed 8-bit gray or RGB
// images within the limits that survive our PNG writer unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "imageio/jpeg.h"
#include "imageio/png.h"
#include "fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    erd::imageio::ImageLimits limits;
    limits.max_side = 2048;
    limits.max_pixels = std::int64_t(1) << 18;
    erd::Image im;
    std::string warning;
    erd::Status s = erd::imageio::decode_jpeg(data, size, &im, &warning, limits);
    if (!fuzz_checks::accepted(s)) return 0;
    fuzz_checks::check_image(im, limits);
    if (im.maxval != 255) std::abort();
    std::string bytes;
    if (!erd::imageio::encode_png(im, &bytes).ok()) std::abort();
    erd::Image back;
    std::string w;
    if (!erd::imageio::decode_png(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &back, &w, limits).ok())
        std::abort();
    if (back.samples != im.samples || back.channels != im.channels) std::abort();
    return 0;
}
