// Where the content of a stream ends (cli/fileio.h Framer), so a pipe or a device is read only
// as far as its header says: /dev/zero, /dev/urandom or `yes |` stop within the first 4 KiB,
// and a valid header is followed by its declared body and nothing more. Also the PNG palette
// check that stb does not make.
#pragma once
#include <cstddef>
#include <string>

#include "cli/fileio.h"
#include "cli/image_io.h"

namespace erd::cli {

// Longest PGM header (comments included) accepted from a stream.
constexpr std::size_t kMaxStreamHeader = 65536;

// Images: a PGM's header gives its size (P5: header + W*H*bytes per sample; P2: W*H decimal
// samples counted as they arrive); a PNG ends with its IEND chunk; anything else is already bad.
Framer image_framer(const ImageLimits& limits);

// Model (.model, .erd) or triangulation text: stops at a NUL byte, or when the text read so far
// already holds an error other than "the file ends early" (checked at 4 KiB, 16 KiB, ...).
Framer model_framer(bool triangulation);

// A palette PNG whose PLTE chunk has fewer entries than its bit depth can index: stb would take
// the colour of a larger index from uninitialised memory. Sets *short_palette and writes to
// *padded a copy whose PLTE has every entry, the missing ones all `fill`, and *entries to the
// count the file had; decode_png decodes it with fill 0 and 255 and refuses the image when the
// two differ (a pixel uses a missing entry). A tRNS longer than the palette is refused here.
Status pad_png_palette(const unsigned char* data, std::size_t size, unsigned char fill, bool* short_palette,
                       std::string* padded, std::size_t* entries);

}  // namespace erd::cli
