#include "imageio/pam.h"

#include <cstring>
#include <utility>

#include "algorithms/imaging/luma.h"
#include "imageio/messages.h"

namespace erd::imageio {

Status pam_header(const unsigned char* d, std::size_t n, const ImageLimits& limits, PamHeader* hd) {
    if (n < 3 || d[0] != 'P' || d[1] != '7' || d[2] != '\n') {
        if (n >= 2 && d[0] == 'P' && d[1] == '7' && n < 3) return Status::bad_input("end of file inside the header, after the magic");
        return Status::bad_input("a PAM file starts with 'P7' and a newline");
    }
    std::size_t i = 3;
    std::uint64_t* fields[4] = {&hd->w, &hd->h, &hd->depth, &hd->maxval};
    const char* names[4] = {"WIDTH", "HEIGHT", "DEPTH", "MAXVAL"};
    bool seen[4] = {false, false, false, false};
    for (;;) {
        std::size_t end = i;
        while (end < n && d[end] != '\n') {
            if (d[end] == 0) return Status::bad_input("NUL byte in the header at offset " + std::to_string(end));
            ++end;
        }
        if (end == n) return Status::bad_input("end of file inside the header (no ENDHDR line)");
        std::size_t k = i;
        while (k < end && is_space(d[k])) ++k;
        const std::size_t key = k;
        while (k < end && !is_space(d[k])) ++k;
        const std::string word(reinterpret_cast<const char*>(d + key), k - key);
        while (k < end && is_space(d[k])) ++k;
        i = end + 1;
        if (word.empty() || word[0] == '#' || word == "TUPLTYPE") continue;
        if (word == "ENDHDR") break;
        int f = 0;
        while (f < 4 && word != names[f]) ++f;
        if (f == 4) return Status::bad_input("unknown PAM header keyword '" + show(d + key, word.size(), 0, 16) + "'");
        if (seen[f]) return Status::bad_input(std::string("PAM ") + names[f] + " given twice");
        std::uint64_t v = 0;
        std::size_t digits = k;
        while (k < end && is_digit(d[k]) && v <= 0xffffffffu) v = v * 10 + std::uint64_t(d[k++] - '0');
        while (k < end && is_space(d[k])) ++k;
        if (k == digits || k != end || v > 0xffffffffu)
            return Status::bad_input(std::string("junk where the PAM ") + names[f] + " belongs: '" + show(d, end, digits) + "'");
        *fields[f] = v;
        seen[f] = true;
    }
    for (int f = 0; f < 4; ++f)
        if (!seen[f]) return Status::bad_input(std::string("PAM header has no ") + names[f] + " line");
    Status s = check_side("width", hd->w, limits);
    if (s) s = check_side("height", hd->h, limits);
    if (s) s = check_pixels("", hd->w, hd->h, limits);
    if (!s) return s;
    if (hd->depth < 1 || hd->depth > 4)
        return Status::bad_input("PAM DEPTH " + std::to_string(hd->depth) + ": erd reads 1 (gray), 2 (gray, alpha), 3 (RGB), 4 (RGB, alpha)");
    if (hd->maxval == 0) return Status::bad_input("maxval is 0 (it must be 1 to 65535)");
    if (hd->maxval > 65535) return Status::bad_input("maxval " + std::to_string(hd->maxval) + " is above 65535");
    hd->raster = i;
    return Status::success();
}

Status decode_pam(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    PamHeader hd;
    Status s = pam_header(data, size, limits, &hd);
    if (!s) return s;
    const std::uint64_t bps = hd.maxval < 256 ? 1 : 2, pixels = hd.w * hd.h, expected = pixels * hd.depth * bps;
    const std::uint64_t left = size - hd.raster;
    if (left < expected)
        return Status::bad_input("raster truncated: expected " + std::to_string(expected) + " bytes (" + std::to_string(hd.w) + " x " +
                                 std::to_string(hd.h) + " x " + std::to_string(hd.depth) + " x " + std::to_string(bps) + "), found " +
                                 std::to_string(left));
    const int channels = hd.depth >= 3 ? 3 : 1;
    Image im(int(hd.w), int(hd.h), std::uint32_t(hd.maxval), channels);
    const unsigned char* p = data + hd.raster;
    const std::size_t depth = std::size_t(hd.depth);
    std::uint16_t* o = im.samples.data();
    for (std::size_t px = 0; px < std::size_t(pixels); ++px) {
        for (std::size_t c = 0; c < depth; ++c) {
            const std::size_t k = px * depth + c;
            const std::uint32_t v = bps == 1 ? p[k] : std::uint32_t(p[2 * k]) << 8 | p[2 * k + 1];
            if (v > hd.maxval)
                return Status::bad_input("sample " + std::to_string(v) + " at " + at((long long)(px % hd.w), (long long)(px / hd.w)) +
                                         " is above maxval " + std::to_string(hd.maxval));
            if (c < std::size_t(channels)) *o++ = std::uint16_t(v);
        }
    }
    std::string note;
    if (hd.depth == 2 || hd.depth == 4) note = "PAM alpha channel ignored (erd meshes the colour or gray channels only)";
    if (left > expected)
        note += std::string(note.empty() ? "" : "\n") + "ignored " + std::to_string(left - expected) +
                " bytes after the image (only the first image of a file is read)";
    if (warning) *warning = note;
    gray_if_channels_equal(&im);
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd::imageio
