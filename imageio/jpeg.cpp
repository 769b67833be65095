#include "imageio/jpeg.h"

#include <cstdint>
#include <utility>

#include "algorithms/imaging/luma.h"
#include "imageio/messages.h"
#include "third_party/stb_glue.h"

namespace erd::imageio {

namespace {

std::string hex2(unsigned v) {
    static const char h[] = "0123456789ABCDEF";
    return std::string("FF") + h[v >> 4 & 15] + h[v & 15];
}

// Frame-header markers other than the two stb reads (C0 baseline, C1 extended, C2 progressive
// are read; C4 is DHT, C8 reserved, CC is DAC), named for the message.
const char* unsupported_frame(unsigned m) {
    switch (m) {
        case 0xc3: return "lossless";
        case 0xc5: case 0xc6: case 0xc7: return "hierarchical";
        case 0xc9: case 0xca: return "arithmetic-coded";
        case 0xcb: return "lossless arithmetic-coded";
        case 0xcd: case 0xce: case 0xcf: return "hierarchical arithmetic-coded";
        default: return nullptr;
    }
}

// Samples per file byte above which a JPEG is taken as corrupt rather than decoded: real photos
// hold about 10 samples a byte, flat synthetic baseline files up to about 200; a progressive
// file can declare a huge image in a few bytes (end-of-band runs), and stb would reserve 2 bytes
// of coefficients per sample for it before finding the data missing.
constexpr std::uint64_t kMaxSamplesPerByte = 4096;
constexpr std::uint64_t kFreeSamples = std::uint64_t(1) << 22;

// What the markers before a scan have defined: Huffman tables (bit id for DC, 4 + id for AC),
// quantisation tables (bit id), and the frame's components (id, quantisation table).
struct Tables {
    unsigned huffman = 0, quant = 0;
    unsigned components = 0;
    unsigned char id[3] = {}, quant_of[3] = {};
};

// A DQT segment's tables: each a precision/id byte, then 64 values of 1 or 2 bytes.
Status check_dqt(const unsigned char* p, std::size_t len, unsigned* defined) {
    std::size_t i = 0;
    while (i < len) {
        const unsigned pq = p[i] >> 4, tq = p[i] & 15;
        if (pq > 1 || tq > 3) return Status::bad_input("JPEG corrupt: quantisation table (DQT) with a bad precision or id");
        if (len - i - 1 < 64 * (pq + 1)) return Status::bad_input("JPEG corrupt: quantisation table (DQT) cut short");
        *defined |= 1u << tq;
        i += 1 + 64 * (pq + 1);
    }
    return Status::success();
}

// A DHT segment's tables (payload p, len bytes): each a class/id byte, 16 code counts summing to
// at most 256, then that many symbols. stb 2.27 builds its tables from counts summing above 256
// and writes past its 257-entry array (found by fuzz_jpeg: fuzz/corpus/fuzz_jpeg/
// regress_dht_over_256), so they are refused here first. Each table read sets its bit in
// *defined: bit id for DC tables, bit 4 + id for AC tables.
Status check_dht(const unsigned char* p, std::size_t len, unsigned* defined) {
    std::size_t i = 0;
    while (i < len) {
        if (len - i < 17) return Status::bad_input("JPEG corrupt: Huffman table (DHT) cut short");
        if ((p[i] >> 4) > 1 || (p[i] & 15) > 3) return Status::bad_input("JPEG corrupt: Huffman table (DHT) with a bad class or id");
        std::size_t n = 0;
        for (std::size_t k = 1; k <= 16; ++k) n += p[i + k];
        if (n > 256) return Status::bad_input("JPEG corrupt: Huffman table (DHT) with " + std::to_string(n) + " codes (at most 256)");
        if (len - i - 17 < n) return Status::bad_input("JPEG corrupt: Huffman table (DHT) longer than its segment");
        *defined |= 1u << ((p[i] >> 4) * 4 + (p[i] & 15));
        i += 17 + n;
    }
    return Status::success();
}

// A scan header (SOS payload p, len bytes) may only use tables defined before it: stb 2.27
// decodes with whatever its unset tables hold (uninitialised memory), indexes past its Huffman
// arrays (found by fuzz_jpeg: regress_scan_undefined_table) and multiplies by garbage
// quantisation values (regress_scan_undefined_quant). A baseline scan uses its components' DC and
// AC tables; a progressive DC scan the DC table on its first pass (Ah = 0) and none when refining;
// a progressive AC scan the AC table. Each component's quantisation table must be defined too.
Status check_sos(const unsigned char* p, std::size_t len, const Tables& t, bool progressive) {
    if (len < 1 || len < 1 + 2 * std::size_t(p[0]) + 3 || p[0] == 0)
        return Status::bad_input("JPEG corrupt: scan header (SOS) of " + std::to_string(len + 2) + " bytes");
    const unsigned ns = p[0];
    const unsigned ss = p[1 + 2 * ns], ah = p[3 + 2 * ns] >> 4;
    const bool dc = !progressive || (ss == 0 && ah == 0), ac = !progressive || ss > 0;
    for (unsigned c = 0; c < ns; ++c) {
        const unsigned td = p[2 + 2 * c] >> 4, ta = p[2 + 2 * c] & 15;
        const char* missing = dc && (td > 3 || !(t.huffman >> td & 1))        ? "DC"
                              : ac && (ta > 3 || !(t.huffman >> (4 + ta) & 1)) ? "AC"
                                                                              : nullptr;
        if (missing)
            return Status::bad_input(std::string("JPEG corrupt: a scan uses Huffman table ") + missing + " " +
                                     std::to_string(*missing == 'D' ? td : ta) + ", which no DHT segment before it defines");
        for (unsigned f = 0; f < t.components; ++f)
            if (t.id[f] == p[1 + 2 * c] && !(t.quant >> (t.quant_of[f] & 15) & 1))
                return Status::bad_input("JPEG corrupt: a scan uses quantisation table " + std::to_string(t.quant_of[f]) +
                                         ", which no DQT segment before it defines");
    }
    return Status::success();
}

// The segments that define or use tables (DHT, DQT, SOS), wherever they are in the file; others pass.
Status check_tables(unsigned m, const unsigned char* p, std::size_t len, Tables* t, bool progressive) {
    switch (m) {
        case 0xc4: return check_dht(p, len, &t->huffman);
        case 0xdb: return check_dqt(p, len, &t->quant);
        case 0xda: return check_sos(p, len, *t, progressive);
        default: return Status::success();
    }
}

}  // namespace

Status jpeg_header(const unsigned char* d, std::size_t n, const ImageLimits& limits, JpegHeader* hd) {
    if (n < 3 || d[0] != 0xff || d[1] != 0xd8 || d[2] != 0xff) return Status::bad_input(wrong_magic(d, n));
    std::size_t pos = 2;
    bool frame = false;
    Tables tables;  // defined so far
    for (;;) {
        if (pos >= n) return Status::bad_input("JPEG truncated: the file ends before the image data (no SOS marker)");
        if (d[pos] != 0xff)
            return Status::bad_input("JPEG corrupt: byte " + std::to_string(pos) + " should start a marker (FF) but is " +
                                     show(d, n, pos, 1));
        while (pos < n && d[pos] == 0xff) ++pos;  // fill bytes
        if (pos >= n) return Status::bad_input("JPEG truncated: the file ends inside a marker");
        const unsigned m = d[pos++];
        if (m == 0xd9) return Status::bad_input("JPEG has no image data (end-of-image marker before any scan)");
        if (m == 0x01 || (m >= 0xd0 && m <= 0xd7)) continue;  // markers without a length
        if (pos + 2 > n) return Status::bad_input("JPEG truncated: the file ends inside the " + hex2(m) + " marker");
        const std::size_t len = std::size_t(d[pos]) << 8 | d[pos + 1];
        if (len < 2) return Status::bad_input("JPEG corrupt: marker " + hex2(m) + " has length " + std::to_string(len));
        if (pos + len > n) return Status::bad_input("JPEG truncated: the file ends inside the " + hex2(m) + " segment");
        const unsigned char* s = d + pos + 2;
        if (m == 0xda && !frame) return Status::bad_input("JPEG corrupt: image data (SOS) before any frame header");
        if (Status st = check_tables(m, s, len - 2, &tables, hd->progressive); !st) return st;
        if (const char* kind = unsupported_frame(m))
            return Status::bad_input(std::string("JPEG is ") + kind + " (frame marker " + hex2(m) +
                                     "): erd reads baseline and progressive Huffman JPEG; convert it to PNG");
        if (m == 0xc0 || m == 0xc1 || m == 0xc2) {
            if (frame) return Status::bad_input("JPEG corrupt: two frame headers");
            if (len < 8) return Status::bad_input("JPEG corrupt: frame header of " + std::to_string(len) + " bytes");
            frame = true;
            hd->progressive = m == 0xc2;
            hd->precision = s[0];
            const std::uint64_t h = std::uint64_t(s[1]) << 8 | s[2], w = std::uint64_t(s[3]) << 8 | s[4];
            hd->components = s[5];
            if (hd->precision != 8)
                return Status::bad_input("JPEG with " + std::to_string(hd->precision) +
                                         "-bit samples: erd reads 8-bit JPEG; convert it to 16-bit PNG");
            if (h == 0) return Status::bad_input("JPEG height is 0 (defined later by a DNL marker, which erd does not read)");
            Status st = check_side("JPEG width", w, limits);
            if (st) st = check_side("JPEG height", h, limits);
            if (st) st = check_pixels("JPEG ", w, h, limits);
            if (!st) return st;
            if (hd->components == 4)
                return Status::bad_input("JPEG has 4 components (CMYK or YCCK): erd reads gray and RGB; convert it to RGB first");
            if (hd->components != 1 && hd->components != 3)
                return Status::bad_input("JPEG has " + std::to_string(hd->components) + " components: erd reads 1 (gray) or 3 (colour)");
            if (len < 8 + 3 * std::size_t(hd->components))
                return Status::bad_input("JPEG corrupt: frame header too short for its " + std::to_string(hd->components) + " components");
            hd->width = int(w);
            hd->height = int(h);
            tables.components = unsigned(hd->components);
            for (int c = 0; c < hd->components; ++c) {
                tables.id[c] = s[6 + 3 * c];
                tables.quant_of[c] = s[8 + 3 * c];
            }
        }
        pos += len;
        if (m == 0xda) break;  // start of scan: entropy-coded data follows
    }
    // In entropy-coded data every FF byte is followed by 00 or a marker, so FF D9 after the first
    // scan is the end-of-image marker; a file without it was cut short (stb would decode the
    // missing part as flat gray without a word).
    // The Huffman and quantisation tables and the scan headers between the scans of a progressive
    // file are checked the same way (FF C4, FF DB and FF DA are markers there too).
    bool end = false;
    for (std::size_t k = pos; k + 1 < n; ++k) {
        if (d[k] != 0xff) continue;
        const unsigned m = d[k + 1];
        if (m == 0xd9) { end = true; break; }
        if (m != 0xc4 && m != 0xda && m != 0xdb) continue;
        if (k + 4 > n) return Status::bad_input("JPEG truncated: the file ends inside the " + hex2(m) + " marker");
        const std::size_t len = std::size_t(d[k + 2]) << 8 | d[k + 3];
        if (len < 2 || k + 2 + len > n) return Status::bad_input("JPEG truncated: the file ends inside the " + hex2(m) + " segment");
        if (Status st = check_tables(m, d + k + 4, len - 2, &tables, hd->progressive); !st) return st;
        k += 1 + len;
    }
    if (!end) return Status::bad_input("JPEG truncated: no end-of-image marker (FF D9) after the image data");
    const std::uint64_t samples = std::uint64_t(hd->width) * std::uint64_t(hd->height) * std::uint64_t(hd->components);
    if (samples > kMaxSamplesPerByte * std::uint64_t(n) + kFreeSamples)
        return Status::bad_input("JPEG " + std::to_string(hd->width) + " x " + std::to_string(hd->height) + " in " +
                                 std::to_string(n) + " bytes is more than " + std::to_string(kMaxSamplesPerByte) +
                                 " samples a byte: taken as corrupt (a real picture of that size is larger)");
    return Status::success();
}

Status decode_jpeg(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    JpegHeader hd;
    Status s = jpeg_header(data, size, limits, &hd);
    if (!s) return s;
    // stb keeps each component at full size rounded up to whole MCUs (at most 32 x 32 pixels at
    // 4:1 sampling), 2 bytes of coefficients per sample when progressive, and the output.
    const std::uint64_t padded = (std::uint64_t(hd.width) + 32) * (std::uint64_t(hd.height) + 32);
    const std::uint64_t c = std::uint64_t(hd.components);
    const std::size_t budget = std::size_t(padded * c * (hd.progressive ? 4 : 2) + padded * 4 + 4 * std::uint64_t(size) + (1u << 20));
    stb::Decoded img;
    std::string why;
    if (!stb::decode(data, size, budget, &img, &why)) return Status::bad_input("JPEG rejected by the decoder: " + printable(why));
    if (img.width != hd.width || img.height != hd.height)
        return Status::bad_input("JPEG decoder returned " + std::to_string(img.width) + " x " + std::to_string(img.height) +
                                 ", not the frame header's size");
    Image im;
    im.width = img.width;
    im.height = img.height;
    im.maxval = 255;
    im.channels = img.channels;
    im.samples = std::move(img.samples);
    gray_if_channels_equal(&im);
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd::imageio
