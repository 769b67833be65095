// Rasters read by windows (issue 47 for whole files, issue 48 for tiles): a file opened once, its
// size and type known from the header, then any rectangle read without reading the rest of the
// raster: TIFF by the strips or tiles the window meets (imageio/tiff.h), PFM and raw PGM/PPM (P5,
// P6) by the rows it meets (seeks), PNG (gray or RGB, 8 or 16 bits, not interlaced) by inflating
// rows up to the window's last (imageio/png_rows.h). Other formats (JPEG, plain PNM, PAM, palette
// or interlaced PNG) are refused here: they are read whole (decode_image).
#pragma once
#include <cstdio>
#include <memory>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "imageio/pfm.h"
#include "imageio/png_rows.h"
#include "imageio/pnm.h"
#include "imageio/tiff.h"
#include "kernel/status.h"

namespace erd::imageio {

class RasterWindow {
public:
    RasterWindow() = default;
    ~RasterWindow();
    RasterWindow(const RasterWindow&) = delete;
    RasterWindow& operator=(const RasterWindow&) = delete;

    // Opens `path` (a regular file) and reads its header. Fails (Code::input, no path in the
    // message) for a format not read by windows, naming it.
    Status open(const std::string& path, const ImageLimits& limits = ImageLimits());

    ImageFormat format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }

    // The window x0 <= x < x1, y0 <= y < y1 as an Image: as decode_image would give that part of
    // the file (a real image for TIFF with nodata or non-16-bit types and for PFM; the range and
    // nodata mask those of the window).
    Status read(int x0, int y0, int x1, int y1, Image* out, std::string* warning = nullptr);

private:
    ImageFormat format_ = ImageFormat::unknown;
    int width_ = 0, height_ = 0, channels_ = 1;
    std::FILE* file_ = nullptr;
    std::unique_ptr<TiffReader> tiff_;
    std::unique_ptr<PngRows> png_;
    PfmHeader pfm_;
    PnmHeader pnm_;
};

}  // namespace erd::imageio
