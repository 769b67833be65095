#include "imageio/png.h"

#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include <zlib.h>

#include "algorithms/imaging/luma.h"
#include "imageio/messages.h"
#include "third_party/stb_glue.h"

namespace erd::imageio {

namespace {

const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint64_t be32(const unsigned char* p) {
    return std::uint64_t(p[0]) << 24 | std::uint64_t(p[1]) << 16 | std::uint64_t(p[2]) << 8 | p[3];
}

}  // namespace

Status decode_png(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    int w = 0, h = 0, ch = 0;
    bool is16 = false;
    std::string why;
    if (size < 8 || std::memcmp(data, kPng, 8) != 0) return Status::bad_input("not a PNG file (no PNG signature)");
    // Apple's CgBI variant (Xcode's "iPhone optimised" PNG: a CgBI chunk before IHDR, BGRA byte
    // order, premultiplied alpha, deflate without the zlib wrapper) carries the PNG signature but
    // is no PNG: stb would decode it with its colours changed. Refused by name, before IDAT.
    for (std::size_t at = 8; at + 8 <= size;) {
        if (std::memcmp(data + at + 4, "CgBI", 4) == 0)
            return Status::bad_input("an Apple CgBI file (Xcode's iPhone-optimised PNG: byte-swapped BGRA, raw deflate), not a "
                                     "standard PNG; convert it first (xcrun pngcrush -revert-iphone-optimizations)");
        if (std::memcmp(data + at + 4, "IDAT", 4) == 0 || std::memcmp(data + at + 4, "IEND", 4) == 0) break;
        at += 12 + std::size_t(be32(data + at));
    }
    // Sizes from IHDR ourselves first, so a too-large image gets our message, not stb's "too large".
    if (size >= 24 && std::memcmp(data + 12, "IHDR", 4) == 0) {
        Status s = check_side("PNG width", be32(data + 16), limits);
        if (s) s = check_side("PNG height", be32(data + 20), limits);
        if (!s) return s;
    }
    if (!stb::info(data, size, &w, &h, &ch, &is16, &why)) return Status::bad_input("PNG rejected by the decoder: " + printable(why));
    if (w <= 0 || h <= 0) return Status::bad_input("PNG: width or height is 0");
    Status s = check_side("PNG width", std::uint64_t(w), limits);
    if (!s) return s;
    if (!(s = check_side("PNG height", std::uint64_t(h), limits))) return s;
    if (!(s = check_pixels("PNG ", std::uint64_t(w), std::uint64_t(h), limits))) return s;
    const std::uint64_t pixels = std::uint64_t(w) * std::uint64_t(h);
    // Deflate expands at most 1032:1, so a small file cannot hold a large image: refuse before
    // stb reserves memory for the pixel data the header promises.
    const std::uint64_t bytes_per = std::uint64_t(ch < 1 ? 4 : ch) * (is16 ? 2 : 1);
    const std::uint64_t raw = std::uint64_t(h) * (1 + std::uint64_t(w) * bytes_per);
    if (raw > 1040 * std::uint64_t(size) + 4096)
        return Status::bad_input("PNG: " + std::to_string(w) + " x " + std::to_string(h) + " needs " + std::to_string(raw) +
                                 " bytes of pixel data, more than " + std::to_string(size) +
                                 " compressed bytes can hold (truncated or corrupt)");
    // Room for the compressed stream, the inflated rows and the output, with slack for stb's growth.
    const std::size_t budget = std::size_t(3 * raw + 2 * pixels * bytes_per + 4 * std::uint64_t(size) + (1u << 20));
    stb::Decoded png;
    bool short_palette = false;
    std::string padded;
    std::size_t entries = 0;
    if (Status p = pad_png_palette(data, size, 0, &short_palette, &padded, &entries); !p) return p;
    if (short_palette) {
        // Decoded with the missing entries black, then white: a pixel that changes uses one.
        auto bytes = [](const std::string& b) { return reinterpret_cast<const unsigned char*>(b.data()); };
        if (!stb::decode(bytes(padded), padded.size(), budget, &png, &why))
            return Status::bad_input("PNG rejected by the decoder: " + printable(why));
        stb::Decoded white;
        (void)pad_png_palette(data, size, 255, &short_palette, &padded, &entries);
        if (!stb::decode(bytes(padded), padded.size(), budget, &white, &why))
            return Status::bad_input("PNG rejected by the decoder: " + printable(why));
        for (std::size_t k = 0; k < png.samples.size(); ++k)
            if (png.samples[k] != white.samples[k])
                return Status::bad_input("PNG pixel " + at((long long)(k / std::size_t(png.channels) % std::size_t(png.width)),
                                                           (long long)(k / std::size_t(png.channels) / std::size_t(png.width))) +
                                         " uses a palette index beyond the " + std::to_string(entries) +
                                         " entries of its PLTE chunk");
    } else if (!stb::decode(data, size, budget, &png, &why)) {
        return Status::bad_input("PNG rejected by the decoder: " + printable(why));
    }
    Image im;
    im.width = png.width;
    im.height = png.height;
    im.maxval = png.bits == 16 ? 65535u : 255u;
    im.channels = png.channels;
    im.samples = std::move(png.samples);
    if (warning && (png.file_channels == 2 || png.file_channels == 4))
        *warning = "PNG alpha channel ignored (erd meshes the colour or gray channels only)";
    gray_if_channels_equal(&im);
    *out = std::move(im);
    return Status::success();
}

Status pad_png_palette(const unsigned char* d, std::size_t n, unsigned char fill, bool* short_palette, std::string* padded,
                       std::size_t* entries) {
    *short_palette = false;
    if (n < 33 || std::memcmp(d, kPng, 8) != 0 || std::memcmp(d + 12, "IHDR", 4) != 0) return Status::success();
    const unsigned depth = d[24], colour = d[25];
    if (colour != 3 || depth == 0 || depth > 8) return Status::success();
    const std::size_t need = std::size_t(1) << depth;
    std::size_t pos = 8, plte = 0, plte_len = 0;
    while (pos + 12 <= n) {
        const std::uint64_t len = be32(d + pos);
        if (len > n - pos - 12) break;
        if (std::memcmp(d + pos + 4, "PLTE", 4) == 0 && plte == 0) {
            plte = pos;
            plte_len = std::size_t(len);
        }
        if (std::memcmp(d + pos + 4, "tRNS", 4) == 0 && plte != 0 && len > plte_len / 3)
            return Status::bad_input("PNG tRNS chunk has " + std::to_string(len) + " entries, more than the " +
                                     std::to_string(plte_len / 3) + " of its palette");
        if (std::memcmp(d + pos + 4, "IEND", 4) == 0) break;
        pos += std::size_t(12 + len);
    }
    if (plte == 0 || plte_len % 3 != 0 || plte_len / 3 >= need) return Status::success();  // stb judges the rest
    *short_palette = true;
    *entries = plte_len / 3;
    // The same file with a longer PLTE (stb does not check CRCs, so the old one is kept).
    const std::size_t new_len = 3 * need;
    padded->assign(reinterpret_cast<const char*>(d), plte + 8);
    (*padded)[plte] = char(new_len >> 24);
    (*padded)[plte + 1] = char(new_len >> 16 & 0xff);
    (*padded)[plte + 2] = char(new_len >> 8 & 0xff);
    (*padded)[plte + 3] = char(new_len & 0xff);
    padded->append(reinterpret_cast<const char*>(d + plte + 8), plte_len);
    padded->append(new_len - plte_len, char(fill));
    padded->append(reinterpret_cast<const char*>(d + plte + 8 + plte_len), n - plte - 8 - plte_len);
    return Status::success();
}

namespace {

void put32(std::string* out, std::uint32_t v) {
    out->push_back(char(v >> 24));
    out->push_back(char(v >> 16 & 0xff));
    out->push_back(char(v >> 8 & 0xff));
    out->push_back(char(v & 0xff));
}

void chunk(std::string* out, const char* type, const std::string& body) {
    put32(out, std::uint32_t(body.size()));
    const std::size_t start = out->size();
    out->append(type, 4);
    out->append(body);
    const auto* p = reinterpret_cast<const Bytef*>(out->data() + start);
    put32(out, std::uint32_t(crc32(crc32(0L, Z_NULL, 0), p, uInt(body.size() + 4))));
}

// The filtered scanlines: each row gets the filter (0 none, 1 sub, 2 up, 3 average, 4 Paeth)
// whose bytes, read as signed, have the smallest sum of magnitudes -- libpng's heuristic, which
// pnmtopng uses. bpp is the bytes of one pixel (the filters' left neighbour distance).
std::vector<unsigned char> filter_rows(const std::vector<unsigned char>& raw, std::size_t stride, std::size_t rows, std::size_t bpp) {
    std::vector<unsigned char> out(rows * (stride + 1));
    std::vector<unsigned char> zero(stride, 0), trial[5];
    for (auto& t : trial) t.resize(stride);
    for (std::size_t y = 0; y < rows; ++y) {
        const unsigned char* cur = raw.data() + y * stride;
        const unsigned char* up = y > 0 ? cur - stride : zero.data();
        std::uint64_t best_cost = UINT64_MAX;
        int best = 0;
        for (int f = 0; f < 5; ++f) {
            unsigned char* t = trial[f].data();
            std::uint64_t cost = 0;
            for (std::size_t i = 0; i < stride; ++i) {
                const int a = i >= bpp ? cur[i - bpp] : 0, b = up[i], c = i >= bpp ? up[i - bpp] : 0;
                int pred = 0;
                switch (f) {
                    case 1: pred = a; break;
                    case 2: pred = b; break;
                    case 3: pred = (a + b) / 2; break;
                    case 4: {
                        const int p = a + b - c, pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p, pc = p > c ? p - c : c - p;
                        pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
                        break;
                    }
                    default: break;
                }
                t[i] = static_cast<unsigned char>(cur[i] - pred);
                cost += t[i] < 128 ? t[i] : 256u - t[i];
            }
            if (cost < best_cost) { best_cost = cost; best = f; }
        }
        unsigned char* o = out.data() + y * (stride + 1);
        o[0] = static_cast<unsigned char>(best);
        std::memcpy(o + 1, trial[best].data(), stride);
    }
    return out;
}

}  // namespace

Status encode_png(const Image& im, std::string* out) {
    if (im.channels != 1 && im.channels != 3) return Status::failure("PNG output: " + std::to_string(im.channels) + " channels");
    const bool wide = im.maxval > 255;
    const std::size_t bps = wide ? 2 : 1, bpp = bps * std::size_t(im.channels);
    const std::size_t stride = std::size_t(im.width) * bpp, rows = std::size_t(im.height);
    std::vector<unsigned char> raw(stride * rows);
    const std::size_t n = im.samples.size();
    if (wide) {
        for (std::size_t k = 0; k < n; ++k) {
            raw[2 * k] = static_cast<unsigned char>(im.samples[k] >> 8);
            raw[2 * k + 1] = static_cast<unsigned char>(im.samples[k] & 0xff);
        }
    } else {
        for (std::size_t k = 0; k < n; ++k) raw[k] = static_cast<unsigned char>(im.samples[k]);
    }
    const std::vector<unsigned char> filtered = filter_rows(raw, stride, rows, bpp);

    // Level 9, strategy Z_FILTERED (as libpng for filtered rows): the smallest of the settings
    // measured (docs/DECISIONS.md, "Images").
    z_stream z{};
    if (deflateInit2(&z, 9, Z_DEFLATED, 15, 9, Z_FILTERED) != Z_OK) return Status::failure("PNG output: zlib failed to start");
    std::string idat(deflateBound(&z, uLong(filtered.size())), '\0');
    z.next_in = const_cast<Bytef*>(filtered.data());
    z.avail_in = uInt(filtered.size());
    z.next_out = reinterpret_cast<Bytef*>(&idat[0]);
    z.avail_out = uInt(idat.size());
    const int rc = deflate(&z, Z_FINISH);
    idat.resize(z.total_out);
    deflateEnd(&z);
    if (rc != Z_STREAM_END) return Status::failure("PNG output: zlib failed to compress");

    std::string ihdr;
    put32(&ihdr, std::uint32_t(im.width));
    put32(&ihdr, std::uint32_t(im.height));
    ihdr.push_back(char(wide ? 16 : 8));
    ihdr.push_back(char(im.channels == 3 ? 2 : 0));  // colour type: 2 RGB, 0 gray
    ihdr.append(3, '\0');                             // deflate, adaptive filtering, no interlace
    out->assign(reinterpret_cast<const char*>(kPng), 8);
    chunk(out, "IHDR", ihdr);
    chunk(out, "IDAT", idat);
    chunk(out, "IEND", std::string());
    return Status::success();
}

}  // namespace erd::imageio
