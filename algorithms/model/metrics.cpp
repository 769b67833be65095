#include "algorithms/model/metrics.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "algorithms/imaging/real_image.h"
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

// Real images (issue 47): the sums of squared differences per channel over the pixels the original
// has data at, each row summed in order and the rows added in order (so every thread count gives
// the same doubles), and the largest absolute difference. An approximation without data at such a
// pixel is refused.
static Status real_sums(const Image& a, const Image& b, int threads, double sum[3], double* max_abs) {
    const std::size_t C = std::size_t(a.channels), W = std::size_t(a.width), H = std::size_t(a.height);
    std::vector<double> rows(H * 3, 0.0), maxes(H, 0.0);
    std::vector<std::uint8_t> missing(H, 0);
    const RowParts parts(0, H, threads, rows_for(std::size_t(1) << 19, W * C));
    run_parts(parts, [&](std::size_t, std::size_t y0, std::size_t y1) {
        for (std::size_t y = y0; y < y1; ++y) {
            double s[3] = {0, 0, 0}, m = 0;
            for (std::size_t x = 0; x < W; ++x) {
                const std::size_t i = y * W + x;
                if (!a.valid.empty() && !a.valid[i]) continue;
                if (!b.valid.empty() && !b.valid[i]) {
                    missing[y] = 1;
                    continue;
                }
                for (std::size_t c = 0; c < C; ++c) {
                    const double d = sample_value(a, i * C + c) - sample_value(b, i * C + c);
                    s[c] += d * d;
                    m = std::fabs(d) > m ? std::fabs(d) : m;
                }
            }
            for (std::size_t c = 0; c < 3; ++c) rows[y * 3 + c] = s[c];
            maxes[y] = m;
        }
    });
    sum[0] = sum[1] = sum[2] = 0;
    *max_abs = 0;
    for (std::size_t y = 0; y < H; ++y) {
        if (missing[y])
            return Status::bad_input("the approximation has no data at a pixel of row " + std::to_string(y) +
                                     " where the original has");
        for (std::size_t c = 0; c < 3; ++c) sum[c] += rows[y * 3 + c];
        *max_abs = maxes[y] > *max_abs ? maxes[y] : *max_abs;
    }
    return Status::success();
}

static Status check_real_pair(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        return Status::bad_input("sizes differ: " + std::to_string(a.width) + " x " + std::to_string(a.height) + " and " +
                                 std::to_string(b.width) + " x " + std::to_string(b.height));
    if (a.channels != b.channels) return Status::bad_input("one image is colour and the other gray");
    if (a.pixels() == 0) return Status::bad_input("the original image is empty");
    return Status::success();
}

double psnr_peak(const Image& orig) {
    if (!orig.real()) return psnr_peak(orig.maxval);
    return orig.hi > orig.lo ? orig.hi - orig.lo : 1.0;
}

Status max_abs_error(const Image& orig, const Image& approx, double* out, int threads) {
    if (Status s = check_real_pair(orig, approx); !s) return s;
    double sum[3];
    return real_sums(orig, approx, threads, sum, out);
}

Status mse(const Image& orig, const Image& approx, double* out, int threads) {
    if (orig.real() || approx.real()) {
        if (Status s = check_real_pair(orig, approx); !s) return s;
        double sum[3], m = 0;
        if (Status s = real_sums(orig, approx, threads, sum, &m); !s) return s;
        *out = (sum[0] + sum[1] + sum[2]) / double(valid_pixels(orig) * std::size_t(orig.channels));
        return Status::success();
    }
    Status s = check_pair(orig, approx);
    if (!s) return s;
    std::uint64_t sum[3];
    squared_error_sums(orig, approx, threads, sum);
    *out = double(sum[0] + sum[1] + sum[2]) / double(orig.samples.size());
    return Status::success();
}

Status channel_mse(const Image& orig, const Image& approx, double out[3], int threads) {
    if (orig.real() || approx.real()) {
        if (Status s = check_real_pair(orig, approx); !s) return s;
        double sum[3], m = 0;
        if (Status s = real_sums(orig, approx, threads, sum, &m); !s) return s;
        for (std::size_t k = 0; k < std::size_t(orig.channels); ++k) out[k] = sum[k] / double(valid_pixels(orig));
        return Status::success();
    }
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
    if (orig.real() || approx.real()) {
        const double peak = psnr_peak(orig);
        *out = e == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(peak * peak / e);
        return Status::success();
    }
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
