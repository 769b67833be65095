#include "python/src/arrays.h"

#include <cstring>
#include <limits>
#include <string>

namespace erd::py {

namespace {

std::string shape_text(const pyb::array& a) {
    std::string s = "(";
    for (pyb::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

pyb::array as_array(pyb::handle obj, const char* what) {
    if (!pyb::isinstance<pyb::array>(obj))
        throw pyb::value_error(std::string(what) + " must be a numpy array (uint8 or uint16), got " +
                               std::string(pyb::str(pyb::type::handle_of(obj).attr("__name__"))));
    return pyb::reinterpret_borrow<pyb::array>(obj);
}

}  // namespace

std::uint32_t dtype_maxval(pyb::handle obj) {
    if (!pyb::isinstance<pyb::array>(obj)) return 255;
    const pyb::dtype dt = pyb::reinterpret_borrow<pyb::array>(obj).dtype();
    return dt.itemsize() == 2 ? 65535u : 255u;
}

ImageArg image_arg(pyb::handle obj, const char* what, std::optional<long long> maxval, std::optional<double> nodata) {
    pyb::array a = as_array(obj, what);
    const pyb::dtype dt = a.dtype();
    const char kind = dt.kind();
    const bool small_uint = kind == 'u' && (dt.itemsize() == 1 || dt.itemsize() == 2);
    const bool real = (kind == 'f' && (dt.itemsize() == 4 || dt.itemsize() == 8)) ||
                      (kind == 'i' && (dt.itemsize() == 2 || dt.itemsize() == 4)) || (kind == 'u' && dt.itemsize() == 4) ||
                      (small_uint && nodata);
    if (!small_uint && !real)
        throw pyb::value_error(std::string(what) + " has dtype " + std::string(pyb::str(pyb::handle(dt))) +
                               "; erd takes uint8, uint16 (integer samples) or float32, float64, int16, int32, uint32 "
                               "(real values) arrays");
    // H x W x 3 is colour (R G B per pixel, interleaved as the library takes it); H x W x 1 gray.
    const bool gray3 = a.ndim() == 3 && a.shape(2) == 1;
    const bool rgb = a.ndim() == 3 && a.shape(2) == 3;
    if (a.ndim() == 3 && a.shape(2) == 4)
        throw pyb::value_error(std::string(what) + " has shape " + shape_text(a) +
                               ": RGBA is not taken; drop the alpha channel (image[..., :3])");
    if (a.ndim() != 2 && !gray3 && !rgb)
        throw pyb::value_error(std::string(what) + " must be a 2-D array (H x W) or H x W x 3 (RGB), got shape " + shape_text(a));
    if (a.shape(0) == 0 || a.shape(1) == 0) throw pyb::value_error(std::string(what) + " is empty: shape " + shape_text(a));
    if (a.shape(0) > kMaxImageSide || a.shape(1) > kMaxImageSide)
        throw pyb::value_error(std::string(what) + " of shape " + shape_text(a) + " has a side above " +
                               std::to_string(kMaxImageSide));
    if (real) {
        // One float64 copy by numpy (the values exactly: every dtype taken fits a double).
        pyb::module_ np = pyb::module_::import("numpy");
        ImageArg arg;
        arg.owner = np.attr("ascontiguousarray")(a, np.attr("float64")).cast<pyb::array>();
        const int C = rgb ? 3 : 1;
        arg.view.width = int(a.shape(1));
        arg.view.height = int(a.shape(0));
        arg.view.reals = static_cast<const double*>(arg.owner.data());
        arg.view.stride = std::size_t(a.shape(1)) * std::size_t(C);
        arg.view.channels = C;
        arg.view.has_nodata = bool(nodata);
        arg.view.nodata = nodata ? *nodata : 0.0;
        const std::string name = pyb::str(dt.attr("name"));
        arg.view.type = name == "float32" ? SampleType::f32 : name == "int16" ? SampleType::i16 : name == "int32" ? SampleType::i32
                      : name == "uint32" ? SampleType::u32 : name == "uint8" ? SampleType::u8 : name == "uint16" ? SampleType::u16
                      : SampleType::f64;
        return arg;
    }
    long long mv = maxval ? *maxval : (dt.itemsize() == 2 ? 65535 : 255);
    if (mv < 1 || mv > 65535) throw pyb::value_error("maxval " + std::to_string(mv) + " outside 1..65535");

    ImageArg arg;
    const pyb::ssize_t item = pyb::ssize_t(sizeof(std::uint16_t));
    const bool native16 = dt.itemsize() == 2 && dt.attr("isnative").cast<bool>();
    const pyb::ssize_t C = rgb ? 3 : 1;
    const bool rows_ok = a.strides(1) == C * item && (!rgb || a.strides(2) == item) && a.strides(0) >= a.shape(1) * C * item &&
                         a.strides(0) % item == 0;
    if (native16 && rows_ok) {
        arg.owner = a;  // the library reads the caller's samples in place and copies them once
    } else {
        // One conversion by numpy (widening, byte order, any strides) into a contiguous uint16 array.
        pyb::module_ np = pyb::module_::import("numpy");
        arg.owner = np.attr("ascontiguousarray")(a, np.attr("uint16")).cast<pyb::array>();
    }
    if (gray3) arg.owner = arg.owner.attr("reshape")(a.shape(0), a.shape(1)).cast<pyb::array>();
    arg.view.width = int(a.shape(1));
    arg.view.height = int(a.shape(0));
    arg.view.maxval = std::uint32_t(mv);
    arg.view.samples = static_cast<const std::uint16_t*>(arg.owner.data());
    arg.view.stride = std::size_t(arg.owner.strides(0) / item);
    arg.view.channels = int(C);
    return arg;
}

pyb::array image_array(const Image& image) {
    const std::size_t h = std::size_t(image.height), w = std::size_t(image.width), c = std::size_t(image.channels);
    std::vector<std::size_t> shape = {h, w};
    if (c > 1) shape.push_back(c);
    if (image.real()) {
        pyb::array_t<double> out(shape);
        double* dst = out.mutable_data();
        for (std::size_t i = 0; i < image.reals.size(); ++i)
            dst[i] = image.valid.empty() || image.valid[i / c] ? image.reals[i] : std::numeric_limits<double>::quiet_NaN();
        return out;
    }
    if (image.maxval <= 255) {
        pyb::array_t<std::uint8_t> out(shape);
        std::uint8_t* dst = out.mutable_data();
        for (std::size_t i = 0; i < image.samples.size(); ++i) dst[i] = std::uint8_t(image.samples[i]);
        return out;
    }
    pyb::array_t<std::uint16_t> out(shape);
    std::memcpy(out.mutable_data(), image.samples.data(), image.samples.size() * sizeof(std::uint16_t));
    return out;
}

}  // namespace erd::py
