// PNG read by rows (png_rows.h).
#include "imageio/png_rows.h"

#include <cstdlib>
#include <cstring>
#include <string>

namespace erd::imageio {

namespace {

std::uint32_t be32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

}  // namespace

PngRows::~PngRows() {
    if (z_open_) inflateEnd(&z_);
}

Status PngRows::open(std::FILE* f, const ImageLimits& limits) {
    f_ = f;
    unsigned char h[33];
    if (std::fseek(f, 0, SEEK_SET) != 0 || std::fread(h, 1, 33, f) != 33) return Status::bad_input("PNG header truncated");
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (std::memcmp(h, sig, 8) != 0 || be32(h + 8) != 13 || std::memcmp(h + 12, "IHDR", 4) != 0)
        return Status::bad_input("not a PNG with its IHDR first");
    if (crc32(crc32(0L, Z_NULL, 0), h + 12, 17) != be32(h + 29)) return Status::bad_input("PNG IHDR CRC mismatch");
    width_ = be32(h + 16);
    height_ = be32(h + 20);
    const int depth = h[24], type = h[25], interlace = h[28];
    if (width_ == 0 || height_ == 0 || width_ > std::uint32_t(limits.max_side) || height_ > std::uint32_t(limits.max_side) ||
        std::int64_t(width_) * std::int64_t(height_) > limits.max_pixels)
        return Status::bad_input("PNG size " + std::to_string(width_) + " x " + std::to_string(height_) + " outside the limits");
    if ((depth != 8 && depth != 16) || (type != 0 && type != 2) || interlace != 0 || h[26] != 0 || h[27] != 0)
        return Status::bad_input("PNG read by rows: gray or RGB, 8 or 16 bits, not interlaced (this one: depth " + std::to_string(depth) +
                                 ", colour type " + std::to_string(type) + (interlace ? ", interlaced" : "") + ")");
    channels_ = type == 2 ? 3 : 1;
    bytes_ = depth / 8;
    row_bytes_ = std::size_t(width_) * std::size_t(channels_) * std::size_t(bytes_);
    first_chunk_ = 33;
    return restart();
}

Status PngRows::restart() {
    if (z_open_) inflateEnd(&z_);
    z_ = z_stream{};
    if (inflateInit(&z_) != Z_OK) return Status::failure("zlib: inflateInit failed");
    z_open_ = true;
    if (std::fseek(f_, first_chunk_, SEEK_SET) != 0) return Status::bad_input("PNG truncated");
    chunk_left_ = 0;
    ended_ = false;
    in_.assign(std::size_t(1) << 16, 0);
    prev_.assign(row_bytes_, 0);
    cur_.assign(row_bytes_ + 1, 0);
    next_ = 0;
    return Status::success();
}

Status PngRows::next_row() {
    z_.next_out = cur_.data();
    z_.avail_out = uInt(cur_.size());
    while (z_.avail_out > 0) {
        if (z_.avail_in == 0) {
            // The next bytes of the IDAT stream: the rest of this chunk, else the next IDAT.
            while (chunk_left_ == 0) {
                if (ended_) return Status::bad_input("PNG image data ends at row " + std::to_string(next_));
                unsigned char head[8];
                if (std::fread(head, 1, 8, f_) != 8) return Status::bad_input("PNG truncated at row " + std::to_string(next_));
                const std::uint32_t len = be32(head);
                if (len > 0x7fffffffu) return Status::bad_input("PNG chunk length out of range");
                if (std::memcmp(head + 4, "IDAT", 4) == 0) {
                    chunk_left_ = len;
                    chunk_crc_ = std::uint32_t(crc32(crc32(0L, Z_NULL, 0), head + 4, 4));
                    if (len == 0) {  // an empty IDAT: its CRC follows at once
                        unsigned char c[4];
                        if (std::fread(c, 1, 4, f_) != 4 || be32(c) != chunk_crc_) return Status::bad_input("PNG IDAT CRC mismatch");
                    }
                    continue;
                }
                if (std::memcmp(head + 4, "IEND", 4) == 0) ended_ = true;
                if (std::fseek(f_, long(len) + 4, SEEK_CUR) != 0) return Status::bad_input("PNG truncated");
            }
            const std::uint32_t k = std::min<std::uint32_t>(chunk_left_, std::uint32_t(in_.size()));
            if (std::fread(in_.data(), 1, k, f_) != k) return Status::bad_input("PNG truncated at row " + std::to_string(next_));
            chunk_crc_ = std::uint32_t(crc32(chunk_crc_, in_.data(), k));
            chunk_left_ -= k;
            if (chunk_left_ == 0) {
                unsigned char c[4];
                if (std::fread(c, 1, 4, f_) != 4 || be32(c) != chunk_crc_) return Status::bad_input("PNG IDAT CRC mismatch");
            }
            z_.next_in = in_.data();
            z_.avail_in = k;
        }
        const int r = inflate(&z_, Z_NO_FLUSH);
        if (r == Z_STREAM_END && z_.avail_out > 0) return Status::bad_input("PNG image data ends at row " + std::to_string(next_));
        if (r != Z_OK && r != Z_STREAM_END && r != Z_BUF_ERROR) return Status::bad_input("PNG image data corrupt (zlib)");
    }
    const unsigned filter = cur_[0];
    unsigned char* row = cur_.data() + 1;
    const std::size_t bpp = std::size_t(channels_) * std::size_t(bytes_), n = row_bytes_;
    const bool first = next_ == 0;
    switch (filter) {
        case 0: break;
        case 1:
            for (std::size_t i = bpp; i < n; ++i) row[i] = (unsigned char)(row[i] + row[i - bpp]);
            break;
        case 2:
            if (!first)
                for (std::size_t i = 0; i < n; ++i) row[i] = (unsigned char)(row[i] + prev_[i]);
            break;
        case 3:
            for (std::size_t i = 0; i < n; ++i) {
                const int a = i >= bpp ? row[i - bpp] : 0, b = first ? 0 : prev_[i];
                row[i] = (unsigned char)(row[i] + ((a + b) >> 1));
            }
            break;
        case 4:
            for (std::size_t i = 0; i < n; ++i) {
                const int a = i >= bpp ? row[i - bpp] : 0, b = first ? 0 : prev_[i], c = i >= bpp && !first ? prev_[i - bpp] : 0;
                row[i] = (unsigned char)(row[i] + paeth(a, b, c));
            }
            break;
        default: return Status::bad_input("PNG row " + std::to_string(next_) + ": unknown filter " + std::to_string(filter));
    }
    std::memcpy(prev_.data(), row, n);
    ++next_;
    return Status::success();
}

Status PngRows::read(int x0, int y0, int x1, int y1, Image* out) {
    Status st;
    if (y0 < next_ && !(st = restart())) return st;
    const std::size_t C = std::size_t(channels_), ww = std::size_t(x1 - x0), wh = std::size_t(y1 - y0);
    Image im(int(ww), int(wh), bytes_ == 1 ? 255u : 65535u, channels_);
    while (next_ < y1) {
        if (!(st = next_row())) return st;
        const std::int64_t y = next_ - 1;
        if (y < y0) continue;
        std::uint16_t* dst = &im.samples[std::size_t(y - y0) * ww * C];
        const unsigned char* src = prev_.data() + std::size_t(x0) * C * std::size_t(bytes_);
        for (std::size_t k = 0; k < ww * C; ++k)
            dst[k] = bytes_ == 1 ? src[k] : std::uint16_t(src[2 * k] << 8 | src[2 * k + 1]);
    }
    im.meta.type = bytes_ == 1 ? SampleType::u8 : SampleType::u16;
    *out = std::move(im);
    return Status::success();
}

}  // namespace erd::imageio
