// TIFF and GeoTIFF read through libtiff after our checks, whole or by windows (tiff.h).
#include "imageio/tiff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

// A block (strip or tile) larger than this is refused before libtiff allocates it.
constexpr std::uint64_t kMaxBlockBytes = std::uint64_t(1) << 28;

// A tag of doubles (stored as DOUBLE or FLOAT), shorts or text, as libtiff has it.
bool get_doubles(TIFF* tif, ttag_t tag, std::vector<double>* out) {
    const TIFFField* f = TIFFFindField(tif, tag, TIFF_ANY);
    if (!f) return false;
    std::uint32_t n = 0;
    void* p = nullptr;
    if (TIFFFieldReadCount(f) != TIFF_VARIABLE2 || !TIFFGetField(tif, tag, &n, &p) || !p) return false;
    out->clear();
    for (std::uint32_t i = 0; i < n && i < 4096; ++i) {
        switch (TIFFFieldDataType(f)) {
            case TIFF_DOUBLE: out->push_back(static_cast<const double*>(p)[i]); break;
            case TIFF_FLOAT: out->push_back(double(static_cast<const float*>(p)[i])); break;
            default: return false;
        }
    }
    return true;
}

bool get_shorts(TIFF* tif, ttag_t tag, std::vector<std::uint16_t>* out) {
    const TIFFField* f = TIFFFindField(tif, tag, TIFF_ANY);
    std::uint32_t n = 0;
    void* p = nullptr;
    if (!f || TIFFFieldReadCount(f) != TIFF_VARIABLE2 || TIFFFieldDataType(f) != TIFF_SHORT || !TIFFGetField(tif, tag, &n, &p) || !p)
        return false;
    out->assign(static_cast<const std::uint16_t*>(p), static_cast<const std::uint16_t*>(p) + std::min<std::uint32_t>(n, 65536));
    return true;
}

bool get_text(TIFF* tif, ttag_t tag, std::string* out) {
    const TIFFField* f = TIFFFindField(tif, tag, TIFF_ANY);
    if (!f || TIFFFieldDataType(f) != TIFF_ASCII) return false;
    std::uint32_t n = 0;
    char* p = nullptr;
    if (TIFFFieldPassCount(f)) {
        if (TIFFFieldReadCount(f) != TIFF_VARIABLE2 || !TIFFGetField(tif, tag, &n, &p) || !p) return false;
    } else {
        if (!TIFFGetField(tif, tag, &p) || !p) return false;
        n = std::uint32_t(std::strlen(p));
    }
    n = std::min<std::uint32_t>(n, 65536);
    out->assign(p, std::size_t(std::find(p, p + n, '\0') - p));
    return true;
}

// The number text of GDAL_NODATA (blanks around it allowed): true and *v when it is one.
bool parse_number(const std::string& text, double* v) {
    const char* s = text.c_str();
    while (*s == ' ') ++s;
    char* end = nullptr;
    *v = std::strtod(s, &end);
    if (end == s) return false;
    while (*end == ' ') ++end;
    return *end == '\0';
}

const char* photometric_name(std::uint16_t p) {
    switch (p) {
        case PHOTOMETRIC_SEPARATED: return " (CMYK)";
        case PHOTOMETRIC_CIELAB: case PHOTOMETRIC_ICCLAB: case PHOTOMETRIC_ITULAB: return " (Lab)";
        case PHOTOMETRIC_MASK: return " (transparency mask)";
        case PHOTOMETRIC_LOGL: case PHOTOMETRIC_LOGLUV: return " (LogLuv)";
        default: return "";
    }
}

// Sample k of type t at p, as a double.
inline double sample_at(const unsigned char* p, SampleType t) {
    switch (t) {
        case SampleType::u8: return p[0];
        case SampleType::u16: { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
        case SampleType::u32: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
        case SampleType::i16: { std::int16_t v; std::memcpy(&v, p, 2); return v; }
        case SampleType::i32: { std::int32_t v; std::memcpy(&v, p, 4); return v; }
        case SampleType::f32: { float v; std::memcpy(&v, p, 4); return double(v); }
        case SampleType::f64: { double v; std::memcpy(&v, p, 8); return v; }
    }
    return 0;
}

}  // namespace

