// Image and Grid: the raster types that algorithms/ and kernel/ share, independent of any file format.
//
// Image holds integer samples exactly as read (8- or 16-bit, maxval kept). Grid<T> is a dense
// row-major array used for every intermediate plane (filtered images, gradients, edge maps).
// Coordinates: x to the right (column), y down (row); sample (x, y) is at index y*width + x.
#pragma once
#include <cstddef>
#include <cstdint>
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

// channels is 1 (gray) or 3 (RGB). Samples are interleaved: channel c of pixel (x, y) is at
// index (y*width + x)*channels + c, so a gray image is exactly the thesis's row-major plane.
// at(x, y) is the gray accessor (channels == 1); at(x, y, c) reads any channel.
struct Image {
    int width = 0;
    int height = 0;
    std::uint32_t maxval = 255;          // 1 .. 65535, kept exactly
    int channels = 1;                    // 1 or 3
    std::vector<std::uint16_t> samples;  // interleaved, row-major, each <= maxval

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

// Channel c of a colour image as a gray image of the same size and maxval.
inline Image channel_plane(const Image& im, int c) {
    Image g(im.width, im.height, im.maxval);
    for (std::size_t i = 0; i < g.samples.size(); ++i) g.samples[i] = im.samples[i * std::size_t(im.channels) + std::size_t(c)];
    return g;
}

// Samples as doubles, for filtering (a gray image).
inline Grid<double> to_grid(const Image& im) {
    Grid<double> g(im.width, im.height);
    for (std::size_t i = 0; i < im.samples.size(); ++i) g.data[i] = im.samples[i];
    return g;
}

}  // namespace erd
