#include "imageio/image_format.h"

#include <cstring>

#include "imageio/jpeg.h"
#include "imageio/pam.h"
#include "imageio/pfm.h"
#include "imageio/png.h"
#include "imageio/pnm.h"
#include "imageio/tiff.h"
#include "kernel/file_name.h"

namespace erd::imageio {

const char* format_name(ImageFormat f) {
    switch (f) {
        case ImageFormat::pgm_plain: return "PGM (P2, plain)";
        case ImageFormat::pgm_raw: return "PGM (P5, raw)";
        case ImageFormat::ppm_plain: return "PPM (P3, plain)";
        case ImageFormat::ppm_raw: return "PPM (P6, raw)";
        case ImageFormat::pam: return "PAM (P7)";
        case ImageFormat::png: return "PNG";
        case ImageFormat::jpeg: return "JPEG";
        case ImageFormat::tiff: return "TIFF";
        case ImageFormat::pfm: return "PFM";
        case ImageFormat::unknown: break;
    }
    return "unknown";
}

ImageFormat detect_format(const unsigned char* data, std::size_t size) {
    static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 2 && data[0] == 'P') {
        switch (data[1]) {
            case '2': return ImageFormat::pgm_plain;
            case '3': return ImageFormat::ppm_plain;
            case '5': return ImageFormat::pgm_raw;
            case '6': return ImageFormat::ppm_raw;
            case '7': return ImageFormat::pam;
            case 'f': case 'F':
                if (size >= 3 && (data[2] == ' ' || data[2] == '\n' || data[2] == '\r' || data[2] == '\t')) return ImageFormat::pfm;
                break;
            default: break;
        }
    }
    if (size >= 8 && std::memcmp(data, kPngSignature, 8) == 0) return ImageFormat::png;
    if (size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff) return ImageFormat::jpeg;
    if (size >= 4 && ((data[0] == 'I' && data[1] == 'I' && (data[2] == 42 || data[2] == 43) && data[3] == 0) ||
                      (data[0] == 'M' && data[1] == 'M' && data[2] == 0 && (data[3] == 42 || data[3] == 43))))
        return ImageFormat::tiff;
    return ImageFormat::unknown;
}

Status decode_image(const unsigned char* data, std::size_t size, Image* out, std::string* warning, ImageFormat* format,
                    const ImageLimits& limits) {
    ImageFormat f = detect_format(data, size);
    if (format) *format = f;
    if (f == ImageFormat::png) return decode_png(data, size, out, warning, limits);
    if (f == ImageFormat::jpeg) return decode_jpeg(data, size, out, warning, limits);
    if (f == ImageFormat::pam) return decode_pam(data, size, out, warning, limits);
    if (f == ImageFormat::tiff) return decode_tiff(data, size, out, warning, limits);
    if (f == ImageFormat::pfm) return decode_pfm(data, size, out, warning, limits);
    // decode_pnm also explains what an unknown file is.
    return decode_pnm(data, size, out, warning, limits);
}

ImageFormat format_for_name(const std::string& name, bool plain) {
    if (has_extension(name, ".png")) return ImageFormat::png;
    if (has_extension(name, ".tif") || has_extension(name, ".tiff")) return ImageFormat::tiff;
    if (has_extension(name, ".pfm")) return ImageFormat::pfm;
    return plain ? ImageFormat::pgm_plain : ImageFormat::pgm_raw;
}

Status encode_image(const Image& im, ImageFormat format, std::string* bytes) {
    if (im.width <= 0 || im.height <= 0 || (im.channels != 1 && im.channels != 3) ||
        im.samples.size() != im.pixels() * std::size_t(im.channels) || im.maxval < 1 || im.maxval > 65535)
        return Status::failure("internal error: invalid image " + std::to_string(im.width) + " x " + std::to_string(im.height) +
                               " x " + std::to_string(im.channels) + " maxval " + std::to_string(im.maxval));
    switch (format) {
        case ImageFormat::png: return encode_png(im, bytes);
        case ImageFormat::pgm_plain: case ImageFormat::ppm_plain: *bytes = encode_pnm(im, true); return Status::success();
        case ImageFormat::pgm_raw: case ImageFormat::ppm_raw: *bytes = encode_pnm(im, false); return Status::success();
        case ImageFormat::tiff: return encode_tiff(im, bytes);
        case ImageFormat::pfm: return encode_pfm(im, bytes);
        case ImageFormat::pam: case ImageFormat::jpeg: case ImageFormat::unknown: break;
    }
    return Status::failure(std::string("no writer for ") + format_name(format));
}

}  // namespace erd::imageio
