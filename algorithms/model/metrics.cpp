#include "algorithms/model/metrics.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "kernel/row_parallel.h"

namespace erd {

double psnr_peak(std::uint32_t maxval) {
    int bits = 0;
    while (bits < 32 && (std::uint64_t(1) << bits) - 1 < maxval) ++bits;
    return double((std::uint64_t(1) << bits) - 1);
}

static Status check_pair(const Image& a, const Image& b) {
    auto malformed = [](const Image& im) {
        return im.width <= 0 || im.height <= 0 || (im.channels != 1 && im.channels != 3) ||
               im.samples.size() != im.pixels() * std::size_t(im.channels);
    };
    if (malformed(a)) return Status::bad_input("the original image is empty or malformed");
    if (malformed(b)) return Status::bad_input("the approximation is empty or malformed");
    if (a.width != b.width || a.height != b.height)
        return Status::bad_input("sizes differ: " + std::to_string(a.width) + " x " + std::to_string(a.height) + " and " +
                                 std::to_string(b.width) + " x " + std::to_string(b.height));
    if (a.channels != b.channels) {
        auto kind = [](int c) { return std::to_string(c) + (c == 3 ? " (colour)" : " (gray)"); };
        return Status::bad_input("one image is colour and the other gray: channels " + kind(a.channels) + " and " + kind(b.channels));
    }
    if (a.maxval != b.maxval)
        return Status::bad_input("maxvals differ: " + std::to_string(a.maxval) + " and " + std::to_string(b.maxval));
    return Status::success();
}

// The exact integer sums of squared differences of each channel (c channels interleaved), rows
// in bands of 2^19 samples at least side by side: integer sums, so the bands' order cannot change
// a bit. At most 2^28
// pixels * 2^32 per squared difference < 2^64.
static void squared_error_sums(const Image& a, const Image& b, int threads, std::uint64_t sum[3]) {
    const std::size_t c = std::size_t(a.channels), row = std::size_t(a.width) * c;
    const RowParts parts(0, std::size_t(a.height), threads, rows_for(std::size_t(1) << 19, row));
    std::vector<std::uint64_t> part_sums(parts.count * 3, 0);
    run_parts(parts, [&](std::size_t k, std::size_t y0, std::size_t y1) {
        std::uint64_t s[3] = {0, 0, 0};
        const std::uint16_t* p = a.samples.data();
        const std::uint16_t* q = b.samples.data();
        if (c == 1) {
            for (std::size_t i = y0 * row; i < y1 * row; ++i) {
                const std::int64_t d = std::int64_t(p[i]) - std::int64_t(q[i]);
                s[0] += std::uint64_t(d * d);
            }
        } else {
            for (std::size_t i = y0 * row; i < y1 * row; ++i) {
                const std::int64_t d = std::int64_t(p[i]) - std::int64_t(q[i]);
                s[i % c] += std::uint64_t(d * d);
            }
        }
        for (std::size_t j = 0; j < 3; ++j) part_sums[k * 3 + j] = s[j];
    });
    sum[0] = sum[1] = sum[2] = 0;
    for (std::size_t k = 0; k < parts.count; ++k)
        for (std::size_t j = 0; j < 3; ++j) sum[j] += part_sums[k * 3 + j];
}

Status mse(const Image& orig, const Image& approx, double* out, int threads) {
    Status s = check_pair(orig, approx);
    if (!s) return s;
    std::uint64_t sum[3];
    squared_error_sums(orig, approx, threads, sum);
    *out = double(sum[0] + sum[1] + sum[2]) / double(orig.samples.size());
    return Status::success();
}

Status channel_mse(const Image& orig, const Image& approx, double out[3], int threads) {
    Status s = check_pair(orig, approx);
    if (!s) return s;
    std::uint64_t sum[3];
    squared_error_sums(orig, approx, threads, sum);
    for (std::size_t k = 0; k < std::size_t(orig.channels); ++k) out[k] = double(sum[k]) / double(orig.pixels());
    return Status::success();
}

double psnr_of_mse(double e, std::uint32_t maxval) {
    if (e == 0) return std::numeric_limits<double>::infinity();
    double peak = psnr_peak(maxval);
    return 10.0 * std::log10(peak * peak / e);
}

Status psnr(const Image& orig, const Image& approx, double* out, int threads) {
    double e = 0;
    Status s = mse(orig, approx, &e, threads);
    if (!s) return s;
    *out = psnr_of_mse(e, orig.maxval);
    return Status::success();
}

double mse(const Image& orig, const Image& approx) {
    double e = 0;
    return mse(orig, approx, &e).ok() ? e : std::numeric_limits<double>::quiet_NaN();
}

double psnr(const Image& orig, const Image& approx) {
    double p = 0;
    return psnr(orig, approx, &p).ok() ? p : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace erd
