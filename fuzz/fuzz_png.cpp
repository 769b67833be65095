// libFuzzer target for the fenced PNG reader (imageio/png.h decode_png over third_party/stb_glue):
// Debian's stb_image 2.27 compiled PNG-only with a byte budget. Anything that gets past our IHDR
// and size checks reaches stb, so this is where its known weaknesses would show.
//
// Checks: failures are one line with Code::input; successes are well-formed images whose size is
// within the limits. Run with -malloc_limit_mb (fuzz/run.sh sets it) so a budget leak would show.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli/image_io.h"
#include "fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    erd::cli::ImageLimits limits;
    limits.max_side = 2048;
    limits.max_pixels = std::int64_t(1) << 18;
    erd::Image im;
    std::string warning;
    erd::Status s = erd::cli::decode_png(data, size, &im, &warning, limits);
    if (!fuzz_checks::accepted(s)) return 0;
    fuzz_checks::check_image(im, limits);
    if (im.maxval != 255 && im.maxval != 65535) std::abort();
    // 8- and 16-bit results, gray and colour, must survive our PNG writer unchanged.
    {
        std::string bytes;
        if (!erd::cli::encode_png(im, &bytes).ok()) std::abort();
        erd::Image back;
        std::string w;
        if (!erd::cli::decode_png(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &back, &w, limits).ok())
            std::abort();
        if (back.samples != im.samples) std::abort();
    }
    return 0;
}
