#include "cli/framing.h"

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/model/model_io.h"
#include "imageio/pfm.h"

namespace erd::cli {

namespace {

std::uint64_t be32(const unsigned char* p) {
    return std::uint64_t(p[0]) << 24 | std::uint64_t(p[1]) << 16 | std::uint64_t(p[2]) << 8 | p[3];
}

bool space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool digit(unsigned char c) { return c >= '0' && c <= '9'; }

const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// The state of one stream's framing, kept between calls so each byte is looked at once.
struct ImageFrame {
    ImageLimits limits;
    bool header_done = false;
    PnmHeader hd;
    std::size_t pos = 0;        // P2: next byte to scan; PNG: next chunk
    bool in_comment = false, in_token = false;
    std::uint64_t samples = 0;  // P2: samples seen

    Status operator()(const std::string& so_far, std::uint64_t* total) {
        const auto* d = reinterpret_cast<const unsigned char*>(so_far.data());
        const std::size_t n = so_far.size();
        *total = UINT64_MAX;
        if (n >= 1 && d[0] == 0x89) return png(d, n, total);
        if (n >= 3 && d[0] == 0xff && d[1] == 0xd8 && d[2] == 0xff) return jpeg(d, n, total);
        if (n >= 2 && d[0] == 'P' && d[1] == '7') return pam(d, n, total);
        // TIFF: its directories may lie anywhere in it, so to the end (as JPEG).
        if (n >= 2 && ((d[0] == 'I' && d[1] == 'I') || (d[0] == 'M' && d[1] == 'M'))) return Status::success();
        if (n >= 2 && d[0] == 'P' && (d[1] == 'f' || d[1] == 'F')) return pfm(d, n, total);
        if (!header_done) {
            if (n >= 2 && (d[0] != 'P' || (d[1] != '2' && d[1] != '3' && d[1] != '5' && d[1] != '6'))) {
                *total = n;  // not an image: the decoder says what it is
                return Status::success();
            }
            Status s = pnm_header(d, n, limits, &hd);
            if (!s) {
                if (s.message.compare(0, 11, "end of file") != 0) *total = n;  // bad already
                else if (n >= kMaxStreamHeader)
                    return Status::bad_input("no complete PGM/PPM header in the first " + std::to_string(kMaxStreamHeader) + " bytes");
                return Status::success();
            }
            header_done = true;
            pos = hd.sep + 1;
            if (!hd.plain) {
                const std::uint64_t bps = hd.maxval < 256 ? 1 : 2;
                // "maxval\r\n": decode_pnm takes the LF as the separator's pair only when the file
                // ends one byte after the raster, so two bytes more are read: the stream then shows
                // whether it ends there, as a file's size would (found by fuzz_framing).
                const bool crlf = d[hd.sep] == '\r' && !(hd.sep + 1 < n && d[hd.sep + 1] != '\n');
                *total = hd.sep + 1 + hd.w * hd.h * std::uint64_t(hd.channels) * bps + (crlf ? 2 : 0);
                return Status::success();
            }
        }
        // P2/P3: count the samples; a byte no plain PGM or PPM holds ends the reading.
        const std::uint64_t want = hd.w * hd.h * std::uint64_t(hd.channels);
        for (; pos < n; ++pos) {
            const unsigned char c = d[pos];
            if (in_comment) {
                in_comment = c != '\n' && c != '\r';
                continue;
            }
            if (digit(c)) {
                in_token = true;
                continue;
            }
            if (in_token && ++samples == want) {
                *total = pos + 1;
                return Status::success();
            }
            in_token = false;
            if (c == '#') in_comment = true;
            else if (!space(c)) {
                *total = pos + 1;
                return Status::success();
            }
        }
        return Status::success();
    }

    // PAM: the header, then its declared raster.
    Status pam(const unsigned char* d, std::size_t n, std::uint64_t* total) {
        PamHeader h;
        Status s = pam_header(d, n, limits, &h);
        if (s) {
            *total = h.raster + h.w * h.h * h.depth * (h.maxval < 256 ? 1 : 2);
        } else if (s.message.compare(0, 11, "end of file") != 0) {
            *total = n;  // bad already
        } else if (n >= kMaxStreamHeader) {
            return Status::bad_input("no complete PAM header in the first " + std::to_string(kMaxStreamHeader) + " bytes");
        }
        return Status::success();
    }

    // PFM: the header, then its declared raster.
    Status pfm(const unsigned char* d, std::size_t n, std::uint64_t* total) {
        imageio::PfmHeader h;
        Status s = imageio::pfm_header(d, n, limits, &h);
        if (s) {
            *total = h.raster + std::uint64_t(h.width) * std::uint64_t(h.height) * std::uint64_t(h.channels) * 4;
        } else if (s.message.compare(0, 11, "end of file") != 0) {
            *total = n;  // bad already
        } else if (n >= kMaxStreamHeader) {
            return Status::bad_input("no complete PFM header in the first " + std::to_string(kMaxStreamHeader) + " bytes");
        }
        return Status::success();
    }

