#include "cli/fileio.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "cli/outputs.h"
#include "cli/report.h"

namespace erd::cli {

// Reads fd as far as `framer` says (everything without one); file_size is a regular file's size,
// UINT64_MAX for a stream.
static Status read_fd(int fd, std::uint64_t file_size, const std::string& name, std::string* bytes, std::size_t max_bytes,
                      const Framer& framer, bool* more, std::uint64_t* unread) {
    bytes->clear();
    if (more) *more = false;
    if (unread) *unread = 0;
    const bool stream = file_size == UINT64_MAX;
    bool framed = bool(framer);
    std::uint64_t total = UINT64_MAX;
    char buf[1 << 16];
    for (;;) {
        std::size_t want = sizeof buf;
        // The first read is small, so a bad header stops it after a few KB.
        if (framed && bytes->empty()) want = 4096;
        if (framed && total != UINT64_MAX) want = std::size_t(std::min<std::uint64_t>(want, total - bytes->size()));
        if (want == 0) break;
        ssize_t n = ::read(fd, buf, want);
        if (n < 0) {
            if (errno == EINTR) continue;
            return Status::bad_input(os_error(name, errno));
        }
        if (n == 0) return Status::success();
        if (std::size_t(n) > max_bytes - bytes->size())
            return Status::bad_input(escape_name(name) + ": longer than the limit of " + std::to_string(max_bytes) + " bytes");
        bytes->append(buf, std::size_t(n));
        if (!framed || total != UINT64_MAX) continue;
        if (Status s = framer(*bytes, stream, &total); !s) return Status::bad_input(escape_name(name) + ": " + s.message);
        if (total == UINT64_MAX) continue;
        if (!stream) {
            // A file: whole when little follows the content (its reader sees every byte, as it
            // always did), else the content alone and the size of what follows it.
            if (file_size <= total + kLookAfter) {
                framed = false;
                bytes->reserve(std::size_t(file_size));
                continue;
            }
            if (total < bytes->size()) bytes->resize(std::size_t(total));
            if (unread) *unread = file_size - total;
            if (total == bytes->size()) return Status::success();
        } else if (total < bytes->size()) {
            // The content ended inside this read: the rest is data after it.
            for (std::size_t k = std::size_t(total); k < bytes->size() && more && !*more; ++k)
                *more = !std::isspace(static_cast<unsigned char>((*bytes)[k]));
            bytes->resize(std::size_t(total));
            if (more && *more) return Status::success();
        }
        if (total <= max_bytes) bytes->reserve(std::size_t(total));
    }
    if (!stream) return Status::success();
    // The content of a stream is complete: is anything but a little whitespace after it?
    std::size_t seen = 0;
    while (seen < kLookAfter) {
        ssize_t n = ::read(fd, buf, kLookAfter - seen);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return Status::success();
        for (ssize_t k = 0; k < n; ++k)
            if (!std::isspace(static_cast<unsigned char>(buf[k]))) seen = kLookAfter;
        seen += std::size_t(n);
    }
    if (more) *more = true;
    return Status::success();
}

Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes, const Framer& framer, bool* more,
                 std::uint64_t* unread) {
    if (path.empty()) return Status::bad_input("empty file name");
    const std::string name = path == "-" ? "stdin" : path;
    int fd = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Status::bad_input(os_error(path, errno));
    struct stat st;
    Status s = Status::success();
    if (::fstat(fd, &st) != 0) {
        s = Status::bad_input(os_error(name, errno));
    } else if (S_ISDIR(st.st_mode)) {
        s = Status::bad_input(escape_name(name) + ": is a directory");
    } else if (S_ISREG(st.st_mode) && std::uint64_t(st.st_size) > max_bytes) {
        s = Status::bad_input(escape_name(name) + ": " + std::to_string(st.st_size) + " bytes, above the limit of " +
                              std::to_string(max_bytes) + " bytes");
    } else {
        const bool regular = S_ISREG(st.st_mode);
        if (regular && !framer) bytes->reserve(std::size_t(st.st_size));
        s = read_fd(fd, regular ? std::uint64_t(st.st_size) : UINT64_MAX, name, bytes, max_bytes, framer, more, unread);
    }
    if (fd != 0) ::close(fd);
    return s;
}

Status write_file_atomic(const std::string& path, const std::string& bytes) {
    Outputs outs;
    Status s = outs.stage(path, bytes);
    return s ? outs.commit() : s;
}

Status refuse_overwrite(const std::string& out, const std::vector<std::string>& inputs) {
    return Outputs().check({out}, inputs);
}

}  // namespace erd::cli
