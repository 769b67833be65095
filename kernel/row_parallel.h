// Row-parallel work: a range of rows (or bands, or faces) cut into contiguous parts, one thread
// each. The image stages that use it (MMSODD, error diffusion's density, edge detection's
// gradient, reconstruction, the PSNR) compute every row from the input alone, never from another
// part's results, and reduce in part order with exact arithmetic, so their outputs are the same
// bits for any thread count (tests/test_row_parallel.cpp runs 1, 2 and 3).
//
// Threads are std::thread, started per call and joined before it returns: no pool, no state
// outside the call. Compiled with ERD_NO_THREADS (the embedded build), the same parts run one
// after the other on the calling thread, so that build needs no thread support and gives the
// same results.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>
#ifndef ERD_NO_THREADS
#include <thread>
#endif

namespace erd {

// The thread count a request stands for: `threads` when >= 1, else (0 or negative: "the
// machine's") the processors the standard library reports, 1 when it knows none, and always 1
// under ERD_NO_THREADS.
inline int resolve_threads(int threads) {
#ifdef ERD_NO_THREADS
    (void)threads;
    return 1;
#else
    if (threads >= 1) return threads;
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : int(std::min(n, 256u));
#endif
}

// How [begin, end) is cut for `threads` threads with at least `min_items` items per part: parts
// of equal size (the first ones one larger), at most resolve_threads(threads) of them, one for an
// empty or small range.
struct RowParts {
    std::size_t begin = 0, end = 0, count = 1;

    RowParts(std::size_t b, std::size_t e, int threads, std::size_t min_items = 1) : begin(b), end(std::max(b, e)) {
        const std::size_t n = end - begin, per = std::max<std::size_t>(1, min_items);
        count = std::max<std::size_t>(1, std::min(std::size_t(resolve_threads(threads)), n / per));
    }
    std::size_t part_begin(std::size_t k) const {
        const std::size_t n = end - begin, q = n / count, r = n % count;
        return begin + k * q + std::min(k, r);
    }
    std::size_t part_end(std::size_t k) const { return part_begin(k + 1); }
};

// The rows a part needs so that it holds at least `items` items (pixels, samples) of rows with
// `per_row` items each: starting a thread costs tens of microseconds on an idle machine (more
// under load), so the callers give each part a few tenths of a millisecond of work at least.
inline std::size_t rows_for(std::size_t items, std::size_t per_row) {
    return per_row == 0 ? items : (items + per_row - 1) / per_row;
}

// Calls fn(k, part_begin(k), part_end(k)) for every part k, part 0 on the calling thread and
// the others on threads of their own; returns when all have returned. fn must write nothing
// another part reads or writes (its own rows, or a per-part slot indexed by k).
template <class Fn>
void run_parts(const RowParts& parts, Fn fn) {
#ifndef ERD_NO_THREADS
    if (parts.count > 1) {
        std::vector<std::thread> others;
        others.reserve(parts.count - 1);
        for (std::size_t k = 1; k < parts.count; ++k)
            others.emplace_back([&fn, &parts, k] { fn(k, parts.part_begin(k), parts.part_end(k)); });
        fn(std::size_t(0), parts.part_begin(0), parts.part_end(0));
        for (std::thread& t : others) t.join();
        return;
    }
#endif
    for (std::size_t k = 0; k < parts.count; ++k) fn(k, parts.part_begin(k), parts.part_end(k));
}

// The common case: fn(begin, end) on each part of [begin, end).
template <class Fn>
void parallel_rows(std::size_t begin, std::size_t end, int threads, std::size_t min_items, Fn fn) {
    run_parts(RowParts(begin, end, threads, min_items), [&fn](std::size_t, std::size_t b, std::size_t e) { fn(b, e); });
}

}  // namespace erd