struct TiffReader::Impl {
    Stream stream;
    Messages msg;
    TIFF* tif = nullptr;
    TiffInfo info;
    std::vector<std::uint16_t> colormap[3];  // a palette image's, 8-bit indices
    ~Impl() {
        if (tif) TIFFClose(tif);
        if (stream.file) std::fclose(stream.file);
    }
    Status check(const ImageLimits& limits);
};

TiffReader::TiffReader() : impl_(new Impl) {}
TiffReader::~TiffReader() = default;
const TiffInfo& TiffReader::info() const { return impl_->info; }

Status TiffReader::open(const unsigned char* data, std::size_t size, const ImageLimits& limits) {
    impl_.reset(new Impl);
    impl_->stream.data = data;
    impl_->stream.size = size;
    // libtiff's allocations capped near what the limits let an image need (a block, a directory).
    const std::uint64_t cap = std::min<std::uint64_t>(std::max<std::uint64_t>(std::uint64_t(limits.max_pixels) * 16, 16u << 20), 1u << 30);
    impl_->tif = open_stream(&impl_->stream, "rm", &impl_->msg, cap);
    if (!impl_->tif) return Status::bad_input("TIFF rejected by libtiff: " + why(impl_->msg, "not a readable TIFF"));
    return impl_->check(limits);
}

Status TiffReader::open_file(const std::string& path, const ImageLimits& limits) {
    impl_.reset(new Impl);
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return Status::bad_input("cannot open the file");
    // A file whose end cannot be found (a pipe, a directory) is not read by windows.
    const long n = std::fseek(f, 0, SEEK_END) == 0 ? std::ftell(f) : -1;
    if (n < 0) {
        std::fclose(f);
        return Status::bad_input("not a file that can be read by windows (a pipe or a directory?)");
    }
    impl_->stream.file = f;
    impl_->stream.size = std::uint64_t(n);
    const std::uint64_t cap = std::min<std::uint64_t>(std::max<std::uint64_t>(std::uint64_t(limits.max_pixels) * 16, 16u << 20), 1u << 30);
    impl_->tif = open_stream(&impl_->stream, "rm", &impl_->msg, cap);
    if (!impl_->tif) return Status::bad_input("TIFF rejected by libtiff: " + why(impl_->msg, "not a readable TIFF"));
    return impl_->check(limits);
}

