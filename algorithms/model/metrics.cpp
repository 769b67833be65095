#include "algorithms/model/metrics.h"

#include <cmath>
#include <limits>
#include <string>

namespace erd {

double psnr_peak(std::uint32_t maxval) {
    int bits = 0;
    while (bits < 32 && (std::uint64_t(1) << bits) - 1 < maxval) ++bits;
    return double((std::uint64_t(1) << bits) - 1);
}

static Status check_pair(const Image& a, const Image& b) {
    if (a.width <= 0 || a.height <= 0 || a.samples.size() != std::size_t(a.width) * std::size_t(a.height))
        return Status::bad_input("the original image is empty or malformed");
    if (b.width <= 0 || b.height <= 0 || b.samples.size() != std::size_t(b.width) * std::size_t(b.height))
        return Status::bad_input("the approximation is empty or malformed");
    if (a.width != b.width || a.height != b.height)
        return Status::bad_input("sizes differ: " + std::to_string(a.width) + " x " + std::to_string(a.height) + " and " +
                                 std::to_string(b.width) + " x " + std::to_string(b.height));
    if (a.maxval != b.maxval)
        return Status::bad_input("maxvals differ: " + std::to_string(a.maxval) + " and " + std::to_string(b.maxval));
    return Status::success();
}

Status mse(const Image& orig, const Image& approx, double* out) {
    Status s = check_pair(orig, approx);
    if (!s) return s;
    // Exact integer sum: at most 2^28 pixels * 2^32 per squared difference < 2^64.
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < orig.samples.size(); ++i) {
        std::int64_t d = std::int64_t(orig.samples[i]) - std::int64_t(approx.samples[i]);
        sum += std::uint64_t(d * d);
    }
    *out = double(sum) / double(orig.samples.size());
    return Status::success();
}

Status psnr(const Image& orig, const Image& approx, double* out) {
    double e = 0;
    Status s = mse(orig, approx, &e);
    if (!s) return s;
    if (e == 0) {
        *out = std::numeric_limits<double>::infinity();
        return Status::success();
    }
    double peak = psnr_peak(orig.maxval);
    *out = 10.0 * std::log10(peak * peak / e);
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
