// libFuzzer target for the fenced PNG reader (imageio/png.h decode_png over third_party/stb_glue):
// Debian's stb_image 2.27 compiled PNG-only with a byte budget. Anything that gets past our IHDR
// and size checks reaches stb, so this is where its known weaknesses would show.
//
// Checks: failures are one line with Code::input; successes are well-formed images whose size is
// within the limits; when our row reader (imageio/png_rows.h, `erd tiles`) takes the file too, any
// window of it reads as that part of the whole (a colour image stb made gray: the first channel). Run with -malloc_limit_mb (fuzz/run.sh sets it) so a budget leak would show.
#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli/image_io.h"
#include "fuzz/fuzz_checks.h"
#include "imageio/png_rows.h"

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
    // The row reader on the same bytes: a window, then one above it (a restart), as the whole's parts.
    if (std::FILE* f = fmemopen(const_cast<std::uint8_t*>(data), size, "rb")) {
        erd::imageio::PngRows rows;
        if (rows.open(f, limits).ok()) {
            if (rows.width() != im.width || rows.height() != im.height) std::abort();
            const int wins[2][4] = {{im.width / 3, im.height / 2, im.width, im.height}, {0, 0, im.width / 2 + 1, im.height / 3 + 1}};
            for (const auto& w : wins) {
                erd::Image part;
                if (!rows.read(w[0], w[1], w[2], w[3], &part).ok()) break;  // stb may read what we do not
                const std::size_t C = std::size_t(rows.channels()), IC = std::size_t(im.channels);
                for (int y = w[1]; y < w[3]; ++y)
                    for (int x = w[0]; x < w[2]; ++x)
                        for (std::size_t c = 0; c < IC; ++c)
                            if (part.samples[(std::size_t(y - w[1]) * std::size_t(part.width) + std::size_t(x - w[0])) * C + c] !=
                                im.samples[(std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * IC + c])
                                std::abort();
            }
        }
        std::fclose(f);
    }
    return 0;
}
