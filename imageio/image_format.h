// erd's optional image-I/O part (build/liberd_imageio.a; docs/architecture.md): PGM and PPM by our
// own readers (and PAM), PNG and JPEG through the fenced stb glue (third_party/stb_glue.h), PNG written with
// zlib. The core library (kernel/, algorithms/, api/) never includes it, so an application that
// has its own images needs neither stb nor zlib.
//
// Everything works on memory; imageio/image_file.h adds plain file reading and writing. The format
// is detected from the first bytes, never from the file name. Every malformed input gets one
// specific line (Code::input, no file name: the caller adds it).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd::imageio {

enum class ImageFormat { unknown, pgm_plain, pgm_raw, ppm_plain, ppm_raw, pam, png, jpeg, tiff, pfm };

// "PGM (P2, plain)", "PGM (P5, raw)", "PPM (P3, plain)", "PPM (P6, raw)", "PAM (P7)", "PNG", "JPEG",
// "TIFF", "PFM", "unknown".
const char* format_name(ImageFormat f);

// Size limits, checked before any allocation. Defaults are those of algorithms/imaging/image.h
// (predicate exactness bounds the side, memory bounds the pixel count); the fuzzers lower them.
struct ImageLimits {
    int max_side = kMaxImageSide;
    std::int64_t max_pixels = kMaxImagePixels;
};

// Detects the format from the magic bytes (P2, P3, P5, P6, P7, the PNG signature, FF D8 FF, II*0
// and MM0* (TIFF; + for BigTIFF), Pf and PF followed by whitespace).
ImageFormat detect_format(const unsigned char* data, std::size_t size);

// Detects the format and decodes. Colour stays colour (channels 3, interleaved); a colour image
// whose three channels are equal everywhere comes back gray (channels 1, the same samples);
// alpha is dropped with a warning. *warning receives non-fatal remarks, one per line (may be
// null); *format (may be null) what was found.
Status decode_image(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                    ImageFormat* format = nullptr, const ImageLimits& limits = ImageLimits());

// The format a file name asks for: PNG for a name ending in ".png" (any case), TIFF for ".tif" and
// ".tiff", PFM for ".pfm", else PGM/PPM (raw, or plain with `plain`), the netpbm type following the
// image's channels. A real image (algorithms/imaging/real_image.h) keeps its values in TIFF (its
// own sample type) and PFM (float32); PNG and PGM/PPM get its 16-bit proxy (lo..hi onto 0..65535).
ImageFormat format_for_name(const std::string& name, bool plain = false);

// Encodes an image as `format` (pgm_* and ppm_* are the same choice: the channels decide; JPEG
// and PAM are not written; TIFF and PFM: imageio/tiff.h, imageio/pfm.h). The image must be valid:
// checked, Code::failure when not.
Status encode_image(const Image& im, ImageFormat format, std::string* bytes);

}  // namespace erd::imageio
