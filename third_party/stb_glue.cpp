#include "third_party/stb_glue.h"

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace {
// Byte budget for the current decode. Thread-local so concurrent decodes do not share it.
thread_local std::size_t g_budget = 0;
thread_local std::size_t g_used = 0;

struct Header { std::size_t size; std::size_t pad; };

// Every byte the decoder is given starts zeroed (calloc here, the grown part in realloc): stb's
// progressive JPEG decoder reads coefficients of blocks no scan wrote, and with plain malloc the
// decode (even whether it succeeds) depended on what the heap held before (found by the fuzz
// campaign; tests/test_colour_io.cpp, fuzz/corpus/fuzz_jpeg/regress_progressive_unwritten_coefficients).
void* budget_malloc(std::size_t n) {
    if (n > g_budget || g_used > g_budget - n) return nullptr;
    auto* h = static_cast<Header*>(std::calloc(1, sizeof(Header) + n));
    if (!h) return nullptr;
    h->size = n;
    g_used += n;
    return h + 1;
}
void budget_free(void* p) {
    if (!p) return;
    Header* h = static_cast<Header*>(p) - 1;
    g_used -= h->size;
    std::free(h);
}
void* budget_realloc(void* p, std::size_t n) {
    if (!p) return budget_malloc(n);
    Header* h = static_cast<Header*>(p) - 1;
    std::size_t old = h->size;
    if (n > old && (n - old > g_budget || g_used > g_budget - (n - old))) return nullptr;
    auto* nh = static_cast<Header*>(std::realloc(h, sizeof(Header) + n));
    if (!nh) return nullptr;
    if (n > old) std::memset(reinterpret_cast<unsigned char*>(nh + 1) + old, 0, n - old);
    g_used = g_used - old + n;
    nh->size = n;
    return nh + 1;
}
}  // namespace

// stb copies zero bytes from or to a null buffer when a PNG has an empty IDAT chunk
// (memcpy(NULL, p, 0): undefined behaviour that UBSan reports; found by fuzz_png,
// regression seed fuzz/corpus/fuzz_png/regress_empty_idat). Route its memcpy through a
// version that does nothing for zero bytes.
static inline void* stb_safe_memcpy(void* dst, const void* src, std::size_t n) {
    return n == 0 ? dst : std::memcpy(dst, src, n);
}
#include <string.h>
#define memcpy(d, s, n) stb_safe_memcpy(d, s, n)

#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_NO_THREAD_LOCALS
#define STBI_MAX_DIMENSIONS 32768
#define STBI_MALLOC(sz) budget_malloc(sz)
#define STBI_REALLOC(p, newsz) budget_realloc(p, newsz)
#define STBI_FREE(p) budget_free(p)
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
// stb 2.27 shifts a zero by 32 or more when a scan runs short into a marker: its bit reader has
// stopped at the marker (nomore = 1: every byte it adds from then on is 0) and its bit count has
// gone below -7, so stbi__grow_buffer_unsafe computes 0 << (24 - code_bits) with a count >= 32
// (nothings/stb#1293, fixed after 2.27; found by fuzz_jpeg, regression seed fuzz/corpus/fuzz_jpeg/
// regress_scan_short_at_marker). The value shifted is always 0, so that one check is off for stb's
// functions; every other UBSan check stays on (docs/DECISIONS.md "Images").
#if defined(__clang__)
#pragma clang attribute push(__attribute__((no_sanitize("shift-exponent"))), apply_to = function)
#endif
#include <stb/stb_image.h>
#if defined(__clang__)
#pragma clang attribute pop
#endif
#pragma GCC diagnostic pop
#undef memcpy

namespace erd::stb {

// stb's last failure reason. stb builds "XXXX PNG chunk not known" from the raw chunk type, so a
// type with a NUL byte (as read past the end of a truncated file) gives an empty string.
static std::string reason(const char* fallback) {
    const char* r = stbi_failure_reason();
    if (!r) return fallback;
    if (!*r) return "unknown chunk type (truncated file?)";
    return r;
}

// stbi_info may allocate nothing but is given a small budget anyway, in case a future stb does.
constexpr std::size_t kInfoBudget = std::size_t(1) << 20;

// stb keeps its failure reason in a global and writes unknown chunk names into a static buffer,
// so decodes are serialised: erd is not limited by PNG decoding speed, and this keeps concurrent
// library users (two threads reading images) free of data races.
static std::mutex g_stb_mutex;

static bool info_locked(const unsigned char* data, std::size_t size, int* w, int* h, int* channels, bool* is16, std::string* why) {
    if (size > std::size_t(0x7fffffff)) { *why = "file too large"; return false; }
    int len = int(size);
    g_budget = kInfoBudget;
    g_used = 0;
    if (!stbi_info_from_memory(data, len, w, h, channels)) {
        *why = reason("not a PNG or JPEG");
        return false;
    }
    *is16 = stbi_is_16_bit_from_memory(data, len) != 0;
    return true;
}

bool info(const unsigned char* data, std::size_t size, int* w, int* h, int* channels, bool* is16, std::string* why) {
    std::lock_guard<std::mutex> lock(g_stb_mutex);
    return info_locked(data, size, w, h, channels, is16, why);
}

// Copies stb's interleaved pixels, alpha dropped, after checking they are the size info promised.
template <class T>
static bool keep(const T* px, int w, int h, int got, Decoded* out, std::string* why) {
    if (w != out->width || h != out->height || got < 1 || got > 4) {
        *why = "decoder returned an unexpected size";
        return false;
    }
    out->file_channels = got;
    out->channels = got >= 3 ? 3 : 1;
    const std::size_t n = std::size_t(w) * std::size_t(h), c = std::size_t(out->channels), g = std::size_t(got);
    out->samples.resize(n * c);
    std::uint16_t* o = out->samples.data();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < c; ++k) o[i * c + k] = std::uint16_t(px[i * g + k]);
    return true;
}

bool decode(const unsigned char* data, std::size_t size, std::size_t budget_bytes, Decoded* out, std::string* why) {
    int w = 0, h = 0, ch = 0;
    bool is16 = false;
    std::lock_guard<std::mutex> lock(g_stb_mutex);
    if (!info_locked(data, size, &w, &h, &ch, &is16, why)) return false;
    g_budget = budget_bytes;
    g_used = 0;
    int len = int(size), got = 0;
    out->width = w;
    out->height = h;
    out->bits = is16 ? 16 : 8;
    bool ok = false;
    // 16-bit files go through stbi_load_16 only (INPUTS.md); 8-bit and lower through stbi_load.
    if (is16) {
        stbi_us* px = stbi_load_16_from_memory(data, len, &w, &h, &got, 0);
        if (!px) { *why = reason("decode failed"); return false; }
        ok = keep(px, w, h, got, out, why);
        stbi_image_free(px);
    } else {
        stbi_uc* px = stbi_load_from_memory(data, len, &w, &h, &got, 0);
        if (!px) { *why = reason("decode failed"); return false; }
        ok = keep(px, w, h, got, out, why);
        stbi_image_free(px);
    }
    g_budget = 0;
    return ok;
}

}  // namespace erd::stb
