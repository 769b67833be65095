#include "imageio/image_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace erd::imageio {

Status read_image_file(const std::string& path, Image* out, std::string* warning, const ImageLimits& limits) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return Status::bad_input(path + ": cannot open: " + std::strerror(errno));
    std::string bytes;
    char buf[1 << 16];
    std::size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) {
        if (bytes.size() + got > kMaxImageFileBytes) {
            std::fclose(f);
            return Status::bad_input(path + ": larger than " + std::to_string(kMaxImageFileBytes) + " bytes");
        }
        bytes.append(buf, got);
    }
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) return Status::bad_input(path + ": read error");
    Status s = decode_image(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), out, warning, nullptr, limits);
    if (!s) return Status::error(s.code, path + ": " + s.message);
    return s;
}

Status write_image_file(const std::string& path, const Image& im) {
    std::string bytes;
    Status s = encode_image(im, format_for_name(path), &bytes);
    if (!s) return Status::error(s.code, path + ": " + s.message);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return Status::failure(path + ": cannot create: " + std::strerror(errno));
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !ok) return Status::failure(path + ": write error");
    return Status::success();
}

}  // namespace erd::imageio
