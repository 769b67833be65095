// Image and Grid: the raster types that algorithms/ and kernel/ share, independent of any file format.
//
// Image holds integer samples exactly as read (8- or 16-bit, maxval kept), or a real-valued raster
// (float, signed, 32-bit, or any with nodata: issue 47) in a double plane beside a 16-bit proxy
// (see Image::reals). Grid<T> is a dense row-major array used for every intermediate plane
// (filtered images, gradients, edge maps).
// Coordinates: x to the right (column), y down (row); sample (x, y) is at index y*width + x.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace erd {

// Largest accepted image. The side bound keeps doubled lattice coordinates (at most 2*side-2)
// far inside the exactness bound of kernel/predicates.h; the pixel bound admits 16384 x 16384
// (issue 18) and keeps the half-pixel plane of edge detection under 2^31 cells (point_rings.h).
// Memory is the caller's to cap: the methods' peak heap per pixel is in their registry rows
// (algorithms/methods/methods.cpp: up to 88 bytes per pixel for ERDED and ERDGPI).
constexpr int kMaxImageSide = 32768;
constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;

template <class T>
struct Grid {
    int width = 0;
    int height = 0;
    std::vector<T> data;

    Grid() = default;
    Grid(int w, int h, T fill = T()) : width(w), height(h), data(std::size_t(w) * std::size_t(h), fill) {}

    T& operator()(int x, int y) { return data[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const T& operator()(int x, int y) const { return data[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
    std::size_t size() const { return data.size(); }
};

// The type of a raster's samples in its file: what reconstruction writes back.
enum class SampleType : std::uint8_t { u8, u16, u32, i16, i32, f32, f64 };

// "uint8" "uint16" "uint32" "int16" "int32" "float32" "float64".
inline const char* sample_type_name(SampleType t) {
    static const char* const kNames[] = {"uint8", "uint16", "uint32", "int16", "int32", "float32", "float64"};
    return kNames[int(t)];
}

// GeoTIFF's georeferencing, exactly as the file holds it (no reprojection), to be written again
// into the outputs: ModelPixelScale (tag 33550), ModelTiepoint (33922, 6 values per point),
// ModelTransformation (34264, 16 values), GeoKeyDirectory (34735), GeoDoubleParams (34736) and
// GeoAsciiParams (34737).
struct GeoTags {
    std::vector<double> pixel_scale;
    std::vector<double> tiepoints;
    std::vector<double> transform;
    std::vector<std::uint16_t> keys;
    std::vector<double> doubles;
    std::string ascii;

    bool empty() const {
        return pixel_scale.empty() && tiepoints.empty() && transform.empty() && keys.empty() && doubles.empty() && ascii.empty();
    }
    friend bool operator==(const GeoTags& a, const GeoTags& b) {
        return a.pixel_scale == b.pixel_scale && a.tiepoints == b.tiepoints && a.transform == b.transform && a.keys == b.keys &&
               a.doubles == b.doubles && a.ascii == b.ascii;
    }
};

// What a raster file says beyond its samples, carried from the image through its model to the
// outputs: the sample type, the nodata value (GDAL_NODATA) and the georeferencing.
struct RasterMeta {
    SampleType type = SampleType::u8;
    bool has_nodata = false;
    double nodata = 0.0;  // the file's nodata value, written where no face covers a pixel
    GeoTags geo;
};

// channels is 1 (gray) or 3 (RGB). Samples are interleaved: channel c of pixel (x, y) is at
// index (y*width + x)*channels + c, so a gray image is exactly the thesis's row-major plane.
// at(x, y) is the gray accessor (channels == 1); at(x, y, c) reads any channel.
struct Image {
    int width = 0;
    int height = 0;
    std::uint32_t maxval = 255;          // 1 .. 65535, kept exactly
    int channels = 1;                    // 1 or 3
    std::vector<std::uint16_t> samples;  // interleaved, row-major, each <= maxval

    // Real-valued images (issue 47; algorithms/imaging/real_image.h makes them). `reals` holds every
    // sample exactly, in the data's units, interleaved as `samples`; a nodata pixel holds the value
    // of the nearest valid pixel (so filters see no step at a hole) and is 0 in `valid`, which is
    // empty when every pixel is valid. `samples` then holds a 16-bit proxy (maxval 65535: lo..hi
    // mapped onto 0..65535) for the stages that only look for structure and are scale-free (edge
    // detection, the edge kind, densities, where the line search looks); every value, error and
    // fit reads `reals`. lo, hi: the range of the valid samples (the PSNR peak is hi - lo).
    std::vector<double> reals;
    std::vector<std::uint8_t> valid;
    double lo = 0.0, hi = 0.0;
    RasterMeta meta;  // type (u8 or u16 for an integer image read from a file), nodata, georeferencing

    bool real() const { return !reals.empty(); }
    bool has_holes() const { return !valid.empty(); }

    Image() = default;
    Image(int w, int h, std::uint32_t mv, int c = 1)
        : width(w), height(h), maxval(mv), channels(c), samples(std::size_t(w) * std::size_t(h) * std::size_t(c), 0) {}

    std::uint16_t& at(int x, int y) { return samples[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    std::uint16_t at(int x, int y) const { return samples[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    std::uint16_t& at(int x, int y, int c) { return samples[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)]; }
    std::uint16_t at(int x, int y, int c) const { return samples[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)]; }
    std::size_t pixels() const { return std::size_t(width) * std::size_t(height); }

    // Bits per sample: ceil(log2(maxval + 1)); PSNR peaks at 2^bits - 1 (../shared/spec/NOTES.md).
    int bits() const {
        int b = 0;
        while ((std::uint32_t(1) << b) - 1 < maxval) ++b;
        return b;
    }
};

// Channel c of a colour image as a gray image of the same size and maxval (a real image's
// channel keeps its real plane, mask, range and meta).
inline Image channel_plane(const Image& im, int c) {
    Image g(im.width, im.height, im.maxval);
    for (std::size_t i = 0; i < g.samples.size(); ++i) g.samples[i] = im.samples[i * std::size_t(im.channels) + std::size_t(c)];
    if (im.real()) {
        g.reals.resize(g.samples.size());
        for (std::size_t i = 0; i < g.reals.size(); ++i) g.reals[i] = im.reals[i * std::size_t(im.channels) + std::size_t(c)];
        g.valid = im.valid;
        g.lo = im.lo;
        g.hi = im.hi;
        g.meta = im.meta;
    }
    return g;
}

// Samples as doubles, for filtering (a gray image; a real image's proxy samples).
inline Grid<double> to_grid(const Image& im) {
    Grid<double> g(im.width, im.height);
    for (std::size_t i = 0; i < im.samples.size(); ++i) g.data[i] = im.samples[i];
    return g;
}

}  // namespace erd
