#include "imageio/raster_window.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/imaging/real_image.h"

namespace erd::imageio {

RasterWindow::~RasterWindow() {
    if (file_) std::fclose(file_);
}

Status RasterWindow::open(const std::string& path, const ImageLimits& limits) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return Status::bad_input("cannot open the file");
    unsigned char head[512];
    const std::size_t n = std::fread(head, 1, sizeof head, f);
    format_ = detect_format(head, n);
    Status s;
    if (format_ == ImageFormat::tiff) {
        std::fclose(f);
        tiff_ = std::make_unique<TiffReader>();
        if (!(s = tiff_->open_file(path, limits))) return s;
        width_ = tiff_->info().width;
        height_ = tiff_->info().height;
        channels_ = tiff_->info().channels;
        return s;
    }
    file_ = f;
    if (format_ == ImageFormat::png) {
        png_ = std::make_unique<PngRows>();
        if (!(s = png_->open(f, limits))) return s;
        width_ = png_->width();
        height_ = png_->height();
        channels_ = png_->channels();
        return s;
    }
    if (format_ == ImageFormat::pfm) {
        if (!(s = pfm_header(head, n, limits, &pfm_))) return s;
        width_ = pfm_.width;
        height_ = pfm_.height;
        channels_ = pfm_.channels;
        return s;
    }
    if (format_ == ImageFormat::pgm_raw || format_ == ImageFormat::ppm_raw) {
        if (!(s = pnm_header(head, n, limits, &pnm_))) return s;
        width_ = int(pnm_.w);
        height_ = int(pnm_.h);
        channels_ = pnm_.channels;
        return s;
    }
    return Status::bad_input(std::string(format_name(format_)) + " is not read by windows (TIFF, PFM, raw PGM and PPM, PNG are)");
}

Status RasterWindow::read(int x0, int y0, int x1, int y1, Image* out, std::string* warning) {
    if (x0 < 0 || y0 < 0 || x1 > width_ || y1 > height_ || x0 >= x1 || y0 >= y1)
        return Status::bad_input("window (" + std::to_string(x0) + ", " + std::to_string(y0) + ") - (" + std::to_string(x1) + ", " +
                                 std::to_string(y1) + ") is not inside the " + std::to_string(width_) + " x " +
                                 std::to_string(height_) + " image");
    if (tiff_) return tiff_->read(x0, y0, x1, y1, out, warning);
    if (png_) return png_->read(x0, y0, x1, y1, out);
    if (!file_) return Status::failure("no file open");
    const std::size_t W = std::size_t(width_), C = std::size_t(channels_), ww = std::size_t(x1 - x0), wh = std::size_t(y1 - y0);
    if (format_ == ImageFormat::pfm) {
        // The rows H-y1 .. H-1-y0 from the bottom, in one read.
        const std::size_t row = W * C * 4;
        std::vector<unsigned char> bytes(wh * row);
        const long at = long(pfm_.raster + std::size_t(height_ - y1) * row);
        if (std::fseek(file_, at, SEEK_SET) != 0 || std::fread(bytes.data(), 1, bytes.size(), file_) != bytes.size())
            return Status::bad_input("PFM raster truncated (rows " + std::to_string(y0) + " to " + std::to_string(y1 - 1) + ")");
        std::vector<double> rows(wh * W * C), values(ww * wh * C);
        pfm_rows(pfm_, bytes.data(), y0, y1, rows.data());
        for (std::size_t y = 0; y < wh; ++y)
            for (std::size_t k = 0; k < ww * C; ++k) values[y * ww * C + k] = rows[y * W * C + std::size_t(x0) * C + k];
        RasterMeta meta;
        meta.type = SampleType::f32;
        Status s = make_real_image(int(ww), int(wh), int(C), std::move(values), meta, out);
        return s ? s : Status::bad_input("PFM " + s.message);
    }
    // Raw PGM/PPM: 8-bit, or 16-bit big-endian samples.
    const std::size_t bps = pnm_.maxval < 256 ? 1 : 2, row = W * C * bps;
    Image im(int(ww), int(wh), std::uint32_t(pnm_.maxval), int(C));
    std::vector<unsigned char> bytes(ww * C * bps);
    for (std::size_t y = 0; y < wh; ++y) {
        const long at = long(pnm_.sep + 1 + (std::size_t(y0) + y) * row + std::size_t(x0) * C * bps);
        if (std::fseek(file_, at, SEEK_SET) != 0 || std::fread(bytes.data(), 1, bytes.size(), file_) != bytes.size())
            return Status::bad_input("raster truncated at row " + std::to_string(std::size_t(y0) + y));
        // The row decoded, then checked against maxval by its largest sample (the first sample
        // above it named).
        std::uint16_t* dst = im.samples.data() + y * ww * C;
        const std::size_t n = ww * C;
        std::uint16_t top = 0;
        if (bps == 1) {
            for (std::size_t k = 0; k < n; ++k) dst[k] = bytes[k], top = std::max<std::uint16_t>(top, dst[k]);
        } else {
            for (std::size_t k = 0; k < n; ++k)
                dst[k] = std::uint16_t(bytes[2 * k] << 8 | bytes[2 * k + 1]), top = std::max(top, dst[k]);
        }
        if (top > pnm_.maxval) {
            const std::uint16_t v = *std::find_if(dst, dst + n, [&](std::uint16_t s) { return s > pnm_.maxval; });
            return Status::bad_input("sample " + std::to_string(v) + " above maxval " + std::to_string(pnm_.maxval) + " in row " +
                                     std::to_string(std::size_t(y0) + y));
        }
    }
    im.meta.type = bps == 1 ? SampleType::u8 : SampleType::u16;
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd::imageio
