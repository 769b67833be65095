#include "cli/output_names.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <utility>

#include "cli/report.h"

namespace erd::cli {

namespace {

// Absolute path with ".", ".." and repeated slashes removed, lexically (the file may not exist).
std::string normalise(const std::string& path) {
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

}  // namespace

void split_path(const std::string& path, std::string* dir, std::string* base) {
    std::string::size_type slash = path.rfind('/');
    *dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    *base = slash == std::string::npos ? path : path.substr(slash + 1);
}

Status resolve_output(const std::string& path, std::string* target) {
    *target = path;
    struct stat lst, st;
    if (::lstat(path.c_str(), &lst) != 0 || !S_ISLNK(lst.st_mode)) return Status::success();
    if (::stat(path.c_str(), &st) != 0) {
        const int err = errno;
        const char* what = err == ENOENT  ? "a symbolic link to a missing file"
                           : err == ELOOP ? "a symbolic link loop"
                                          : "a symbolic link that cannot be followed";
        return Status::failure(escape_name(path) + ": " + what + " (" + std::strerror(err) +
                               "); erd writes through a link only onto an existing target");
    }
    if (!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) return Status::success();
    char* real = ::realpath(path.c_str(), nullptr);
    if (!real) return Status::failure(os_error(path, errno));
    *target = real;
    std::free(real);
    return Status::success();
}

Status refuse_read_only(const std::string& path, const std::string& target) {
    struct stat st;
    if (::stat(target.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return Status::success();
    if (::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) == 0 || errno != EACCES) return Status::success();
    return Status::failure(escape_name(path) + ": " + std::strerror(EACCES) + " (a read-only file; erd does not replace it)");
}

Status check_output_folder(const std::string& path) {
    std::string target;
    if (path == "-" || !resolve_output(path, &target)) return Status::success();
    struct stat st;
    const bool exists = ::stat(target.c_str(), &st) == 0;
    if (exists && !S_ISREG(st.st_mode)) return Status::success();
    std::string dir, base;
    split_path(target, &dir, &base);
    if (base.empty()) return Status::failure(escape_name(path) + ": not a file name");
    struct stat ds;
    if (::stat(dir.c_str(), &ds) != 0) return Status::failure(os_error(path, errno));
    if (!S_ISDIR(ds.st_mode)) return Status::failure(os_error(path, ENOTDIR));
    if (::faccessat(AT_FDCWD, dir.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
        return Status::failure(os_error(path, errno) + " (erd cannot create files in " + escape_name(dir) + ")");
    const uid_t me = ::geteuid();
    if (exists && (ds.st_mode & S_ISVTX) && me != 0 && st.st_uid != me && ds.st_uid != me)
        return Status::failure(os_error(path, EPERM) + " (another user's file in the sticky folder " + escape_name(dir) + ")");
    return Status::success();
}

namespace {

// What a name refers to, for the clash checks. Two names are one file that writing an output
// would destroy or garble when they are the same regular file, FIFO or socket (stdout a pipe and
// /dev/stdout), or the same name not yet created; a device may be read and written and repeat
// (/dev/null).
struct FileId {
    bool exists = false;
    bool device = false;  // a character or block device
    dev_t dev = 0;
    ino_t ino = 0;
    std::string key;  // its folder's real path + its name (for a name that does not exist yet)
};

FileId id_of_fd(int fd) {
    FileId id;
    struct stat st;
    if (::fstat(fd, &st) == 0) {
        id.exists = true;
        id.device = S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode);
        id.dev = st.st_dev;
        id.ino = st.st_ino;
    }
    id.key = fd == 0 ? "(stdin)" : "(stdout)";
    return id;
}

FileId id_of_path(const std::string& path) {
    FileId id;
    struct stat st;
    if (::stat(path.c_str(), &st) == 0) {
        id.exists = true;
        id.device = S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode);
        id.dev = st.st_dev;
        id.ino = st.st_ino;
    }
    std::string dir, base;
    split_path(normalise(path), &dir, &base);
    char* real = ::realpath(dir.c_str(), nullptr);
    id.key = real ? std::string(real) + "/" + base : normalise(path);
    std::free(real);
    return id;
}

// The files named so far, found by identity (same_file) in logarithmic time: a batch may name
// thousands.
class FileIndex {
public:
    // The index of a file added before that is the same file as `id`, or -1. A name through a
    // folder that does not exist (x/../a.pgm) is found by its normalised name.
    long find(const FileId& id) const {
        if (id.device) return -1;
        if (id.exists) {
            auto it = by_inode_.find({id.dev, id.ino});
            if (it != by_inode_.end()) return long(it->second);
        }
        auto it = by_name_.find(id.key);
        return it == by_name_.end() ? -1 : long(it->second);
    }
    void add(const FileId& id, std::size_t index) {
        if (id.device) return;
        if (id.exists) by_inode_.emplace(std::make_pair(id.dev, id.ino), index);
        by_name_.emplace(id.key, index);
    }

private:
    std::map<std::pair<dev_t, ino_t>, std::size_t> by_inode_;
    std::map<std::string, std::size_t> by_name_;
};

}  // namespace

Status check_output_names(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, bool whole) {
    FileIndex ins, outs;
    for (std::size_t k = 0; k < inputs.size(); ++k)
        if (!inputs[k].empty()) ins.add(inputs[k] == "-" ? id_of_fd(0) : id_of_path(inputs[k]), k);
    int to_stdout = 0;
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const std::string& out = outputs[i];
        if (out.empty()) {
            if (whole) return Status::bad_input("empty output file name");
            continue;
        }
        FileId id;
        if (out == "-") {
            if (++to_stdout > 1) return Status::bad_input("only one output can go to stdout");
            id = id_of_fd(1);
        } else {
            std::string target;
            Status s = resolve_output(out, &target);
            if (!s && whole) return s;
            if (!s) target = out;
            id = id_of_path(target);
            struct stat st;
            if (whole && id.exists && ::stat(target.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
                return Status::failure(escape_name(out) + ": is a directory");
            if (whole && !(s = refuse_read_only(out, target))) return s;
        }
        const std::string shown = out == "-" ? "stdout" : escape_name(out);
        if (const long k = ins.find(id); k >= 0)
            return Status::bad_input(shown + ": output would overwrite the input " +
                                     (inputs[std::size_t(k)] == "-" ? std::string("stdin") : escape_name(inputs[std::size_t(k)])) +
                                     "; choose another output file");
        if (const long k = outs.find(id); k >= 0)
            return Status::bad_input(shown + ": the same file as the output " +
                                     (outputs[std::size_t(k)] == "-" ? std::string("stdout") : escape_name(outputs[std::size_t(k)])) +
                                     "; give each output its own file");
        // Last: a clash (x/../in.pgm, x missing) is the better message than the missing folder.
        if (whole && out != "-")
            if (Status s = check_output_folder(out); !s) return s;
        outs.add(id, i);
    }
    return Status::success();
}

}  // namespace erd::cli
