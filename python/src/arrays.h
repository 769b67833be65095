// numpy arrays in and out of the library: images as erd::api::ImageView (checked, at most one
// copy), meshes and images back as fresh arrays.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "api/erd.h"

namespace erd::py {

namespace pyb = pybind11;

// An image argument: the view the library reads, and what keeps its samples alive. The view
// points into the caller's array when that is native uint16 with contiguous rows (the library
// then makes its one copy); otherwise into `converted`, numpy's one contiguous uint16 copy. A
// real-valued array (float32, float64, int16, int32, uint32, or any with nodata given) is viewed
// as its float64 copy (api::ImageView::reals).
struct ImageArg {
    api::ImageView view;
    pyb::array owner;
};

// Checks `obj` as an image and makes its view. `what` names the argument in messages ("image").
// Accepted: numpy arrays of dtype uint8 or uint16, shape H x W (or H x W x 1: gray) or H x W x 3
// (RGB: a colour view), any strides; and real-valued ones: float32, float64, int16, int32, uint32
// (NaN, and `nodata` when given, mark pixels without data; given for uint8/uint16 it makes them
// real too). Refused with ValueError: other dtypes, other shapes (H x W x 4 is named: drop the
// alpha), empty arrays. maxval: given, else 255 for uint8 and 65535 for uint16.
ImageArg image_arg(pyb::handle obj, const char* what, std::optional<long long> maxval, std::optional<double> nodata = std::nullopt);

// The default maxval of an image argument's dtype (255 or 65535), without other checks.
std::uint32_t dtype_maxval(pyb::handle obj);

// An erd::Image as a new H x W array (H x W x 3 for colour): uint8 when maxval <= 255, else uint16;
// a real image as float64 with NaN where it has no data.
pyb::array image_array(const Image& image);

// A rows x cols array of T filled from `fill(i, j)`.
template <class T, class F>
pyb::array_t<T> table(std::size_t rows, std::size_t cols, F fill) {
    pyb::array_t<T> out({rows, cols});
    auto w = out.template mutable_unchecked<2>();
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) w(pyb::ssize_t(i), pyb::ssize_t(j)) = fill(i, j);
    return out;
}

}  // namespace erd::py
