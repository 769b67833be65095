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

struct Image {
    int width = 0;
    int height = 0;
    std::uint32_t maxval = 255;          // 1 .. 65535, kept exactly
    std::vector<std::uint16_t> samples;  // row-major, each <= maxval

    Image() = default;
    Image(int w, int h, std::uint32_t mv) : width(w), height(h), maxval(mv), samples(std::size_t(w) * std::size_t(h), 0) {}

    std::uint16_t& at(int x, int y) { return samples[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    std::uint16_t at(int x, int y) const { return samples[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    std::size_t pixels() const { return samples.size(); }

    // Bits per sample: ceil(log2(maxval + 1)); PSNR peaks at 2^bits - 1 (../shared/spec/NOTES.md).
    int bits() const {
        int b = 0;
        while ((std::uint32_t(1) << b) - 1 < maxval) ++b;
        return b;
    }
};

// Samples as doubles, for filtering.
inline Grid<double> to_grid(const Image& im) {
    Grid<double> g(im.width, im.height);
    for (std::size_t i = 0; i < im.samples.size(); ++i) g.data[i] = im.samples[i];
    return g;
}

}  // namespace erd
