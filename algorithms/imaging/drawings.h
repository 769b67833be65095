// Hard-edged test images: drawings, cartoons, screenshots, icons, maps, charts, pixel art and
// aliased rendered scenes, each pixel taking the value of the one shape that covers its centre
// (no anti-aliasing), so every edge is a step between two pixels. A blurred (soft) version of the
// same picture is the binomial filter [1 2 1]/4 applied `blur` times along x and y, in integers.
//
// Deterministic like synth(): geometry in exact integers, shading with + - * / and sqrt only
// (IEEE-exact), no std:: distributions.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd {

struct DrawingParams {
    std::string kind = "drawing";  // one of drawing_kinds()
    int width = 320;
    int height = 240;
    int bits = 8;   // 1..16: maxval = 2^bits - 1
    int blur = 0;   // passes of the binomial [1 2 1]/4 along x and y (0: the hard-edged picture)
};

// The kinds draw_picture() knows, in a fixed order.
const std::vector<std::string>& drawing_kinds();

// Fills *out. Fails (Code::input) on an unknown kind, a size outside 8..kMaxImageSide, above
// kMaxImagePixels, bits outside 1..16 or blur outside 0..64.
Status draw_picture(const DrawingParams& params, Image* out);

// The binomial blur of draw_picture, in place: `passes` times [1 2 1]/4 along x then y, borders
// replicated, each pass rounded half up to integers.
void binomial_blur(Image* im, int passes);

}  // namespace erd
