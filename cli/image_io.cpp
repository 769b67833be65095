#include "cli/image_io.h"

#include <cstdint>
#include <cstdio>

#include "algorithms/imaging/luma.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/report.h"
#include "imageio/raster_window.h"

namespace erd::cli {

namespace {

// A regular file that is a TIFF or a PFM: read by imageio's windows, so the file's bytes are not
// held beside the decoded raster (a float raster of 16384^2 is 1 GiB on disk). False (nothing
// read) for anything else.
bool read_by_window(const std::string& path, Image* out, std::string* w, ImageFormat* format, const ImageLimits& limits, Status* st) {
    if (path == "-") return false;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    unsigned char head[4] = {0, 0, 0, 0};
    const std::size_t n = std::fread(head, 1, 4, f);
    const bool seekable = std::fseek(f, 0, SEEK_END) == 0 && std::ftell(f) > 0;
    std::fclose(f);
    const ImageFormat fmt = imageio::detect_format(head, n);
    if (!seekable || (fmt != ImageFormat::tiff && fmt != ImageFormat::pfm)) return false;
    if (format) *format = fmt;
    imageio::RasterWindow win;
    *st = win.open(path, limits);
    if (*st) *st = win.read(0, 0, win.width(), win.height(), out, w);
    return true;
}

}  // namespace

Status read_image(const std::string& path, Image* out, std::string* warning, ImageFormat* format, const ImageLimits& limits) {
    if (warning) warning->clear();
    std::string w0;
    Status ws;
    if (read_by_window(path, out, &w0, format, limits, &ws)) {
        const std::string name = escape_name(path);
        if (!ws) return Status::bad_input(name + ": " + ws.message);
        if (warning && !w0.empty()) *warning = name + ": " + w0;
        return Status::success();
    }
    std::string bytes;
    bool more = false;
    std::uint64_t unread = 0;
    if (Status s = read_file(path, &bytes, kMaxInputBytes, image_framer(limits), &more, &unread); !s) return s;
    return decode_image_bytes(path, bytes, more, unread, out, warning, format, limits);
}

Status decode_image_bytes(const std::string& path, const std::string& bytes, bool more, std::uint64_t unread, Image* out,
                          std::string* warning, ImageFormat* format, const ImageLimits& limits) {
    if (warning) warning->clear();
    const std::string name = escape_name(path == "-" ? "stdin" : path);
    std::string w;
    Status s = decode_image(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), out, &w, format, limits);
    if (!s) return Status::bad_input(name + ": " + s.message);
    if (more) w += std::string(w.empty() ? "" : "\n") + "ignored the data after the image (a stream is read as far as its header says)";
    if (unread)  // a file whose image ends long before it does: what follows was never read
        w += std::string(w.empty() ? "" : "\n") + "ignored " + std::to_string(unread) +
             " bytes after the image (only the first image of a file is read)";
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

void to_gray(const std::string& path, Image* im, bool asked, std::string* warning) {
    if (im->channels != 3) return;
    *im = luma(*im);
    if (asked || !warning) return;
    if (!warning->empty()) *warning += "\n";
    *warning += escape_name(path == "-" ? "stdin" : path) +
                ": colour image converted to gray with BT.601 luma (0.299 R + 0.587 G + 0.114 B); --gray does this silently";
}

Status read_input_image(const std::string& path, ColourInput colour, const Reporter& rep, Image* out, ImageFormat* format) {
    std::string warning;
    if (Status st = read_image(path, out, &warning, format); !st) return st;
    if (colour != ColourInput::keep) to_gray(path, out, colour == ColourInput::luma_asked, &warning);
    rep.warn(warning);
    return Status::success();
}

bool keeps_real_values(const std::string& path) {
    const ImageFormat f = imageio::format_for_name(path);
    return f == ImageFormat::tiff || f == ImageFormat::pfm;
}

Status encode_image(const std::string& path, const Image& im, const WriteOptions& options, std::string* bytes) {
    Status s = imageio::encode_image(im, imageio::format_for_name(path, options.plain), bytes);
    if (!s) return Status::error(s.code, escape_name(path) + ": " + s.message);
    return s;
}

Status write_image(const std::string& path, const Image& im, const WriteOptions& options) {
    std::string bytes;
    Status s = encode_image(path, im, options, &bytes);
    return s ? write_file_atomic(path, bytes) : s;
}

}  // namespace erd::cli