Status TiffReader::Impl::check(const ImageLimits& limits) {
    TiffInfo& in = info;
    std::uint32_t w = 0, h = 0;
    if (!TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w) || !TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h))
        return Status::bad_input("TIFF has no image width or length");
    if (Status s = check_side("TIFF width", w, limits); !s) return s;
    if (Status s = check_side("TIFF height", h, limits); !s) return s;
    if (Status s = check_pixels("TIFF ", w, h, limits); !s) return s;
    in.width = int(w);
    in.height = int(h);
    std::uint16_t spp = 1, bps = 1, fmt = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG, comp = COMPRESSION_NONE, photo = 0;
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bps);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &fmt);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
    TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &comp);
    const bool has_photo = TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photo) != 0;
    if (spp < 1 || spp > 4)
        return Status::bad_input("TIFF has " + std::to_string(spp) +
                                 " samples per pixel; erd reads 1 (gray) or 3 (RGB), and 2 or 4 with alpha");
    const std::string layout = std::to_string(bps) + "-bit " +
                               (fmt == SAMPLEFORMAT_INT ? "signed" : fmt == SAMPLEFORMAT_IEEEFP ? "float" : "unsigned") + " samples";
    if (fmt == SAMPLEFORMAT_VOID) fmt = SAMPLEFORMAT_UINT;
    if (fmt != SAMPLEFORMAT_UINT && fmt != SAMPLEFORMAT_INT && fmt != SAMPLEFORMAT_IEEEFP)
        return Status::bad_input("TIFF sample format " + std::to_string(fmt) + " (complex numbers) is not supported");
    SampleType t;
    if (fmt == SAMPLEFORMAT_UINT && bps == 8) t = SampleType::u8;
    else if (fmt == SAMPLEFORMAT_UINT && bps == 16) t = SampleType::u16;
    else if (fmt == SAMPLEFORMAT_UINT && bps == 32) t = SampleType::u32;
    else if (fmt == SAMPLEFORMAT_INT && bps == 16) t = SampleType::i16;
    else if (fmt == SAMPLEFORMAT_INT && bps == 32) t = SampleType::i32;
    else if (fmt == SAMPLEFORMAT_IEEEFP && bps == 32) t = SampleType::f32;
    else if (fmt == SAMPLEFORMAT_IEEEFP && bps == 64) t = SampleType::f64;
    else
        return Status::bad_input("TIFF has " + layout +
                                 "; erd reads unsigned 8, 16 and 32-bit, signed 16 and 32-bit, and float 32 and 64-bit samples");
    if (!has_photo) photo = spp >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK;
    if (photo == PHOTOMETRIC_YCBCR) {
        if (comp != COMPRESSION_JPEG) return Status::bad_input("TIFF YCbCr samples are read only JPEG-compressed");
        TIFFSetField(tif, TIFFTAG_JPEGCOLORMODE, JPEGCOLORMODE_RGB);
        photo = PHOTOMETRIC_RGB;
    }
    if (photo == PHOTOMETRIC_PALETTE) {
        if (t != SampleType::u8 || spp != 1)
            return Status::bad_input("TIFF palette image with " + std::to_string(spp) + " " + layout +
                                     "; erd reads palettes of one 8-bit index a pixel");
        std::uint16_t *r = nullptr, *g = nullptr, *b = nullptr;
        if (!TIFFGetField(tif, TIFFTAG_COLORMAP, &r, &g, &b) || !r || !g || !b) return Status::bad_input("TIFF palette image has no colour map");
        colormap[0].assign(r, r + 256);
        colormap[1].assign(g, g + 256);
        colormap[2].assign(b, b + 256);
        in.palette = true;
    } else if (photo == PHOTOMETRIC_MINISBLACK || photo == PHOTOMETRIC_MINISWHITE) {
        if (spp > 2)
            return Status::bad_input("TIFF gray image has " + std::to_string(spp) + " samples per pixel (1, or 2 with alpha)");
        if (photo == PHOTOMETRIC_MINISWHITE) {
            if (fmt != SAMPLEFORMAT_UINT) return Status::bad_input("TIFF with 0 as white and " + layout + " is not supported");
            in.min_is_white = true;
        }
    } else if (photo == PHOTOMETRIC_RGB) {
        if (spp < 3) return Status::bad_input("TIFF RGB image has " + std::to_string(spp) + " samples per pixel (3, or 4 with alpha)");
    } else {
        return Status::bad_input("TIFF photometric interpretation " + std::to_string(photo) + photometric_name(photo) +
                                 " is not supported (gray, RGB or 8-bit palette)");
    }
    if (!TIFFIsCODECConfigured(comp))
        return Status::bad_input("TIFF compression " + std::to_string(comp) + " is not one this libtiff decodes");
    in.file_samples = spp;
    in.channels = (in.palette || spp >= 3) ? 3 : 1;
    in.bits = bps;
    in.planar = planar == PLANARCONFIG_SEPARATE && spp > 1;
    in.compression = comp;
    in.tiled = TIFFIsTiled(tif) != 0;
    if (in.tiled) {
        std::uint32_t tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        if (tw == 0 || th == 0 || tw > 65536 || th > 65536)
            return Status::bad_input("TIFF tile size " + std::to_string(tw) + " x " + std::to_string(th) + " is not usable");
        in.block_width = tw;
        in.block_height = th;
    } else {
        std::uint32_t rps = h;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rps);
        in.block_width = w;
        in.block_height = std::max<std::uint32_t>(1, std::min(rps, h));
    }
    const std::uint64_t block = std::uint64_t(in.block_width) * in.block_height * (in.planar ? 1 : spp) * std::uint64_t(bps / 8);
    if (block > kMaxBlockBytes)
        return Status::bad_input(std::string("TIFF ") + (in.tiled ? "tile" : "strip") + " of " + std::to_string(block) +
                                 " bytes is above the limit of " + std::to_string(kMaxBlockBytes) + " bytes");
    const std::uint64_t expect = in.tiled ? std::uint64_t(TIFFTileSize64(tif)) : std::uint64_t(TIFFStripSize64(tif));
    if (expect == 0 || expect > kMaxBlockBytes)
        return Status::bad_input("TIFF " + std::string(in.tiled ? "tile" : "strip") + " size is not usable: " + why(msg, "libtiff computes " + std::to_string(expect) + " bytes"));
    in.meta.type = in.palette ? SampleType::u8 : t;
    // GeoTIFF and GDAL_NODATA.
    GeoTags& g = in.meta.geo;
    get_doubles(tif, kPixelScale, &g.pixel_scale);
    get_doubles(tif, kTiepoint, &g.tiepoints);
    get_doubles(tif, kTransform, &g.transform);
    get_shorts(tif, kGeoKeys, &g.keys);
    get_doubles(tif, kGeoDoubles, &g.doubles);
    get_text(tif, kGeoAscii, &g.ascii);
    for (const auto* v : {&g.pixel_scale, &g.tiepoints, &g.transform, &g.doubles})
        for (double x : *v)
            if (!std::isfinite(x)) return Status::bad_input("TIFF GeoTIFF tag has a value that is not a finite number");
    std::string nodata;
    if (get_text(tif, kGdalNodata, &nodata)) {
        double v = 0;
        if (!parse_number(nodata, &v)) return Status::bad_input("TIFF GDAL_NODATA tag '" + printable(nodata.substr(0, 40)) + "' is not a number");
        in.meta.has_nodata = true;
        in.meta.nodata = v;
    }
    return Status::success();
}

