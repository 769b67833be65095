// libFuzzer target for the stream framing (cli/framing.h): how far a pipe or device is read.
//
// The input's first byte picks the framer (image, model, triangulation, polylines: bits 0-1) and
// whether the bytes come as a stream or a regular file (bit 2), the second the size of the reads
// after the first 4 KiB (as cli/fileio.cpp read_fd makes them); the rest is the stream.
// Checks beyond "no crash": a framer error is one non-empty line; the framed bytes are a prefix
// of the stream; a stream with a bad start (not P2, P5 or PNG) stops within its first read; and
// whatever decodes as a whole file decodes the same from the framed bytes (reading from a pipe
// never cuts a valid image or model short). Replay without libFuzzer: fuzz/replay.cpp.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/model/model_io.h"
#include "cli/framing.h"

namespace {

// read_fd's loop over an in-memory stream (or regular file: is_stream false): the bytes it
// keeps, or false on a framer error.
bool framed_read(const erd::cli::Framer& framer, const std::string& stream, bool is_stream, std::size_t chunk,
                 std::string* bytes, std::size_t* reads) {
    bytes->clear();
    *reads = 0;
    std::uint64_t total = UINT64_MAX;
    std::size_t at = 0;
    while (at < stream.size()) {
        std::size_t want = bytes->empty() ? 4096 : chunk;
        if (total != UINT64_MAX) want = std::size_t(std::min<std::uint64_t>(want, total - bytes->size()));
        if (want == 0) break;
        const std::size_t n = std::min(want, stream.size() - at);
        bytes->append(stream, at, n);
        at += n;
        ++*reads;
        if (total == UINT64_MAX) {
            erd::Status s = framer(*bytes, is_stream, &total);
            if (!s) {
                if (s.message.empty() || s.message.find('\n') != std::string::npos) std::abort();
                return false;
            }
            // A file: whole when at most kLookAfter bytes follow the content, else cut there.
            if (!is_stream && total != UINT64_MAX && stream.size() <= total + erd::cli::kLookAfter) total = stream.size();
            if (total < bytes->size()) bytes->resize(std::size_t(total));
        }
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const int kind = data[0] % 4;
    const bool is_stream = (data[0] & 4) == 0;  // else a regular file of the stream's size
    const std::size_t chunk = 1 + std::size_t(data[1]) * 97;
    const std::string stream(reinterpret_cast<const char*>(data + 2), size - 2);
    erd::cli::ImageLimits limits;
    limits.max_side = 4096;
    limits.max_pixels = std::int64_t(1) << 20;  // keeps every run fast; the logic is the same
    const erd::cli::Framer framer = kind == 0   ? erd::cli::image_framer(limits)
                                    : kind == 3 ? erd::cli::polylines_framer()
                                                : erd::cli::model_framer(kind == 2);
    std::string bytes;
    std::size_t reads = 0;
    const bool ok = framed_read(framer, stream, is_stream, chunk, &bytes, &reads);
    if (ok && stream.compare(0, bytes.size(), bytes) != 0) std::abort();
    if (kind == 0) {
        // A start no reader takes is refused from the first read (PNG, JPEG, PGM/PPM, PAM, PFM
        // and TIFF are read further, as cli/framing.cpp frames them).
        const auto u = [&](std::size_t i) { return static_cast<unsigned char>(stream[i]); };
        const bool jpeg = stream.size() >= 3 && u(0) == 0xff && u(1) == 0xd8 && u(2) == 0xff;
        const bool pnm = stream[0] == 'P' && (stream[1] == '2' || stream[1] == '3' || stream[1] == '5' ||
                                              stream[1] == '6' || stream[1] == '7' || stream[1] == 'f' ||
                                              stream[1] == 'F');
        const bool tiff = (stream[0] == 'I' && stream[1] == 'I') || (stream[0] == 'M' && stream[1] == 'M');
        const bool bad_start = stream.size() >= 2 && u(0) != 0x89 && !jpeg && !pnm && !tiff;
        if (bad_start && reads > 1 && (is_stream || stream.size() > 4096 + erd::cli::kLookAfter)) std::abort();
        erd::Image whole, framed;
        std::string w;
        const auto* p = reinterpret_cast<const unsigned char*>(stream.data());
        if (erd::cli::decode_image(p, stream.size(), &whole, &w, nullptr, limits).ok()) {
            if (!ok) std::abort();
            const auto* q = reinterpret_cast<const unsigned char*>(bytes.data());
            if (!erd::cli::decode_image(q, bytes.size(), &framed, &w, nullptr, limits).ok()) std::abort();
            if (framed.width != whole.width || framed.height != whole.height || framed.maxval != whole.maxval ||
                framed.samples != whole.samples)
                std::abort();
        }
        return 0;
    }
    if (kind == 3) {
        std::vector<std::vector<erd::LatticePoint>> whole, framed;
        if (erd::read_polylines(stream, &whole).ok()) {
            if (!ok || !erd::read_polylines(bytes, &framed).ok() || framed != whole) std::abort();
        }
        return 0;
    }
    erd::Model whole, framed;
    const bool whole_ok = kind == 2 ? erd::read_triangulation(stream, &whole).ok()
                                    : erd::read_model(stream, erd::ModelFileKind::unknown, &whole).ok();
    if (whole_ok) {
        if (!ok) std::abort();
        const bool framed_ok = kind == 2 ? erd::read_triangulation(bytes, &framed).ok()
                                         : erd::read_model(bytes, erd::ModelFileKind::unknown, &framed).ok();
        if (!framed_ok || framed.vertices != whole.vertices || framed.faces != whole.faces) std::abort();
    }
    return 0;
}
