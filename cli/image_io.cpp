#include "cli/image_io.h"

#include <cstring>
#include <utility>
#include <vector>

#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/report.h"
#include "third_party/stb_glue.h"

namespace erd::cli {

const char* format_name(ImageFormat f) {
    switch (f) {
        case ImageFormat::pgm_plain: return "PGM (P2, plain)";
        case ImageFormat::pgm_raw: return "PGM (P5, raw)";
        case ImageFormat::png: return "PNG";
        case ImageFormat::unknown: break;
    }
    return "unknown";
}

static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

ImageFormat detect_format(const unsigned char* data, std::size_t size) {
    if (size >= 2 && data[0] == 'P' && data[1] == '2') return ImageFormat::pgm_plain;
    if (size >= 2 && data[0] == 'P' && data[1] == '5') return ImageFormat::pgm_raw;
    if (size >= 8 && std::memcmp(data, kPngSignature, 8) == 0) return ImageFormat::png;
    return ImageFormat::unknown;
}

namespace {

// pgm(5) whitespace: space, TAB, LF, VT, FF, CR.
bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }

// A few bytes from data[i] for a message: printable ASCII as is, others as \xNN.
std::string show(const unsigned char* data, std::size_t size, std::size_t i, std::size_t max_chars = 12) {
    static const char hex[] = "0123456789abcdef";
    std::string s;
    std::size_t k = i;
    for (; k < size && k - i < max_chars; ++k) {
        unsigned char c = data[k];
        if (k > i && (is_space(c) || c == '#')) return s;
        if (c >= 0x21 && c < 0x7f) {
            s += char(c);
        } else {
            s += "\\x";
            s += hex[c >> 4];
            s += hex[c & 15];
        }
    }
    // Cut short in the middle of a token: say so.
    if (k < size && !is_space(data[k]) && data[k] != '#') s += "...";
    return s;
}

// stb's reasons may quote raw bytes (an unknown chunk's name): keep messages one printable line.
std::string printable(const std::string& why) {
    std::string out;
    for (unsigned char c : why) {
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            static const char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

std::string at(long long x, long long y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

// Why a file that is not PGM is not: the formats people most often pass by mistake, named.
std::string wrong_magic(const unsigned char* d, std::size_t n) {
    if (n == 0) return "empty file";
    if (n == 1) return "file too short (1 byte) to be an image";
    const char* what = nullptr;
    if (d[0] == 'P') {
        switch (d[1]) {
            case '1': what = "a PBM bitmap (P1, plain)"; break;
            case '4': what = "a PBM bitmap (P4, raw)"; break;
            case '3': what = "a PPM colour image (P3, plain)"; break;
            case '6': what = "a PPM colour image (P6, raw)"; break;
            case '7': what = "a PAM image (P7)"; break;
            case 'F': what = "a PFM colour float image (PF)"; break;
            case 'f': what = "a PFM gray float image (Pf)"; break;
            default: break;
        }
        if (what) return std::string(what) + ", not a PGM: erd reads PGM (P2, P5) and PNG; convert it to gray first";
        return "unknown netpbm magic '" + show(d, n, 0, 2) + "' (a PGM starts with P2 or P5)";
    }
    if (d[0] == 'p' && (d[1] == '2' || d[1] == '5'))
        return std::string("magic 'p") + char(d[1]) + "' is lower case: a PGM starts with 'P" + char(d[1]) + "'";
    if (d[0] == 'p' && d[1] >= '1' && d[1] <= '7')
        return std::string("magic 'p") + char(d[1]) + "' is not a PGM magic (PGM is 'P2' or 'P5', upper case)";
    if (n >= 8 && std::memcmp(d, kPngSignature, 8) == 0) what = "a PNG file";
    else if (n >= 3 && d[0] == 0xff && d[1] == 0xd8 && d[2] == 0xff) what = "a JPEG file";
    else if (n >= 4 && std::memcmp(d, "GIF8", 4) == 0) what = "a GIF file";
    else if (n >= 2 && d[0] == 'B' && d[1] == 'M') what = "a BMP file";
    else if (n >= 4 && (std::memcmp(d, "II*\0", 4) == 0 || std::memcmp(d, "MM\0*", 4) == 0)) what = "a TIFF file";
    else if (n >= 4 && d[0] == 0x89 && d[1] == 'P' && d[2] == 'N' && d[3] == 'G') what = "a damaged PNG file (bad signature)";
    if (what) return std::string(what) + ", not a PGM: erd reads PGM (P2, P5) and PNG";
    return "not a PGM or PNG file (it starts with '" + show(d, n, 0, 8) + "')";
}

// A cursor over the PGM header. Every failure is one specific line.
struct Cursor {
    const unsigned char* d;
    std::size_t n;
    std::size_t i;

    Status nul() const { return Status::bad_input("NUL byte in the header at offset " + std::to_string(i)); }

    // Skips a comment starting at '#': up to and excluding the CR or LF that ends it.
    Status skip_comment(const char* before) {
        while (i < n && d[i] != '\n' && d[i] != '\r') {
            if (d[i] == 0) return nul();
            ++i;
        }
        if (i == n) return Status::bad_input(std::string("end of file inside the header (in a comment, before the ") + before + ")");
        return Status::success();
    }

    // Skips whitespace and comments; fails at the end of the file or on a NUL byte.
    Status skip_space(const char* before) {
        for (;;) {
            if (i == n) return Status::bad_input(std::string("end of file inside the header, before the ") + before);
            unsigned char c = d[i];
            if (c == 0) return nul();
            if (is_space(c)) { ++i; continue; }
            if (c == '#') {
                Status s = skip_comment(before);
                if (!s) return s;
                continue;
            }
            return Status::success();
        }
    }

    // A decimal header number: digits only (no sign, no 0x), ended by whitespace or '#'.
    Status number(const char* what, std::uint64_t* v) {
        Status s = skip_space(what);
        if (!s) return s;
        std::size_t start = i;
        if (!is_digit(d[i])) return Status::bad_input(std::string("junk where the ") + what + " belongs: '" + show(d, n, start) + "'");
        std::uint64_t value = 0;
        bool huge = false;
        while (i < n && is_digit(d[i])) {
            value = value * 10 + std::uint64_t(d[i] - '0');
            if (value > 0xffffffffu) { huge = true; value = 0xffffffffu; }
            ++i;
        }
        if (i == n) return Status::bad_input(std::string("end of file inside the header, after the ") + what);
        if (d[i] == 0) return nul();
        if (!is_space(d[i]) && d[i] != '#')
            return Status::bad_input(std::string("junk where the ") + what + " belongs: '" + show(d, n, start) + "'");
        if (huge)
            return Status::bad_input(std::string(what) + " " + show(d, n, start, 24) + " is too large to represent");
        *v = value;
        return Status::success();
    }
};

Status check_side(const char* what, std::uint64_t v, const ImageLimits& limits) {
    if (v == 0) return Status::bad_input(std::string(what) + " is 0");
    if (v > std::uint64_t(limits.max_side))
        return Status::bad_input(std::string(what) + " " + std::to_string(v) + " is above the limit of " +
                                 std::to_string(limits.max_side) +
                                 " pixels (the bound under which the mesh arithmetic is exact; see docs/manual.md)");
    return Status::success();
}

// P2 raster: decimal samples separated by whitespace (comments allowed, as netpbm does).
Status read_plain(Cursor& c, Image* out, std::uint32_t maxval, std::string* warning) {
    const std::size_t total = std::size_t(out->width) * std::size_t(out->height);
    std::vector<std::uint16_t> samples;
    // Each sample takes at least two bytes, so the file bounds the allocation, not the header.
    samples.reserve(std::min(total, (c.n - c.i) / 2 + 1));
    for (std::size_t k = 0; k < total; ++k) {
        long long x = (long long)(k % std::size_t(out->width)), y = (long long)(k / std::size_t(out->width));
        // Whitespace and comments between samples.
        for (;;) {
            if (c.i < c.n && is_space(c.d[c.i])) { ++c.i; continue; }
            if (c.i < c.n && c.d[c.i] == '#') {
                while (c.i < c.n && c.d[c.i] != '\n' && c.d[c.i] != '\r') ++c.i;
                continue;
            }
            break;
        }
        if (c.i == c.n)
            return Status::bad_input("only " + std::to_string(k) + " of " + std::to_string(total) +
                                     " samples before the end of the file (plain PGM)");
        std::size_t start = c.i;
        if (c.d[c.i] == '-' && c.i + 1 < c.n && is_digit(c.d[c.i + 1]))
            return Status::bad_input("sample at " + at(x, y) + " is negative: '" + show(c.d, c.n, start) + "'");
        if (!is_digit(c.d[c.i]))
            return Status::bad_input("junk where the sample at " + at(x, y) + " belongs: '" + show(c.d, c.n, start) + "'");
        std::uint64_t v = 0;
        bool huge = false;
        while (c.i < c.n && is_digit(c.d[c.i])) {
            v = v * 10 + std::uint64_t(c.d[c.i] - '0');
            if (v > 0xffffffffu) { huge = true; v = 0xffffffffu; }
            ++c.i;
        }
        if (c.i < c.n && !is_space(c.d[c.i]) && c.d[c.i] != '#')
            return Status::bad_input("junk where the sample at " + at(x, y) + " belongs: '" + show(c.d, c.n, start) + "'");
        if (huge) return Status::bad_input("sample at " + at(x, y) + " is too large: '" + show(c.d, c.n, start, 24) + "'");
        if (v > maxval)
            return Status::bad_input("sample " + std::to_string(v) + " at " + at(x, y) + " is above maxval " + std::to_string(maxval));
        samples.push_back(std::uint16_t(v));
    }
    std::size_t rest = c.i;
    while (rest < c.n && is_space(c.d[rest])) ++rest;
    if (rest < c.n && warning)
        *warning = "ignored " + std::to_string(c.n - rest) + " bytes after the image (only the first image of a file is read)";
    out->samples = std::move(samples);
    return Status::success();
}

}  // namespace

Status pgm_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PgmHeader* hd) {
    if (size < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5')) return Status::bad_input(wrong_magic(data, size));
    hd->plain = data[1] == '2';
    Cursor c{data, size, 2};
    if (c.i == size) return Status::bad_input("end of file inside the header, after the magic");
    if (data[2] == 0) return c.nul();
    // A comment directly after the magic is accepted (netpbm does); anything else must be whitespace.
    if (!is_space(data[2]) && data[2] != '#')
        return Status::bad_input("junk after the magic: '" + show(data, size, 0) + "' (the magic must be followed by whitespace)");
    Status s = c.number("width", &hd->w);
    if (!s) return s;
    if (!(s = check_side("width", hd->w, limits))) return s;
    if (!(s = c.number("height", &hd->h))) return s;
    if (!(s = check_side("height", hd->h, limits))) return s;
    if (!(s = c.number("maxval", &hd->maxval))) return s;
    if (hd->maxval == 0) return Status::bad_input("maxval is 0 (it must be 1 to 65535)");
    if (hd->maxval > 65535) return Status::bad_input("maxval " + std::to_string(hd->maxval) + " is above 65535");
    const std::uint64_t pixels = hd->w * hd->h;  // both <= 2^32 - 1 here, and bounded by max_side
    if (std::int64_t(pixels) > limits.max_pixels)
        return Status::bad_input(std::to_string(hd->w) + " x " + std::to_string(hd->h) + " = " + std::to_string(pixels) +
                                 " pixels is above the limit of " + std::to_string(limits.max_pixels) + " pixels (memory)");
    // Exactly one whitespace byte ends the header; a comment may stand before it.
    if (c.d[c.i] == '#') {
        if (!(s = c.skip_comment("raster"))) return s;
    }
    hd->sep = c.i;
    return Status::success();
}

Status decode_pgm(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    PgmHeader hd;
    Status s = pgm_header(data, size, limits, &hd);
    if (!s) return s;
    const bool plain = hd.plain;
    const std::uint64_t w = hd.w, h = hd.h, maxval = hd.maxval, pixels = w * h;
    const std::size_t sep = hd.sep;
    Cursor c{data, size, sep + 1};

    Image im;
    im.width = int(w);
    im.height = int(h);
    im.maxval = std::uint32_t(maxval);
    if (plain) {
        s = read_plain(c, &im, im.maxval, warning);
        if (!s) return s;
        *out = std::move(im);
        return Status::success();
    }

    const std::uint64_t bps = maxval < 256 ? 1 : 2;
    const std::uint64_t expected = pixels * bps;
    std::size_t left = size - c.i;
    std::string note;
    if (data[sep] == '\r' && left > 0 && data[c.i] == '\n') {
        // "255\r\n": pgm(5) takes the CR as the one separator and the LF as the first raster
        // byte (netpbm does the same). When exactly one byte is extra, the writer meant CR LF.
        if (std::uint64_t(left) == expected + 1) {
            ++c.i;
            --left;
            note = "maxval is followed by CR LF; the file holds exactly one byte more than the raster, so the LF was skipped "
                   "(netpbm would shift the pixels by one byte)";
        } else {
            note = "maxval is followed by CR LF; as pgm(5) says, the raster starts at the LF (byte 10), so the pixels "
                   "may look shifted by one byte";
        }
    }
    if (std::uint64_t(left) < expected) {
        std::string msg = "raster truncated: expected " + std::to_string(expected) + " bytes (" + std::to_string(w) + " x " +
                          std::to_string(h) + " x " + std::to_string(bps) + "), found " + std::to_string(left);
        if (bps == 2 && left % 2 == 1) msg += " (an odd count: 16-bit samples take 2 bytes)";
        return Status::bad_input(msg);
    }
    if (std::uint64_t(left) > expected) {
        if (!note.empty()) note += "\n";
        note += "ignored " + std::to_string(std::uint64_t(left) - expected) +
                " bytes after the image (only the first image of a file is read)";
    }
    const unsigned char* p = data + c.i;
    const std::size_t n = std::size_t(pixels);
    // The samples in one pass, the maxval check as a maximum (none for 8-bit maxval 255); only a
    // file with a sample above maxval is searched for the first one.
    std::uint32_t top = 0;
    if (bps == 1) {
        im.samples.assign(p, p + n);  // widened on the way, no zero fill first
        unsigned char m = 0;
        if (im.maxval < 255)  // else no byte can exceed it
            for (std::size_t k = 0; k < n; ++k) m = p[k] > m ? p[k] : m;
        top = m;
    } else {
        im.samples.resize(n);
        std::uint16_t* out_samples = im.samples.data();
        std::uint16_t m = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint16_t v = std::uint16_t(std::uint32_t(p[2 * k]) << 8 | p[2 * k + 1]);
            out_samples[k] = v;
            m = v > m ? v : m;
        }
        top = m;
    }
    if (top > im.maxval) {
        std::size_t k = 0;
        while (im.samples[k] <= im.maxval) ++k;
        return Status::bad_input("sample " + std::to_string(im.samples[k]) + " at " + at((long long)(k % w), (long long)(k / w)) +
                                 " is above maxval " + std::to_string(maxval));
    }
    if (warning) *warning = note;
    *out = std::move(im);
    return Status::success();
}

Status decode_png(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    int w = 0, h = 0, ch = 0;
    bool is16 = false;
    std::string why;
    // Sizes from IHDR ourselves first, so a too-large image gets our message, not stb's "too large".
    if (size >= 24 && std::memcmp(data + 12, "IHDR", 4) == 0) {
        auto be32 = [&](std::size_t k) {
            return std::uint64_t(data[k]) << 24 | std::uint64_t(data[k + 1]) << 16 | std::uint64_t(data[k + 2]) << 8 | data[k + 3];
        };
        Status s = check_side("PNG width", be32(16), limits);
        if (s) s = check_side("PNG height", be32(20), limits);
        if (!s) return s;
    }
    if (!stb::png_info(data, size, &w, &h, &ch, &is16, &why)) return Status::bad_input("PNG rejected by the decoder: " + printable(why));
    if (w <= 0 || h <= 0) return Status::bad_input("PNG: width or height is 0");
    Status s = check_side("PNG width", std::uint64_t(w), limits);
    if (!s) return s;
    if (!(s = check_side("PNG height", std::uint64_t(h), limits))) return s;
    const std::uint64_t pixels = std::uint64_t(w) * std::uint64_t(h);
    if (std::int64_t(pixels) > limits.max_pixels)
        return Status::bad_input("PNG " + std::to_string(w) + " x " + std::to_string(h) + " = " + std::to_string(pixels) +
                                 " pixels is above the limit of " + std::to_string(limits.max_pixels) + " pixels (memory)");
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
    stb::PngImage png;
    bool short_palette = false;
    std::string padded;
    std::size_t entries = 0;
    if (Status p = pad_png_palette(data, size, 0, &short_palette, &padded, &entries); !p) return p;
    if (short_palette) {
        // Decoded with the missing entries black, then white: a pixel that changes uses one.
        auto bytes = [](const std::string& b) { return reinterpret_cast<const unsigned char*>(b.data()); };
        if (!stb::png_decode(bytes(padded), padded.size(), budget, &png, &why))
            return Status::bad_input("PNG rejected by the decoder: " + printable(why));
        stb::PngImage white;
        (void)pad_png_palette(data, size, 255, &short_palette, &padded, &entries);
        if (!stb::png_decode(bytes(padded), padded.size(), budget, &white, &why))
            return Status::bad_input("PNG rejected by the decoder: " + printable(why));
        for (std::size_t k = 0; k < png.gray.size(); ++k)
            if (png.gray[k] != white.gray[k])
                return Status::bad_input("PNG pixel " + at((long long)(k % std::size_t(png.width)), (long long)(k / std::size_t(png.width))) +
                                         " uses a palette index beyond the " + std::to_string(entries) +
                                         " entries of its PLTE chunk");
    } else if (!stb::png_decode(data, size, budget, &png, &why)) {
        return Status::bad_input("PNG rejected by the decoder: " + printable(why));
    }
    Image im;
    im.width = png.width;
    im.height = png.height;
    im.maxval = png.bits == 16 ? 65535u : 255u;
    im.samples = std::move(png.gray);
    if (warning) {
        if (png.channels >= 3) *warning = "colour PNG converted to gray with BT.601 luma (0.299 R + 0.587 G + 0.114 B)";
        if (png.channels == 2 || png.channels == 4) {
            if (!warning->empty()) *warning += "\n";
            *warning += "PNG alpha channel ignored";
        }
    }
    *out = std::move(im);
    return Status::success();
}

Status decode_image(const unsigned char* data, std::size_t size, Image* out, std::string* warning, ImageFormat* format,
                    const ImageLimits& limits) {
    ImageFormat f = detect_format(data, size);
    if (format) *format = f;
    if (f == ImageFormat::png) return decode_png(data, size, out, warning, limits);
    // decode_pgm also explains what an unknown file is.
    return decode_pgm(data, size, out, warning, limits);
}

std::string encode_pgm(const Image& im, bool plain) {
    const char* magic = im.channels == 3 ? (plain ? "P3\n" : "P6\n") : (plain ? "P2\n" : "P5\n");  // samples are interleaved
    std::string out = std::string(magic) + std::to_string(im.width) + " " + std::to_string(im.height) +
                      "\n" + std::to_string(im.maxval) + "\n";
    const std::size_t n = im.samples.size();
    if (plain) {
        // At most 70 characters a line, as pgm(5) asks of plain files.
        std::size_t line = 0;
        for (std::size_t k = 0; k < n; ++k) {
            std::string v = std::to_string(im.samples[k]);
            if (line > 0 && line + 1 + v.size() > 70) { out += '\n'; line = 0; }
            if (line > 0) { out += ' '; ++line; }
            out += v;
            line += v.size();
        }
        out += '\n';
        return out;
    }
    const bool wide = im.maxval > 255;
    std::size_t head = out.size();
    out.resize(head + n * (wide ? 2 : 1));
    char* p = &out[head];
    const std::uint16_t* v = im.samples.data();
    // Two loops rather than a test per sample: each one vectorises.
    if (wide) {
        for (std::size_t k = 0; k < n; ++k) {
            p[2 * k] = char(v[k] >> 8);
            p[2 * k + 1] = char(v[k] & 0xff);
        }
    } else {
        for (std::size_t k = 0; k < n; ++k) p[k] = char(v[k]);
    }
    return out;
}

Status encode_png(const Image& im, std::string* out) {
    if (im.maxval > 255)
        return Status::bad_input("PNG output needs maxval <= 255 (this image has maxval " + std::to_string(im.maxval) +
                                 "); write a .pgm to keep all bits");
    std::vector<unsigned char> px(im.samples.size());
    for (std::size_t k = 0; k < px.size(); ++k) px[k] = static_cast<unsigned char>(im.samples[k]);
    std::vector<unsigned char> bytes;
    if (!stb::png_encode(px.data(), im.width, im.height, im.channels, &bytes)) return Status::failure("PNG encoding failed");
    out->assign(bytes.begin(), bytes.end());
    return Status::success();
}

static bool ends_with_png(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (auto& ch : ext) ch = char(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
    return ext == ".png";
}

Status read_image(const std::string& path, Image* out, std::string* warning, ImageFormat* format, const ImageLimits& limits) {
    if (warning) warning->clear();
    std::string bytes;
    bool more = false;
    Status s = read_file(path, &bytes, kMaxInputBytes, image_framer(limits), &more);
    if (!s) return s;
    const std::string name = escape_name(path == "-" ? "stdin" : path);
    std::string w;
    s = decode_image(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), out, &w, format, limits);
    if (!s) return Status::bad_input(name + ": " + s.message);
    if (more) w += std::string(w.empty() ? "" : "\n") + "ignored the data after the image (a stream is read as far as its header says)";
    if (warning && !w.empty()) {
        // Prefix every line with the file name.
        std::string::size_type i = 0;
        while (i < w.size()) {
            std::string::size_type j = w.find('\n', i);
            if (j == std::string::npos) j = w.size();
            if (!warning->empty()) *warning += "\n";
            *warning += name + ": " + w.substr(i, j - i);
            i = j + 1;
        }
    }
    return Status::success();
}

Status encode_image(const std::string& path, const Image& im, const WriteOptions& options, std::string* bytes) {
    if (im.width <= 0 || im.height <= 0 || (im.channels != 1 && im.channels != 3) ||
        im.samples.size() != im.pixels() * std::size_t(im.channels) || im.maxval < 1 || im.maxval > 65535)
        return Status::failure(escape_name(path) + ": internal error: invalid image " + std::to_string(im.width) + " x " +
                               std::to_string(im.height) + " maxval " + std::to_string(im.maxval));
    if (ends_with_png(path)) {
        Status s = encode_png(im, bytes);
        if (!s) return Status::error(s.code, escape_name(path) + ": " + s.message);
    } else {
        *bytes = encode_pgm(im, options.plain);
    }
    return Status::success();
}

Status write_image(const std::string& path, const Image& im, const WriteOptions& options) {
    std::string bytes;
    Status s = encode_image(path, im, options, &bytes);
    return s ? write_file_atomic(path, bytes) : s;
}

}  // namespace erd::cli