    // JPEG: the segments (each with its length) up to the first scan, then the entropy-coded data,
    // where an FF byte is followed by 00 (a stuffed FF), a restart marker, another FF (fill) or a
    // marker: the end of image (FF D9), or a segment between the scans of a progressive file
    // (tables, the next scan's header) skipped by its length. Anything else (a header that is not
    // a chain of segments, a length below 2) leaves the stream to be read to its end, as before,
    // for the decoder to name the problem.
    bool jpeg_scan = false, jpeg_to_end = false;
    Status jpeg(const unsigned char* d, std::size_t n, std::uint64_t* total) {
        if (jpeg_to_end) return Status::success();
        if (pos < 2) pos = 2;
        const auto length = [&](std::size_t k) { return std::size_t(d[k + 2]) << 8 | d[k + 3]; };
        while (!jpeg_scan && pos < n) {
            if (d[pos] != 0xff) return jpeg_end();
            if (pos + 1 >= n) return Status::success();
            const unsigned m = d[pos + 1];
            if (m == 0xff) { ++pos; continue; }                        // fill byte
            if ((m >= 0xd0 && m <= 0xd7) || m == 0x01) { pos += 2; continue; }  // no length
            if (m == 0xd8 || m == 0xd9 || m == 0x00) return jpeg_end();
            if (pos + 4 > n) return Status::success();
            if (length(pos) < 2) return jpeg_end();
            pos += 2 + length(pos);
            jpeg_scan = m == 0xda;
        }
        while (jpeg_scan && pos < n) {
            if (d[pos] != 0xff) { ++pos; continue; }
            if (pos + 1 >= n) return Status::success();
            const unsigned m = d[pos + 1];
            if (m == 0xff) { ++pos; continue; }
            if (m == 0x00 || (m >= 0xd0 && m <= 0xd7) || m == 0x01) { pos += 2; continue; }
            if (m == 0xd9) {
                *total = pos + 2;
                return Status::success();
            }
            if (m == 0xd8) return jpeg_end();
            if (pos + 4 > n) return Status::success();
            if (length(pos) < 2) return jpeg_end();
            pos += 2 + length(pos);
        }
        return Status::success();
    }
    Status jpeg_end() {
        jpeg_to_end = true;
        return Status::success();
    }

    // PNG: chunk after chunk up to IEND.
    Status png(const unsigned char* d, std::size_t n, std::uint64_t* total) {
        if (n < 8) return Status::success();
        if (std::memcmp(d, kPng, 8) != 0) {
            *total = n;
            return Status::success();
        }
        if (pos < 8) pos = 8;
        while (pos + 8 <= n) {
            const std::uint64_t len = be32(d + pos);
            if (len > 0x7fffffffu) {
                *total = n;
                return Status::success();
            }
            const std::uint64_t end = pos + 12 + len;
            if (std::memcmp(d + pos + 4, "IEND", 4) == 0) {
                *total = end;
                return Status::success();
            }
            if (end > n) return Status::success();
            pos = std::size_t(end);
        }
        return Status::success();
    }
};

}  // namespace

Framer image_framer(const ImageLimits& limits) {
    auto frame = std::make_shared<ImageFrame>();
    frame->limits = limits;
    return [frame](const std::string& so_far, bool, std::uint64_t* total) { return (*frame)(so_far, total); };
}

namespace {

// Text stops at a NUL byte (text has none: a zero-filled or sparse tail is not read). Text from a
// stream is also checked at 4 KiB, 16 KiB, 64 KiB, ...: the text so far (cut after its last
// whitespace, so no token is split) is parsed, and a definite error stops the reading; an error
// that only says the text ends early does not. The parses cost at most 4/3 of one parse of the
// whole, which a regular file, whose end is known, does not pay. With `erdz`, an .erdz file or
// stream is framed by its header instead.
Framer text_framer(std::function<Status(const std::string&)> parse, bool erdz) {
    auto next = std::make_shared<std::size_t>(4096);
    auto nul_from = std::make_shared<std::size_t>(0);
    return [next, nul_from, parse, erdz](const std::string& so_far, bool stream, std::uint64_t* total) {
        *total = UINT64_MAX;
        if (erdz && so_far.size() >= 4 && is_erdz(so_far)) {  // binary: its header gives the size
            const std::uint64_t n = erdz_stream_size(so_far);
            if (n != 0) *total = n;
            return Status::success();
        }
        if (std::memchr(so_far.data() + *nul_from, 0, so_far.size() - *nul_from)) {
            *total = so_far.size();  // text has no NUL: the parser names the line
            return Status::success();
        }
        *nul_from = so_far.size();
        if (!stream || so_far.size() < *next) return Status::success();
        *next = so_far.size() * 4;
        std::size_t cut = so_far.size();
        while (cut > 0 && !space(static_cast<unsigned char>(so_far[cut - 1]))) --cut;
        Status s = parse(so_far.substr(0, cut));
        if (!s && s.message.find("ends early") == std::string::npos && s.message != "empty file") *total = so_far.size();
        return Status::success();
    };
}

}  // namespace

Framer model_framer(bool triangulation) {
    return text_framer(
        [triangulation](const std::string& text) {
            Model m;
            return triangulation ? read_triangulation(text, &m) : read_model(text, ModelFileKind::unknown, &m);
        },
        true);
}

bool looks_like_model(const std::string& start) {
    if (start.size() >= 4 && is_erdz(start.substr(0, 4))) return true;
    const std::size_t i = start.find_first_not_of(" \t\r\n");
    return i != std::string::npos && ((start[i] >= '0' && start[i] <= '9') || start.compare(i, 4, "erd-") == 0);
}

Framer model_or_image_framer(const ImageLimits& limits) {
    return [model = model_framer(false), image = image_framer(limits)](const std::string& so_far, bool stream,
                                                                      std::uint64_t* total) {
        const std::size_t head = so_far.size() < 64 ? so_far.size() : 64;
        if (head < 4 || (head < 64 && so_far.find_first_not_of(" \t\r\n") == std::string::npos)) {
            *total = UINT64_MAX;
            return Status::success();
        }
        return looks_like_model(so_far.substr(0, head)) ? model(so_far, stream, total) : image(so_far, stream, total);
    };
}

Framer polylines_framer() {
    return text_framer(
        [](const std::string& text) {
            std::vector<std::vector<LatticePoint>> lines;
            return read_polylines(text, &lines);
        },
        false);
}

}  // namespace erd::cli
