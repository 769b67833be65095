// Image bytes held in a string, decoded as erd reads any image file (imageio::decode_image), and
// the refusal every bad file must get: for the image-file tests (test_image_io.cpp,
// test_colour_io.cpp).
#pragma once
#include <catch2/catch.hpp>

#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "kernel/status.h"

namespace erd_test {

// warning, format: may be null.
inline erd::Status decode(const std::string& bytes, erd::Image* im, std::string* warning = nullptr,
                          erd::imageio::ImageFormat* format = nullptr,
                          const erd::imageio::ImageLimits& limits = erd::imageio::ImageLimits()) {
    std::string w;
    return erd::imageio::decode_image(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), im,
                                      warning ? warning : &w, format, limits);
}

// Refused as bad input with one line that names the problem (contains `fragment`).
inline void check_refused(const erd::Status& s, const std::string& fragment) {
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains(fragment));
    CHECK(s.message.find('\n') == std::string::npos);
}

}  // namespace erd_test
