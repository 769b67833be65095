// Visiting the set points of a mostly empty byte map (edge maps), in increasing index order.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace erd {

// Calls fn(index) for every nonzero byte of data[0..n) in increasing order, skipping zero bytes
// eight at a time (edge maps are mostly empty).
template <class Fn>
void for_each_set(const std::uint8_t* data, std::size_t n, Fn fn) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, data + i, 8);
        if (!word) continue;
        for (std::size_t j = i; j < i + 8; ++j)
            if (data[j]) fn(j);
    }
    for (; i < n; ++i)
        if (data[i]) fn(i);
}

}  // namespace erd
