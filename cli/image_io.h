// Image files: our own PGM (netpbm P2/P5, 8- and 16-bit, maxval kept exactly) and PNG through the
// fenced stb glue (third_party/stb_glue.h). The format is detected from the first bytes, never
// from the file name. Every malformed input of ../shared/spec/INPUTS.md gets one specific line.
//
// Decoders work on memory so the fuzzers and tests reach them without files; read_image and
// write_image add the file handling of cli/fileio.h and prefix messages with the path.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/imaging/image.h"
#include "kernel/status.h"

namespace erd::cli {

enum class ImageFormat { unknown, pgm_plain, pgm_raw, png };

// "PGM (P2, plain)", "PGM (P5, raw)", "PNG", "unknown".
const char* format_name(ImageFormat f);

// Size limits, checked before any allocation. Defaults are those of algorithms/imaging/image.h
// (predicate exactness bounds the side, memory bounds the pixel count); the fuzzers lower them.
struct ImageLimits {
    int max_side = kMaxImageSide;
    std::int64_t max_pixels = kMaxImagePixels;
};

// Detects the format from the magic bytes (P2, P5, PNG signature). Unknown for anything else.
ImageFormat detect_format(const unsigned char* data, std::size_t size);

// The header of a PGM: magic, width, height, maxval (each checked against the limits) and the
// index of the one whitespace byte that ends it (the raster starts after it).
struct PgmHeader {
    bool plain = false;
    std::uint64_t w = 0, h = 0, maxval = 0;
    std::size_t sep = 0;
};
Status pgm_header(const unsigned char* data, std::size_t size, const ImageLimits& limits, PgmHeader* header);

// Decodes a PGM from memory. *warning receives non-fatal remarks (e.g. a CR before an LF after
// maxval); it may be null. Errors are Code::input with a one-line message without file name.
Status decode_pgm(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

// Decodes a PNG from memory: 8/16-bit gray kept, colour turned into BT.601 luma (with a warning),
// alpha ignored (with a warning). The size is checked from the header before decoding.
Status decode_png(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                  const ImageLimits& limits = ImageLimits());

// Detects the format and decodes; *format (may be null) receives what was found.
Status decode_image(const unsigned char* data, std::size_t size, Image* out, std::string* warning,
                    ImageFormat* format = nullptr, const ImageLimits& limits = ImageLimits());

// PGM bytes: P5 (raw) or P2 (plain, at most 70 characters a line). maxval kept, 16-bit big-endian.
// The image must be valid (sizes > 0, samples <= maxval, 1 <= maxval <= 65535): not rechecked.
std::string encode_pgm(const Image& im, bool plain);

// 8-bit gray PNG bytes. Fails (Code::input) when maxval > 255. Samples are stored as they are
// (not rescaled to 255): a PNG has no maxval, so one written from maxval < 255 reads back with
// maxval 255 and the same sample values (docs/DECISIONS.md, Images).
Status encode_png(const Image& im, std::string* out);

// Reads an image file ("-" = stdin) of any supported format. Messages start with the path.
Status read_image(const std::string& path, Image* out, std::string* warning, ImageFormat* format = nullptr,
                  const ImageLimits& limits = ImageLimits());

struct WriteOptions {
    bool plain = false;  // PGM: write P2 (the thesis's programs write plain PNM) instead of P5
};

// The bytes write_image writes to `path` (PNG or PGM, chosen by the name as below), for a
// command that stages several outputs (cli/outputs.h). Messages start with the path.
Status encode_image(const std::string& path, const Image& im, const WriteOptions& options, std::string* bytes);

// Writes atomically (cli/fileio.h). A path ending in ".png" (any case) gets PNG, which needs
// maxval < 256 (else Code::input, before anything is written); anything else, "-" included,
// gets PGM (P5, or P2 with options.plain).
Status write_image(const std::string& path, const Image& im, const WriteOptions& options = WriteOptions());

}  // namespace erd::cli
