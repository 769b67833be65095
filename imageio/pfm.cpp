#include "imageio/pfm.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "algorithms/imaging/real_image.h"
#include "imageio/messages.h"

namespace erd::imageio {

namespace {

bool host_little_endian() {
    const std::uint16_t one = 1;
    unsigned char b;
    std::memcpy(&b, &one, 1);
    return b == 1;
}

}  // namespace

Status pfm_header(const unsigned char* d, std::size_t n, const ImageLimits& limits, PfmHeader* out) {
    const Status eof = Status::bad_input("end of file in the PFM header");
    if (n < 2) return eof;
    if (d[0] != 'P' || (d[1] != 'f' && d[1] != 'F')) return Status::bad_input("not a PFM file (no Pf or PF)");
    PfmHeader h;
    h.channels = d[1] == 'F' ? 3 : 1;
    std::size_t i = 2;
    // Three tokens: width, height, scale, each after whitespace; one whitespace byte ends the header.
    std::string tok[3];
    for (int k = 0; k < 3; ++k) {
        if (i >= n) return eof;
        if (!is_space(d[i])) return Status::bad_input("PFM header: expected whitespace at byte " + std::to_string(i) + ", found '" + show(d, n, i) + "'");
        while (i < n && is_space(d[i])) ++i;
        while (i < n && !is_space(d[i]) && tok[k].size() < 32) tok[k] += char(d[i++]);
        if (i >= n) return eof;
        if (!is_space(d[i])) return Status::bad_input("PFM header: token '" + show(d, n, i - tok[k].size()) + "' too long");
    }
    for (int k = 0; k < 2; ++k) {
        if (tok[k].empty() || tok[k].size() > 10 || tok[k].find_first_not_of("0123456789") != std::string::npos)
            return Status::bad_input(std::string("PFM ") + (k ? "height" : "width") + " '" + printable(tok[k]) + "' is not a number");
    }
    const std::uint64_t w = std::stoull(tok[0]), hh = std::stoull(tok[1]);
    if (Status s = check_side("PFM width", w, limits); !s) return s;
    if (Status s = check_side("PFM height", hh, limits); !s) return s;
    if (Status s = check_pixels("PFM ", w, hh, limits); !s) return s;
    char* end = nullptr;
    const double scale = std::strtod(tok[2].c_str(), &end);
    if (end == tok[2].c_str() || *end != '\0' || scale == 0 || !std::isfinite(scale))
        return Status::bad_input("PFM scale '" + printable(tok[2]) + "' is not a nonzero number");
    h.width = int(w);
    h.height = int(hh);
    h.little_endian = scale < 0;
    h.raster = i + 1;
    *out = h;
    return Status::success();
}

void pfm_rows(const PfmHeader& h, const unsigned char* rows, int y0, int y1, double* values) {
    const std::size_t W = std::size_t(h.width), C = std::size_t(h.channels), row = W * C * 4;
    const bool swap = h.little_endian != host_little_endian();
    for (int y = y0; y < y1; ++y) {
        // File row k (from the bottom) is image row H-1-k; in the block given, the first is H-y1.
        const unsigned char* src = rows + std::size_t(y1 - 1 - y) * row;
        double* dst = values + std::size_t(y - y0) * W * C;
        for (std::size_t k = 0; k < W * C; ++k) {
            unsigned char b[4];
            std::memcpy(b, src + 4 * k, 4);
            if (swap) {
                std::swap(b[0], b[3]);
                std::swap(b[1], b[2]);
            }
            float f;
            std::memcpy(&f, b, 4);
            dst[k] = double(f);
        }
    }
}

Status decode_pfm(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    PfmHeader h;
    if (Status s = pfm_header(data, size, limits, &h); !s) return s;
    const std::uint64_t need = std::uint64_t(h.width) * std::uint64_t(h.height) * std::uint64_t(h.channels) * 4;
    if (size - h.raster < need)
        return Status::bad_input("PFM raster truncated: " + std::to_string(size - h.raster) + " bytes of the " + std::to_string(need) +
                                 " a " + std::to_string(h.width) + " x " + std::to_string(h.height) + " image needs");
    if (warning && size - h.raster > need) *warning = "ignored " + std::to_string(size - h.raster - need) + " bytes after the PFM raster";
    std::vector<double> values(std::size_t(h.width) * std::size_t(h.height) * std::size_t(h.channels));
    pfm_rows(h, data + h.raster, 0, h.height, values.data());
    RasterMeta meta;
    meta.type = SampleType::f32;
    Status s = make_real_image(h.width, h.height, h.channels, std::move(values), meta, out);
    if (!s) return Status::bad_input("PFM " + s.message);
    return s;
}

namespace {

class PfmRowWriter : public RowWriter {
public:
    ByteSink* sink = nullptr;
    int w = 0, h = 0, y = 0;
    std::size_t C = 1, head = 0;
    std::vector<unsigned char> row;
    Status write_row(const double* values) override {
        if (y >= h) return Status::failure("PFM writer: more rows than the image has");
        for (std::size_t k = 0; k < std::size_t(w) * C; ++k) {
            const float f = float(values[k]);
            std::memcpy(&row[4 * k], &f, 4);
        }
        const std::uint64_t at = head + std::uint64_t(h - 1 - y) * row.size();
        if (!sink->write_at(at, row.data(), row.size())) return Status::failure("PFM writer: write error");
        ++y;
        return Status::success();
    }
    Status finish() override {
        if (y != h) return Status::failure("PFM writer: " + std::to_string(y) + " rows of " + std::to_string(h) + " written");
        return Status::success();
    }
};

}  // namespace

Status open_pfm_row_writer(ByteSink* sink, int w, int h, int channels, std::unique_ptr<RowWriter>* out) {
    auto wr = std::make_unique<PfmRowWriter>();
    const std::string header = (channels == 3 ? "PF\n" : "Pf\n") + std::to_string(w) + " " + std::to_string(h) + "\n" +
                               (host_little_endian() ? "-1.0\n" : "1.0\n");
    if (!sink->write_at(0, header.data(), header.size())) return Status::failure("PFM writer: write error");
    wr->sink = sink;
    wr->w = w;
    wr->h = h;
    wr->C = std::size_t(channels);
    wr->head = header.size();
    wr->row.assign(std::size_t(w) * wr->C * 4, 0);
    *out = std::move(wr);
    return Status::success();
}

Status encode_pfm(const Image& im, std::string* out) {
    if (im.width <= 0 || im.height <= 0 || (im.channels != 1 && im.channels != 3))
        return Status::failure("internal error: invalid image for PFM");
    const std::size_t W = std::size_t(im.width), H = std::size_t(im.height), C = std::size_t(im.channels);
    std::string s = (C == 3 ? "PF\n" : "Pf\n") + std::to_string(W) + " " + std::to_string(H) + "\n" +
                    (host_little_endian() ? "-1.0\n" : "1.0\n");
    const std::size_t head = s.size();
    s.resize(head + W * H * C * 4);
    for (std::size_t y = 0; y < H; ++y) {
        char* dst = &s[head + (H - 1 - y) * W * C * 4];
        for (std::size_t x = 0; x < W; ++x) {
            const std::size_t i = y * W + x;
            const bool ok = pixel_valid(im, i);
            for (std::size_t c = 0; c < C; ++c) {
                const float f = ok ? float(sample_value(im, i * C + c)) : std::numeric_limits<float>::quiet_NaN();
                std::memcpy(dst + (x * C + c) * 4, &f, 4);
            }
        }
    }
    *out = std::move(s);
    return Status::success();
}

}  // namespace erd::imageio
