// Quantiles of non-negative floats by histogram (the edge detector's thresholds: counted in
// canny_pass.cpp, selected in canny_track.cpp): the bin of the k-th largest from the counts, then
// selection among that bin's values alone.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace erd::canny_detail {

// Monotone bins from the bit pattern of a non-negative float (sign, exponent and 6 mantissa bits:
// 32768 bins, each 1/64 of an octave wide), so a histogram needs no prior pass for the maximum.
// Narrow bins make the streaming pass's bound on tau_low tight (within 1.1%): on bull at beta
// 0.055 it ends with 0.53M points kept for 0.52M strong ones.
constexpr int kBinShift = 17;
inline std::uint32_t float_bin(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u >> kBinShift;
}
constexpr std::uint32_t kFloatBins = 1u << (32 - kBinShift);

// The smallest float in bin b.
inline float bin_floor(std::uint32_t b) {
    const std::uint32_t u = b << kBinShift;
    float v;
    std::memcpy(&v, &u, sizeof v);
    return v;
}

// The bin holding the k-th largest of the values counted in hist[0, n), whose entry i counts bin
// base + i (bins past its end count nothing); base when no bin above it holds k values. *above
// receives the number of values in higher bins.
inline std::uint32_t kth_bin(const std::size_t* hist, std::size_t n, std::size_t k, std::size_t* above, std::uint32_t base = 0) {
    *above = 0;
    std::size_t i = n;
    while (i > 1) {
        --i;
        if (*above + hist[i] >= k) return base + std::uint32_t(i);
        *above += hist[i];
    }
    return base;
}

// The rank (k - above)-th largest of in_bin (the values of the bin kth_bin chose); *at_or_above
// receives the number of values >= the result.
inline float select_in_bin(std::vector<float>* in_bin, std::size_t k, std::size_t above, std::size_t* at_or_above) {
    if (in_bin->empty()) { *at_or_above = above; return 0.0f; }
    const std::size_t r = std::min(k - above, in_bin->size()) - 1;  // rank from the top inside the bin
    std::nth_element(in_bin->begin(), in_bin->begin() + std::ptrdiff_t(r), in_bin->end(), std::greater<float>());
    const float q = (*in_bin)[r];
    std::size_t n = above;
    for (float v : *in_bin) n += v >= q;
    *at_or_above = n;
    return q;
}

}  // namespace erd::canny_detail
