// Where the content of a file or stream ends (cli/fileio.h Framer), so a pipe, a device or a file
// is read only as far as its header says: /dev/zero, /dev/urandom or `yes |` stop within the
// first 4 KiB, a valid header is followed by its declared body and nothing more, and a small
// image followed by a gigabyte reads the image (and a bounded look after it, cli/fileio.h).
#pragma once
#include <cstddef>
#include <string>

#include "cli/fileio.h"
#include "cli/image_io.h"

namespace erd::cli {

// Longest PGM/PPM header (comments included) accepted from a stream.
constexpr std::size_t kMaxStreamHeader = 65536;

// Images: a PGM's or PPM's header gives its size (P5/P6: header + W*H*channels*bytes per sample;
// P2/P3: W*H*channels decimal samples counted as they arrive), a PAM's likewise; a PNG ends with
// its IEND chunk; a JPEG with its end-of-image marker after the scans (one that is not a chain
// of segments is read to its end, up to the input cap); anything else is already bad.
Framer image_framer(const ImageLimits& limits);

// Model (.model, .erd) or triangulation text: stops at a NUL byte, or, from a stream, when the
// text read so far already holds an error other than "the file ends early" (checked at 4 KiB,
// 16 KiB, ...); a regular file without a NUL is read to its end (its size is known and capped).
// .erdz (binary): its header gives its size.
Framer model_framer(bool triangulation);

// Polylines text (erd-polylines 1, generate --constraints): as model text.
Framer polylines_framer();

// Whether the first bytes of a file are a model's: the .erdz magic, or text that starts with a
// number or "erd-", which no image does.
bool looks_like_model(const std::string& start);

// A model or an image, told by its first bytes (looks_like_model), then framed as either; the
// total stays unknown until 64 bytes or a non-blank one have come (erd info -).
Framer model_or_image_framer(const ImageLimits& limits);

}  // namespace erd::cli
