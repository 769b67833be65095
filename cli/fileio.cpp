#include "cli/fileio.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace erd::cli {

static std::string os_error(const std::string& what, int err) { return what + ": " + std::strerror(err); }

// Reads fd to the end, keeping at most max_bytes; one byte more means "too long".
static Status read_fd(int fd, const std::string& name, std::string* bytes, std::size_t max_bytes) {
    bytes->clear();
    char buf[1 << 16];
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            return Status::bad_input(os_error(name, errno));
        }
        if (n == 0) break;
        if (std::size_t(n) > max_bytes - bytes->size())
            return Status::bad_input(name + ": longer than the limit of " + std::to_string(max_bytes) + " bytes");
        bytes->append(buf, std::size_t(n));
    }
    return Status::success();
}

Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes) {
    if (path.empty()) return Status::bad_input("empty file name");
    if (path == "-") return read_fd(0, "stdin", bytes, max_bytes);
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Status::bad_input(os_error(path, errno));
    struct stat st;
    if (::fstat(fd, &st) != 0) {
        int e = errno;
        ::close(fd);
        return Status::bad_input(os_error(path, e));
    }
    if (S_ISDIR(st.st_mode)) {
        ::close(fd);
        return Status::bad_input(path + ": is a directory");
    }
    if (S_ISREG(st.st_mode) && std::uint64_t(st.st_size) > max_bytes) {
        ::close(fd);
        return Status::bad_input(path + ": " + std::to_string(st.st_size) + " bytes, above the limit of " +
                                 std::to_string(max_bytes) + " bytes");
    }
    if (S_ISREG(st.st_mode)) bytes->reserve(std::size_t(st.st_size));
    Status s = read_fd(fd, path, bytes, max_bytes);
    ::close(fd);
    return s;
}

static bool write_all(int fd, const std::string& bytes, int* err) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            *err = errno;
            return false;
        }
        done += std::size_t(n);
    }
    return true;
}

// Writes straight into an existing non-regular file (a device, a pipe): there is nothing to
// rename over, and replacing /dev/null with a regular file would be a disaster.
static Status write_direct(int fd, const std::string& name, const std::string& bytes) {
    int err = 0;
    if (!write_all(fd, bytes, &err)) return Status::failure(os_error(name, err));
    return Status::success();
}

Status write_file_atomic(const std::string& path, const std::string& bytes) {
    if (path.empty()) return Status::bad_input("empty output file name");
    if (path == "-") return write_direct(1, "stdout", bytes);
    // Follow a symbolic link so the link survives and its target gets the new contents.
    std::string target = path;
    struct stat lst;
    if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        char* real = ::realpath(path.c_str(), nullptr);
        if (real) {
            target = real;
            std::free(real);
        }
    }
    struct stat st;
    bool exists = ::stat(target.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) return Status::failure(path + ": is a directory");
    if (exists && !S_ISREG(st.st_mode)) {
        int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) return Status::failure(os_error(path, errno));
        Status s = write_direct(fd, path, bytes);
        if (::close(fd) != 0 && s.ok()) s = Status::failure(os_error(path, errno));
        return s;
    }

    std::string::size_type slash = target.rfind('/');
    std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : target.substr(0, slash));
    std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    if (base.empty()) return Status::failure(path + ": not a file name");
    // The temporary name is ours (not mkstemp's) so open() can create it with mode 0666 and let
    // the kernel apply the umask, as for any new file, without touching the process umask.
    static std::atomic<unsigned> counter{0};
    std::string tmp;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        tmp = (dir == "/" ? "" : dir) + "/." + base + ".tmp-" + std::to_string(::getpid()) + "-" +
              std::to_string(counter.fetch_add(1));
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) {
        // ENOTDIR: a parent is a file; ENOENT: the folder does not exist; EACCES/EROFS: not writable.
        return Status::failure(os_error(path, errno));
    }
    int err = 0;
    bool ok = write_all(fd, bytes, &err);
    if (ok && ::fsync(fd) != 0) { err = errno; ok = false; }
    // An existing file keeps its permissions.
    if (ok && exists && ::fchmod(fd, st.st_mode & 07777) != 0) { err = errno; ok = false; }
    if (::close(fd) != 0 && ok) { err = errno; ok = false; }
    if (ok && ::rename(tmp.c_str(), target.c_str()) != 0) { err = errno; ok = false; }
    if (!ok) {
        ::unlink(tmp.c_str());
        return Status::failure(os_error(path, err));
    }
    // Make the rename durable; failure here loses nothing already visible, so it is ignored.
    int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        (void)::fsync(dfd);
        ::close(dfd);
    }
    return Status::success();
}

// Absolute path with ".", ".." and repeated slashes removed, without touching the file system
// beyond getcwd (the file may not exist yet).
static std::string normalise(const std::string& path) {
    std::string full = path;
    if (full.empty() || full[0] != '/') {
        char* cwd = ::getcwd(nullptr, 0);
        std::string c = cwd ? cwd : ".";
        std::free(cwd);
        full = c + "/" + full;
    }
    std::vector<std::string> parts;
    std::string::size_type i = 0;
    while (i <= full.size()) {
        std::string::size_type j = full.find('/', i);
        if (j == std::string::npos) j = full.size();
        std::string part = full.substr(i, j - i);
        if (part == "..") {
            if (!parts.empty()) parts.pop_back();
        } else if (!part.empty() && part != ".") {
            parts.push_back(part);
        }
        i = j + 1;
    }
    std::string out;
    for (const auto& p : parts) out += "/" + p;
    return out.empty() ? "/" : out;
}

Status refuse_overwrite(const std::string& out, const std::vector<std::string>& inputs) {
    if (out == "-" || out.empty()) return Status::success();
    struct stat so;
    bool out_exists = ::stat(out.c_str(), &so) == 0;
    std::string out_norm = normalise(out);
    for (const auto& in : inputs) {
        if (in == "-" || in.empty()) continue;
        struct stat si;
        bool same = false;
        if (out_exists && ::stat(in.c_str(), &si) == 0)
            same = so.st_dev == si.st_dev && so.st_ino == si.st_ino;
        else
            same = out_norm == normalise(in);
        if (same) {
            // Devices such as /dev/null may be both read and written; only files are protected.
            if (out_exists && !S_ISREG(so.st_mode)) continue;
            return Status::bad_input(out + ": output would overwrite the input " + in + "; choose another output file");
        }
    }
    return Status::success();
}

}  // namespace erd::cli
