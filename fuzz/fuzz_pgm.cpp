// libFuzzer target for our netpbm readers (imageio/pnm.h decode_pnm: PGM, PPM; imageio/pam.h
// decode_pam for "P7" inputs) and the "what is this file" messages.
//
// Checks beyond "no crash": a failure is one non-empty line with Code::input; a success is a
// well-formed image (sizes within the limits, every sample <= maxval) that survives an
// encode/decode round trip unchanged in both P5 and P2. Replay without libFuzzer: fuzz/replay.cpp.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli/image_io.h"
#include "fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    erd::cli::ImageLimits limits;
    limits.max_side = 4096;
    limits.max_pixels = std::int64_t(1) << 20;  // keeps every run fast; the logic is the same
    erd::Image im;
    std::string warning;
    const bool pam = size >= 2 && data[0] == 'P' && data[1] == '7';
    erd::Status s = pam ? erd::cli::decode_pam(data, size, &im, &warning, limits)
                        : erd::cli::decode_pnm(data, size, &im, &warning, limits);
    if (!fuzz_checks::accepted(s)) return 0;
    fuzz_checks::check_image(im, limits);
    for (bool plain : {false, true}) {
        std::string bytes = erd::cli::encode_pnm(im, plain);
        erd::Image back;
        std::string w;
        if (!erd::cli::decode_pnm(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &back, &w, limits).ok())
            std::abort();
        if (back.width != im.width || back.height != im.height || back.maxval != im.maxval || back.channels != im.channels ||
            back.samples != im.samples ||
            !w.empty())
            std::abort();
    }
    return 0;
}
