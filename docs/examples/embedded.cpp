// The embedded example (`make embedded`): liberd built with -Os -fno-exceptions -fno-rtti, used
// through the public API alone. Makes a 128x96 image in caller-owned memory (a ramp with a
// bright disc and a dark bar: smooth parts and sharp edges), meshes it with ERDGPI at 2% of the
// pixels, reconstructs it with 4x4 supersampling and prints the PSNR. Exits 1 if any call fails
// or the PSNR is implausibly low, so `make test` can run it.
#include <cstdint>
#include <cstdio>
#include <vector>

#include "api/erd.h"

int main() {
    const int w = 128, h = 96;
    std::vector<std::uint16_t> pixels(std::size_t(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int v = 40 + x + y / 2;                                                  // smooth ramp
            if ((x - 44) * (x - 44) + (y - 40) * (y - 40) <= 22 * 22) v = 230;        // disc
            if (x >= 80 && x < 110 && y >= 20 && y < 80 && x - 80 < (y - 20) / 2 + 8) v = 15;  // bar
            pixels[std::size_t(y) * w + std::size_t(x)] = std::uint16_t(v);
        }
    }
    erd::api::ImageView view;
    view.width = w;
    view.height = h;
    view.maxval = 255;
    view.samples = pixels.data();

    erd::api::Options options;
    options.generate.density = 2.0;
    options.generate.density_given = true;
    options.exact = erd::api::ExactMode::warn;
    options.max_memory = std::size_t(8) << 20;  // refuse rather than abort on a small device
    const erd::api::Method method = erd::api::Method::erdgpi;
    std::printf("estimated peak memory: %zu bytes\n", erd::api::memory_estimate(method, w, h, options));

    erd::Model model;
    erd::api::GenerateInfo info;
    erd::Status st = erd::api::generate(method, view, options, &model, &info);
    if (!st) {
        std::fprintf(stderr, "generate: %s\n", st.message.c_str());
        return 1;
    }
    if (!info.warning.empty()) std::fprintf(stderr, "warning: %s\n", info.warning.c_str());

    erd::Image approx;
    st = erd::api::reconstruct(model, true, &approx);
    if (!st) {
        std::fprintf(stderr, "reconstruct: %s\n", st.message.c_str());
        return 1;
    }
    double db = 0;
    st = erd::api::psnr(view, erd::api::view_of(approx), &db);
    if (!st) {
        std::fprintf(stderr, "psnr: %s\n", st.message.c_str());
        return 1;
    }
    std::printf("%s: %zu vertices, %zu faces, %zu constrained edges, PSNR %.2f dB\n", erd::api::method_name(method),
                model.vertices.size(), model.faces.size(), model.constraints.size(), db);
    return db > 25.0 ? 0 : 1;
}
