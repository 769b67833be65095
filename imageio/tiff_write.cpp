// TIFF written through libtiff (tiff.h): whole images and by rows, with the GeoTIFF and nodata tags.
#include "imageio/tiff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <tiffio.h>

#include "algorithms/imaging/real_image.h"
#include "imageio/messages.h"
#include "imageio/tiff_stream.h"

namespace erd::imageio {

using namespace tiff_io;

namespace {

// The value v as type t: integers rounded (halves away from zero) and clamped to the type.
template <class T>
T to_type(double v) {
    if constexpr (std::is_floating_point<T>::value) {
        return T(v);
    } else {
        if (std::isnan(v)) return T(0);
        const double r = std::round(v);
        const double lo = double(std::numeric_limits<T>::min()), hi = double(std::numeric_limits<T>::max());
        return T(r < lo ? lo : (r > hi ? hi : r));
    }
}

}  // namespace

namespace {

// The directory of a w x h raster of C channels of type t with meta's tags; *rps the rows per strip.
bool set_fields(TIFF* tif, int w, int h, std::size_t C, SampleType t, const RasterMeta& meta, std::uint32_t* rps) {
    const std::size_t bs = std::size_t(bytes_of(t));
    const bool fp = t == SampleType::f32 || t == SampleType::f64;
    std::uint16_t fmt = SAMPLEFORMAT_UINT;
    if (t == SampleType::i16 || t == SampleType::i32) fmt = SAMPLEFORMAT_INT;
    if (fp) fmt = SAMPLEFORMAT_IEEEFP;
    const std::size_t row_bytes = std::size_t(w) * C * bs;
    *rps = std::uint32_t(std::max<std::size_t>(1, std::min<std::size_t>(std::size_t(h), (std::size_t(1) << 16) / row_bytes)));
    TIFFMergeFieldInfo(tif, kGeoFields, sizeof kGeoFields / sizeof kGeoFields[0]);
    bool ok = TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(w)) && TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(h)) &&
              TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(C)) && TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(8 * bs)) &&
              TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, fmt) &&
              TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, C == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK) &&
              TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) && TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE) &&
              TIFFSetField(tif, TIFFTAG_PREDICTOR, fp ? PREDICTOR_FLOATINGPOINT : PREDICTOR_HORIZONTAL) &&
              TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, *rps);
    const GeoTags& g = meta.geo;
    if (ok && !g.pixel_scale.empty()) ok = TIFFSetField(tif, kPixelScale, int(g.pixel_scale.size()), g.pixel_scale.data());
    if (ok && !g.tiepoints.empty()) ok = TIFFSetField(tif, kTiepoint, int(g.tiepoints.size()), g.tiepoints.data());
    if (ok && !g.transform.empty()) ok = TIFFSetField(tif, kTransform, int(g.transform.size()), g.transform.data());
    if (ok && !g.keys.empty()) ok = TIFFSetField(tif, kGeoKeys, int(g.keys.size()), g.keys.data());
    if (ok && !g.doubles.empty()) ok = TIFFSetField(tif, kGeoDoubles, int(g.doubles.size()), g.doubles.data());
    if (ok && !g.ascii.empty()) ok = TIFFSetField(tif, kGeoAscii, g.ascii.c_str());
    if (ok && meta.has_nodata) {
        char text[64];
        if (std::isnan(meta.nodata)) std::snprintf(text, sizeof text, "nan");
        else std::snprintf(text, sizeof text, "%.17g", meta.nodata);
        ok = TIFFSetField(tif, kGdalNodata, text);
    }
    return ok;
}

// Row values (NaN: nodata) as type t at dst.
template <class T>
void put_values(const double* v, std::size_t n, double nodata, unsigned char* dst) {
    for (std::size_t k = 0; k < n; ++k) {
        const T x = to_type<T>(std::isnan(v[k]) ? nodata : v[k]);
        std::memcpy(dst + k * sizeof(T), &x, sizeof(T));
    }
}

void put_typed(SampleType t, const double* v, std::size_t n, double nodata, unsigned char* dst) {
    switch (t) {
        case SampleType::u8: put_values<std::uint8_t>(v, n, nodata, dst); break;
        case SampleType::u16: put_values<std::uint16_t>(v, n, nodata, dst); break;
        case SampleType::u32: put_values<std::uint32_t>(v, n, nodata, dst); break;
        case SampleType::i16: put_values<std::int16_t>(v, n, nodata, dst); break;
        case SampleType::i32: put_values<std::int32_t>(v, n, nodata, dst); break;
        case SampleType::f32: put_values<float>(v, n, nodata, dst); break;
        case SampleType::f64: put_values<double>(v, n, nodata, dst); break;
    }
}

// An integer type needs a value for nodata: its smallest (GDAL's habit for signed types).
RasterMeta with_nodata(RasterMeta meta, SampleType t, bool holes) {
    const bool fp = t == SampleType::f32 || t == SampleType::f64;
    if (holes && !meta.has_nodata && !fp) {
        meta.has_nodata = true;
        meta.nodata = t == SampleType::i16 ? -32768.0 : t == SampleType::i32 ? -2147483648.0 : 0.0;
    }
    return meta;
}

