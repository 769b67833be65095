#include "imageio/pnm.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "algorithms/imaging/luma.h"
#include "imageio/messages.h"

namespace erd::imageio {

namespace {

// A cursor over the PGM/PPM header. Every failure is one specific line.
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

// Where sample k of a raster lies, for a message: "(x, y)", and the channel in a colour image.
std::string where(std::size_t k, std::size_t w, int channels) {
    const std::size_t c = std::size_t(channels), p = k / c;
    std::string s = at((long long)(p % w), (long long)(p / w));
    if (channels == 3) s += std::string(" channel ") + "RGB"[k % c];
    return s;
}

// P2/P3 raster: decimal samples separated by whitespace (comments allowed, as netpbm does).
Status read_plain(Cursor& c, Image* out, std::uint32_t maxval, std::string* warning) {
    const std::size_t total = out->pixels() * std::size_t(out->channels);
    const std::size_t w = std::size_t(out->width);
    std::vector<std::uint16_t> samples;
    // Each sample takes at least two bytes, so the file bounds the allocation, not the header.
    samples.reserve(std::min(total, (c.n - c.i) / 2 + 1));
    for (std::size_t k = 0; k < total; ++k) {
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
                                     " samples before the end of the file (plain " +
                                     (out->channels == 3 ? "PPM)" : "PGM)"));
        std::size_t start = c.i;
        if (c.d[c.i] == '-' && c.i + 1 < c.n && is_digit(c.d[c.i + 1]))
            return Status::bad_input("sample at " + where(k, w, out->channels) + " is negative: '" + show(c.d, c.n, start) + "'");
        if (!is_digit(c.d[c.i]))
            return Status::bad_input("junk where the sample at " + where(k, w, out->channels) + " belongs: '" + show(c.d, c.n, start) + "'");
        std::uint64_t v = 0;
        bool huge = false;
        while (c.i < c.n && is_digit(c.d[c.i])) {
            v = v * 10 + std::uint64_t(c.d[c.i] - '0');
            if (v > 0xffffffffu) { huge = true; v = 0xffffffffu; }
            ++c.i;
        }
        if (c.i < c.n && !is_space(c.d[c.i]) && c.d[c.i] != '#')
            return Status::bad_input("junk where the sample at " + where(k, w, out->channels) + " belongs: '" + show(c.d, c.n, start) + "'");
        if (huge) return Status::bad_input("sample at " + where(k, w, out->channels) + " is too large: '" + show(c.d, c.n, start, 24) + "'");
        if (v > maxval)
            return Status::bad_input("sample " + std::to_string(v) + " at " + where(k, w, out->channels) + " is above maxval " + std::to_string(maxval));
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

Status pnm_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PnmHeader* hd) {
    if (size < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '3' && data[1] != '5' && data[1] != '6'))
        return Status::bad_input(wrong_magic(data, size));
    hd->plain = data[1] == '2' || data[1] == '3';
    hd->channels = data[1] == '3' || data[1] == '6' ? 3 : 1;
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
    if (!(s = check_pixels("", hd->w, hd->h, limits))) return s;
    // Exactly one whitespace byte ends the header; a comment may stand before it.
    if (c.d[c.i] == '#') {
        if (!(s = c.skip_comment("raster"))) return s;
    }
    hd->sep = c.i;
    return Status::success();
}

Status decode_pnm(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    PnmHeader hd;
    Status s = pnm_header(data, size, limits, &hd);
    if (!s) return s;
    const bool plain = hd.plain;
    const std::uint64_t w = hd.w, h = hd.h, maxval = hd.maxval, ch = std::uint64_t(hd.channels), samples = w * h * ch;
    const std::size_t sep = hd.sep;
    Cursor c{data, size, sep + 1};

    Image im;
    im.width = int(w);
    im.height = int(h);
    im.maxval = std::uint32_t(maxval);
    im.channels = hd.channels;
    if (plain) {
        s = read_plain(c, &im, im.maxval, warning);
        if (!s) return s;
        gray_if_channels_equal(&im);
        *out = std::move(im);
        return Status::success();
    }

    const std::uint64_t bps = maxval < 256 ? 1 : 2;
    const std::uint64_t expected = samples * bps;
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
                          std::to_string(h) + (ch == 3 ? " x 3" : "") + " x " + std::to_string(bps) + "), found " + std::to_string(left);
        if (bps == 2 && left % 2 == 1) msg += " (an odd count: 16-bit samples take 2 bytes)";
        return Status::bad_input(msg);
    }
    if (std::uint64_t(left) > expected) {
        if (!note.empty()) note += "\n";
        note += "ignored " + std::to_string(std::uint64_t(left) - expected) +
                " bytes after the image (only the first image of a file is read)";
    }
    const unsigned char* p = data + c.i;
    const std::size_t n = std::size_t(samples);
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
        return Status::bad_input("sample " + std::to_string(im.samples[k]) + " at " + where(k, std::size_t(w), hd.channels) +
                                 " is above maxval " + std::to_string(maxval));
    }
    if (warning) *warning = note;
    gray_if_channels_equal(&im);
    *out = std::move(im);
    return Status::success();
}

std::string encode_pnm(const Image& im, bool plain) {
    const bool colour = im.channels == 3;
    std::string out = std::string(plain ? (colour ? "P3\n" : "P2\n") : (colour ? "P6\n" : "P5\n")) + std::to_string(im.width) + " " + std::to_string(im.height) +
                      "\n" + std::to_string(im.maxval) + "\n";
    const std::size_t n = im.samples.size();
    if (plain) {
        // At most 70 characters a line, as pgm(5) and ppm(5) ask of plain files.
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

}  // namespace erd::imageio