Status TiffReader::read(int x0, int y0, int x1, int y1, Image* out, std::string* warning) {
    Impl& d = *impl_;
    const TiffInfo& in = d.info;
    if (!d.tif) return Status::failure("TIFF: no file open");
    if (x0 < 0 || y0 < 0 || x1 > in.width || y1 > in.height || x0 >= x1 || y0 >= y1)
        return Status::bad_input("TIFF window (" + std::to_string(x0) + ", " + std::to_string(y0) + ") - (" + std::to_string(x1) + ", " +
                                 std::to_string(y1) + ") is not inside the " + std::to_string(in.width) + " x " +
                                 std::to_string(in.height) + " image");
    const SampleType t = in.palette ? SampleType::u8 : in.meta.type;
    const bool integer = (t == SampleType::u8 || t == SampleType::u16) && !in.meta.has_nodata;
    const std::size_t W = std::size_t(x1 - x0), H = std::size_t(y1 - y0), C = std::size_t(in.channels);
    const std::size_t spp = std::size_t(in.file_samples), bs = std::size_t(bytes_of(in.palette ? SampleType::u8 : in.meta.type));
    if ((in.file_samples == 2 || in.file_samples == 4) && warning)
        *warning += std::string(warning->empty() ? "" : "\n") + "alpha channel dropped (erd meshes gray or RGB)";
    std::vector<std::uint16_t> ints;
    std::vector<double> reals;
    if (integer) ints.assign(W * H * C, 0);
    else reals.assign(W * H * C, 0.0);
    const double white = t == SampleType::u8 ? 255.0 : t == SampleType::u16 ? 65535.0 : 4294967295.0;
    const std::size_t planes = in.planar ? spp : 1, per_pixel = in.planar ? 1 : spp;
    const std::size_t row_bytes = std::size_t(in.block_width) * per_pixel * bs;
    std::vector<std::vector<unsigned char>> buf(planes);
    const tmsize_t block_size = in.tiled ? TIFFTileSize(d.tif) : TIFFStripSize(d.tif);
    for (auto& b : buf) b.assign(std::size_t(block_size), 0);
    const std::uint32_t bw = in.block_width, bh = in.block_height;
    const std::uint32_t strips_per_plane = (std::uint32_t(in.height) + bh - 1) / bh;
    for (std::uint32_t by = std::uint32_t(y0) / bh; by * bh < std::uint32_t(y1); ++by) {
        for (std::uint32_t bx = in.tiled ? std::uint32_t(x0) / bw : 0; bx * bw < std::uint32_t(in.tiled ? x1 : 1); ++bx) {
            // The block's planes (only those of the channels read: 1 or 3; a palette's one).
            std::size_t rows_got = bh;
            for (std::size_t p = 0; p < planes && p < (in.palette ? 1 : C); ++p) {
                tmsize_t got;
                if (in.tiled) {
                    const ttile_t k = TIFFComputeTile(d.tif, bx * bw, by * bh, 0, tsample_t(p));
                    got = TIFFReadEncodedTile(d.tif, k, buf[p].data(), block_size);
                } else {
                    got = TIFFReadEncodedStrip(d.tif, tstrip_t(std::uint32_t(p) * strips_per_plane + by), buf[p].data(), block_size);
                }
                if (got < 0) return Status::bad_input("TIFF " + std::string(in.tiled ? "tile" : "strip") + " at row " + std::to_string(by * bh) +
                                                      " cannot be decoded: " + why(d.msg, "read error"));
                if (!in.tiled) rows_got = std::min<std::size_t>(rows_got, std::size_t(got) / std::max<std::size_t>(1, row_bytes));
            }
            const std::uint32_t r0 = std::max(by * bh, std::uint32_t(y0)), r1 = std::min<std::uint32_t>((by + 1) * bh, std::uint32_t(y1));
            const std::uint32_t c0 = in.tiled ? std::max(bx * bw, std::uint32_t(x0)) : std::uint32_t(x0);
            const std::uint32_t c1 = in.tiled ? std::min<std::uint32_t>((bx + 1) * bw, std::uint32_t(x1)) : std::uint32_t(x1);
            for (std::uint32_t y = r0; y < r1; ++y) {
                const std::size_t ry = y - by * bh;
                if (!in.tiled && ry >= rows_got)
                    return Status::bad_input("TIFF strip at row " + std::to_string(by * bh) + " holds fewer rows than the image says");
                for (std::uint32_t x = c0; x < c1; ++x) {
                    const std::size_t rx = in.tiled ? x - bx * bw : x;
                    const std::size_t o = ((y - std::uint32_t(y0)) * W + (x - std::uint32_t(x0))) * C;
                    for (std::size_t c = 0; c < C; ++c) {
                        double v;
                        if (in.palette) {
                            const unsigned char idx = buf[0][ry * row_bytes + rx];
                            v = double(d.colormap[c][idx] >> 8);
                        } else {
                            const unsigned char* p = in.planar ? &buf[c][ry * row_bytes + rx * bs]
                                                               : &buf[0][ry * row_bytes + (rx * per_pixel + c) * bs];
                            v = sample_at(p, t);
                            if (in.min_is_white) v = white - v;
                        }
                        if (integer) ints[o + c] = std::uint16_t(v);
                        else reals[o + c] = v;
                    }
                }
            }
        }
    }
    // A colour image whose channels are equal everywhere is gray (as decode_image says).
    std::size_t channels = C;
    if (C == 3) {
        bool same = true;
        for (std::size_t i = 0; same && i < W * H; ++i) {
            if (integer) same = ints[3 * i] == ints[3 * i + 1] && ints[3 * i] == ints[3 * i + 2];
            else same = reals[3 * i] == reals[3 * i + 1] && reals[3 * i] == reals[3 * i + 2];
        }
        if (same) {
            channels = 1;
            for (std::size_t i = 0; i < W * H; ++i) {
                if (integer) ints[i] = ints[3 * i];
                else reals[i] = reals[3 * i];
            }
            if (integer) ints.resize(W * H);
            else reals.resize(W * H);
        }
    }
    if (integer) {
        Image im(int(W), int(H), t == SampleType::u8 ? 255u : 65535u, int(channels));
        im.samples = std::move(ints);
        im.meta = in.meta;
        *out = std::move(im);
        return Status::success();
    }
    // Nodata: NaN, or the GDAL_NODATA value (in every channel of a pixel: any channel marks it).
    if (in.meta.has_nodata && !std::isnan(in.meta.nodata))
        for (double& v : reals)
            if (v == in.meta.nodata) v = std::numeric_limits<double>::quiet_NaN();
    Status s = make_real_image(int(W), int(H), int(channels), std::move(reals), in.meta, out);
    if (!s) return Status::bad_input("TIFF " + s.message);
    return s;
}

Status decode_tiff(const unsigned char* data, std::size_t size, Image* out, std::string* warning, const ImageLimits& limits) {
    if (warning) warning->clear();
    TiffReader r;
    if (Status s = r.open(data, size, limits); !s) return s;
    return r.read(0, 0, r.info().width, r.info().height, out, warning);
}

}  // namespace erd::imageio
