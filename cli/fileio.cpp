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

// Reads fd: a regular file to its end; a stream as far as `framer` says its content goes.
static Status read_fd(int fd, bool regular, const std::string& name, std::string* bytes, std::size_t max_bytes,
                      const Framer& framer, bool* more) {
    bytes->clear();
    if (more) *more = false;
    const bool framed = framer && !regular;
    std::uint64_t total = UINT64_MAX;
    char buf[1 << 16];
    for (;;) {
        std::size_t want = sizeof buf;
        // The first read of a stream is small, so a bad header stops it after a few KB.
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
        if (framed && total == UINT64_MAX) {
            if (Status s = framer(*bytes, &total); !s) return Status::bad_input(escape_name(name) + ": " + s.message);
            if (total < bytes->size()) {
                // The content ended inside this read: the rest is data after it.
                for (std::size_t k = std::size_t(total); k < bytes->size() && more && !*more; ++k)
                    *more = !std::isspace(static_cast<unsigned char>((*bytes)[k]));
                bytes->resize(std::size_t(total));
                if (more && *more) return Status::success();
            }
            if (total != UINT64_MAX && total <= max_bytes) bytes->reserve(std::size_t(total));
        }
    }
    // The content is complete: is anything but a little whitespace after it?
    std::size_t seen = 0;
    while (seen < 4096) {
        ssize_t n = ::read(fd, buf, 4096 - seen);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return Status::success();
        for (ssize_t k = 0; k < n; ++k)
            if (!std::isspace(static_cast<unsigned char>(buf[k]))) seen = 4096;
        seen += std::size_t(n);
    }
    if (more) *more = true;
    return Status::success();
}

Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes, const Framer& framer, bool* more) {
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
        if (S_ISREG(st.st_mode)) bytes->reserve(std::size_t(st.st_size));
        s = read_fd(fd, S_ISREG(st.st_mode), name, bytes, max_bytes, framer, more);
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
