// Image files for the erd program: the codecs are the image-I/O part of the library (imageio/:
// PGM, PPM, PAM, PNG, JPEG), whose names are brought in here; this adds the file handling of
// cli/fileio.h (standard input, streams framed by their header, atomic writes) and prefixes
// every message with the path.
#pragma once
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "imageio/image_format.h"
#include "imageio/jpeg.h"
#include "imageio/pam.h"
#include "imageio/png.h"
#include "imageio/pnm.h"
#include "cli/report.h"
#include "kernel/status.h"

namespace erd::cli {

using imageio::decode_image;
using imageio::decode_jpeg;
using imageio::decode_pam;
using imageio::decode_png;
using imageio::decode_pnm;
using imageio::detect_format;
using imageio::encode_png;
using imageio::encode_pnm;
using imageio::format_name;
using imageio::ImageFormat;
using imageio::ImageLimits;
using imageio::pad_png_palette;
using imageio::pam_header;
using imageio::PamHeader;
using imageio::pnm_header;
using imageio::PnmHeader;

// Reads an image file ("-" = stdin) of any supported format, colour kept (channels 3; a colour
// file whose channels are equal everywhere is gray). Messages and warnings start with the path.
Status read_image(const std::string& path, Image* out, std::string* warning, ImageFormat* format = nullptr,
                  const ImageLimits& limits = ImageLimits());

// read_image's second half for bytes already read from `path`: `more` when a stream went on after
// what its framing took, `unread` the bytes of a file never read (warnings say so).
Status decode_image_bytes(const std::string& path, const std::string& bytes, bool more, std::uint64_t unread, Image* out,
                          std::string* warning, ImageFormat* format = nullptr, const ImageLimits& limits = ImageLimits());

// For a command that works on gray: a colour image becomes its BT.601 luma (algorithms/imaging/
// luma.h, the conversion of every erd before colour). Unless the user asked for it (--gray), one
// warning line saying so is appended to *warning.
void to_gray(const std::string& path, Image* im, bool asked, std::string* warning);

// What a subcommand makes of a colour input image: keeps it, or its luma (to_gray) because the
// user asked (--gray: no warning) or because the command works on gray (a warning).
enum class ColourInput { keep, luma_asked, luma_warn };

// A subcommand's input image: read_image, then to_gray as `colour` says; the warnings of both
// printed through rep.
Status read_input_image(const std::string& path, ColourInput colour, const Reporter& rep, Image* out,
                        ImageFormat* format = nullptr);

// True when the name asks for a format that keeps a real image's values (.tif, .tiff, .pfm).
bool keeps_real_values(const std::string& path);

struct WriteOptions {
    bool plain = false;  // PGM/PPM: write P2/P3 (the thesis's programs write plain PNM) instead of P5/P6
};

// The bytes write_image writes to `path` (PNG or PGM/PPM, chosen by the name as below), for a
// command that stages several outputs (cli/outputs.h). Messages start with the path.
Status encode_image(const std::string& path, const Image& im, const WriteOptions& options, std::string* bytes);

// Writes atomically (cli/fileio.h). A path ending in ".png" (any case) gets PNG (8-bit for
// maxval <= 255, else 16-bit), ".tif"/".tiff" TIFF (imageio/tiff.h), ".pfm" PFM; anything else,
// "-" included, gets PGM for gray and PPM for colour (P5/P6, or P2/P3 with options.plain).
Status write_image(const std::string& path, const Image& im, const WriteOptions& options = WriteOptions());

}  // namespace erd::cli