class TiffRowWriter : public RowWriter {
public:
    Stream stream;
    Messages msg;
    TIFF* tif = nullptr;
    int w = 0, h = 0, y = 0;
    std::size_t C = 1, row_bytes = 0;
    std::uint32_t rps = 1;
    SampleType type = SampleType::f32;
    double nodata = 0;
    std::vector<unsigned char> strip;
    ~TiffRowWriter() override {
        if (tif) TIFFClose(tif);
    }
    Status write_row(const double* values) override {
        if (!tif || y >= h) return Status::failure("TIFF writer: more rows than the image has");
        put_typed(type, values, std::size_t(w) * C, nodata, strip.data() + std::size_t(std::uint32_t(y) % rps) * row_bytes);
        ++y;
        if (std::uint32_t(y) % rps == 0 || y == h) {
            const std::size_t rows = std::uint32_t(y) % rps == 0 ? rps : std::uint32_t(y) % rps;
            if (TIFFWriteEncodedStrip(tif, std::uint32_t(y - 1) / rps, strip.data(), tmsize_t(rows * row_bytes)) < 0)
                return Status::failure("TIFF writer: " + why(msg, "strip refused"));
        }
        return Status::success();
    }
    Status finish() override {
        if (!tif) return Status::failure("TIFF writer: not open");
        if (y != h) return Status::failure("TIFF writer: " + std::to_string(y) + " rows of " + std::to_string(h) + " written");
        const bool ok = TIFFWriteDirectory(tif) != 0;
        TIFFClose(tif);
        tif = nullptr;
        if (!ok || !msg.error.empty()) return Status::failure("TIFF writer: " + why(msg, "the directory was refused"));
        return Status::success();
    }
};

}  // namespace

Status open_tiff_row_writer(ByteSink* sink, int w, int h, int channels, const RasterMeta& given, std::unique_ptr<RowWriter>* out) {
    auto wr = std::make_unique<TiffRowWriter>();
    wr->stream.sink = sink;
    wr->type = given.type;
    const RasterMeta meta = with_nodata(given, given.type, true);
    wr->nodata = meta.has_nodata ? meta.nodata : std::numeric_limits<double>::quiet_NaN();
    wr->w = w;
    wr->h = h;
    wr->C = std::size_t(channels);
    wr->row_bytes = std::size_t(w) * wr->C * std::size_t(bytes_of(meta.type));
    const std::uint64_t raw = std::uint64_t(wr->row_bytes) * std::uint64_t(h);
    wr->tif = open_stream(&wr->stream, raw > (std::uint64_t(3) << 30) ? "w8" : "w", &wr->msg, 0);
    if (!wr->tif) return Status::failure("TIFF writer: " + why(wr->msg, "cannot start"));
    if (!set_fields(wr->tif, w, h, wr->C, meta.type, meta, &wr->rps)) return Status::failure("TIFF writer: " + why(wr->msg, "a field was refused"));
    wr->strip.assign(std::size_t(wr->rps) * wr->row_bytes, 0);
    *out = std::move(wr);
    return Status::success();
}

Status encode_tiff(const Image& im, std::string* out) {
    if (im.width <= 0 || im.height <= 0 || (im.channels != 1 && im.channels != 3))
        return Status::failure("internal error: invalid image for TIFF");
    const SampleType t = im.real() ? im.meta.type : (im.maxval <= 255 ? SampleType::u8 : SampleType::u16);
    const RasterMeta meta = with_nodata(im.meta, t, im.has_holes());
    const double nodata = meta.has_nodata ? meta.nodata : std::numeric_limits<double>::quiet_NaN();
    const std::size_t bs = std::size_t(bytes_of(t)), C = std::size_t(im.channels), W = std::size_t(im.width);
    const std::uint64_t raw = std::uint64_t(W) * std::uint64_t(im.height) * C * bs;
    std::string bytes;
    Stream st;
    st.out = &bytes;
    Messages msg;
    TIFF* tif = open_stream(&st, raw > (std::uint64_t(3) << 30) ? "w8" : "w", &msg, 0);
    if (!tif) return Status::failure("TIFF writer: " + why(msg, "cannot start"));
    std::uint32_t rps = 1;
    bool ok = set_fields(tif, im.width, im.height, C, t, meta, &rps);
    const std::size_t row_bytes = W * C * bs;
    std::vector<unsigned char> strip;
    std::vector<double> row(W * C);
    for (std::uint32_t y0 = 0; ok && y0 < std::uint32_t(im.height); y0 += rps) {
        const std::uint32_t y1 = std::min<std::uint32_t>(std::uint32_t(im.height), y0 + rps);
        strip.assign(std::size_t(y1 - y0) * row_bytes, 0);
        for (std::uint32_t y = y0; y < y1; ++y) {
            for (std::size_t x = 0; x < W; ++x) {
                const std::size_t i = std::size_t(y) * W + x;
                const bool valid = pixel_valid(im, i);
                for (std::size_t c = 0; c < C; ++c)
                    row[x * C + c] = valid ? sample_value(im, i * C + c) : std::numeric_limits<double>::quiet_NaN();
            }
            put_typed(t, row.data(), W * C, nodata, strip.data() + std::size_t(y - y0) * row_bytes);
        }
        ok = TIFFWriteEncodedStrip(tif, y0 / rps, strip.data(), tmsize_t(strip.size())) >= 0;
    }
    TIFFClose(tif);
    if (!ok || !msg.error.empty()) return Status::failure("TIFF writer: " + why(msg, "a field or strip was refused"));
    *out = std::move(bytes);
    return Status::success();
}

}  // namespace erd::imageio
