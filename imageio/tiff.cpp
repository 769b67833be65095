#include "imageio/tiff.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
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

namespace erd::imageio {

namespace {

// The GeoTIFF tags and GDAL's nodata tag, which libtiff does not know: registered on a handle that
// writes them (a reader sees them as libtiff's anonymous fields, which read the same way).
constexpr ttag_t kPixelScale = 33550, kTiepoint = 33922, kTransform = 34264, kGeoKeys = 34735, kGeoDoubles = 34736,
                 kGeoAscii = 34737, kGdalNodata = 42113;
const TIFFFieldInfo kGeoFields[] = {
    {kPixelScale, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelPixelScaleTag")},
    {kTiepoint, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelTiepointTag")},
    {kTransform, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("ModelTransformationTag")},
    {kGeoKeys, -1, -1, TIFF_SHORT, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoKeyDirectoryTag")},
    {kGeoDoubles, -1, -1, TIFF_DOUBLE, FIELD_CUSTOM, 1, 1, const_cast<char*>("GeoDoubleParamsTag")},
    {kGeoAscii, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GeoAsciiParamsTag")},
    {kGdalNodata, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDAL_NODATA")},
};

// A block (strip or tile) larger than this is refused before libtiff allocates it.
constexpr std::uint64_t kMaxBlockBytes = std::uint64_t(1) << 28;

// The bytes libtiff reads from or writes to: memory, a file, or the caller's sink.
struct Stream {
    const unsigned char* data = nullptr;  // reading memory
    std::uint64_t size = 0;
    std::string* out = nullptr;           // writing memory
    std::FILE* file = nullptr;            // reading a file
    ByteSink* sink = nullptr;             // writing (and reading back) the caller's file
    std::uint64_t pos = 0;
};

tmsize_t stream_read(thandle_t h, void* buf, tmsize_t n) {
    Stream* s = static_cast<Stream*>(h);
    if (n <= 0) return 0;
    if (s->sink) {
        const std::size_t got = s->sink->read_at(s->pos, buf, std::size_t(n));
        s->pos += got;
        return tmsize_t(got);
    }
    if (s->file) {
        if (std::fseek(s->file, long(s->pos), SEEK_SET) != 0) return 0;
        const std::size_t got = std::fread(buf, 1, std::size_t(n), s->file);
        s->pos += got;
        return tmsize_t(got);
    }
    const std::uint64_t size = s->out ? s->out->size() : s->size;
    const unsigned char* data = s->out ? reinterpret_cast<const unsigned char*>(s->out->data()) : s->data;
    if (s->pos >= size) return 0;
    const std::uint64_t k = std::min<std::uint64_t>(std::uint64_t(n), size - s->pos);
    std::memcpy(buf, data + s->pos, std::size_t(k));
    s->pos += k;
    return tmsize_t(k);
}

tmsize_t stream_write(thandle_t h, void* buf, tmsize_t n) {
    Stream* s = static_cast<Stream*>(h);
    if (s->sink && n >= 0) {
        if (!s->sink->write_at(s->pos, buf, std::size_t(n))) return 0;
        s->pos += std::uint64_t(n);
        return n;
    }
    if (!s->out || n < 0) return 0;
    const std::uint64_t end = s->pos + std::uint64_t(n);
    if (end > s->out->size()) s->out->resize(std::size_t(end));
    std::memcpy(&(*s->out)[std::size_t(s->pos)], buf, std::size_t(n));
    s->pos = end;
    return n;
}

toff_t stream_size(thandle_t h) {
    Stream* s = static_cast<Stream*>(h);
    if (s->sink) return toff_t(s->sink->size());
    return s->out ? toff_t(s->out->size()) : toff_t(s->size);
}

toff_t stream_seek(thandle_t h, toff_t off, int whence) {
    Stream* s = static_cast<Stream*>(h);
    std::uint64_t base = 0;
    if (whence == SEEK_CUR) base = s->pos;
    else if (whence == SEEK_END) base = stream_size(h);
    s->pos = base + off;
    return s->pos;
}

int stream_close(thandle_t) { return 0; }
int stream_map(thandle_t, void**, toff_t*) { return 0; }
void stream_unmap(thandle_t, void*, toff_t) {}

// libtiff's messages for one handle: the first error kept (one line), warnings dropped (unknown
// tags, such as the GeoTIFF ones, are warnings).
struct Messages {
    std::string error;
};

int on_error(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
    Messages* m = static_cast<Messages*>(user);
    if (m && m->error.empty()) {
        char buf[512];
        std::vsnprintf(buf, sizeof buf, fmt, ap);
        std::string line = buf;
        if (module && *module && line.find(module) == std::string::npos) line = std::string(module) + ": " + line;
        for (char& c : line)
            if (c == '\n' || c == '\r') c = ' ';
        m->error = printable(line);
    }
    return 1;
}

int on_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

TIFF* open_stream(Stream* s, const char* mode, Messages* msg, std::uint64_t max_alloc) {
    TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
    if (!opts) return nullptr;
    TIFFOpenOptionsSetErrorHandlerExtR(opts, on_error, msg);
    TIFFOpenOptionsSetWarningHandlerExtR(opts, on_warning, msg);
    if (max_alloc) TIFFOpenOptionsSetMaxSingleMemAlloc(opts, tmsize_t(max_alloc));
    TIFF* tif = TIFFClientOpenExt("TIFF", mode, s, stream_read, stream_write, stream_seek, stream_close, stream_size, stream_map,
                                  stream_unmap, opts);
    TIFFOpenOptionsFree(opts);
    return tif;
}

std::string why(const Messages& m, const std::string& fallback) { return m.error.empty() ? fallback : m.error; }

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

int bytes_of(SampleType t) {
    switch (t) {
        case SampleType::u8: return 1;
        case SampleType::u16: case SampleType::i16: return 2;
        case SampleType::u32: case SampleType::i32: case SampleType::f32: return 4;
        case SampleType::f64: return 8;
    }
    return 1;
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
