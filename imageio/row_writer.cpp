#include "imageio/row_writer.h"

#include "imageio/pfm.h"
#include "imageio/tiff.h"

namespace erd::imageio {

Status open_row_writer(ImageFormat format, ByteSink* sink, int w, int h, int channels, const RasterMeta& meta,
                       std::unique_ptr<RowWriter>* out) {
    if (w < 1 || h < 1 || (channels != 1 && channels != 3)) return Status::failure("row writer: bad raster size or channels");
    if (format == ImageFormat::tiff) return open_tiff_row_writer(sink, w, h, channels, meta, out);
    if (format == ImageFormat::pfm) return open_pfm_row_writer(sink, w, h, channels, out);
    return Status::bad_input(std::string(format_name(format)) + " is not written by rows (TIFF and PFM are)");
}

}  // namespace erd::imageio
