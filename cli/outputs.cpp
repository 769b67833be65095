#include "cli/outputs.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <utility>

#include "cli/report.h"

namespace erd::cli {

namespace {

std::string os_error(const std::string& name, int err) { return escape_name(name) + ": " + std::strerror(err); }

// The named temporaries that exist right now, for the signal handler: fixed buffers, so the
// handler touches no allocator. This is the one piece of process-wide state in erd; it exists
// because a signal handler can reach nothing else.
constexpr int kSlots = 32;
struct Slot {
    volatile sig_atomic_t used;
    int dirfd;
    char name[48];
};
Slot g_slots[kSlots];
const int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

extern "C" void remove_temporaries_and_die(int sig) {
    for (Slot& s : g_slots)
        if (s.used) ::unlinkat(s.dirfd, s.name, 0);
    ::signal(sig, SIG_DFL);
    ::raise(sig);  // delivered when the handler returns: the usual death by this signal
}

}  // namespace

void install_output_signal_handlers() {
    for (int sig : kSignals) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup stays
        struct sigaction sa {};
        sa.sa_handler = remove_temporaries_and_die;
        sigfillset(&sa.sa_mask);
        ::sigaction(sig, &sa, nullptr);
    }
    // A file-size limit (ulimit -f) then fails the write with EFBIG instead of killing us.
    ::signal(SIGXFSZ, SIG_IGN);
}

void guard_standard_streams() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        // The lowest free number: fd itself, since the ones below it are open by now.
        const int got = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
        if (got >= 0 && got != fd) ::close(got);
    }
}

namespace {

// Registers a temporary name before it is created; -1 when every slot is taken.
int claim_slot(int dirfd, const std::string& name) {
    if (name.size() >= sizeof g_slots[0].name) return -1;
    for (int k = 0; k < kSlots; ++k) {
        if (g_slots[k].used) continue;
        g_slots[k].dirfd = dirfd;
        std::memcpy(g_slots[k].name, name.c_str(), name.size() + 1);
        std::atomic_signal_fence(std::memory_order_seq_cst);
        g_slots[k].used = 1;
        return k;
    }
    return -1;
}

void release_slot(int* k) {
    if (*k >= 0) g_slots[*k].used = 0;
    *k = -1;
}

std::string temp_name() {
    static unsigned counter = 0;
    return ".erd-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
}

bool write_all(int fd, const std::string& bytes, int* err) {
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

void split(const std::string& path, std::string* dir, std::string* base) {
    std::string::size_type slash = path.rfind('/');
    *dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    *base = slash == std::string::npos ? path : path.substr(slash + 1);
}

// The file an output name writes: a symbolic link to a regular file resolved to its target (the
// whole chain), so the target is replaced in its own folder. A link to a special file (/dev/stdout
// to a pipe, /dev/fd/N) keeps its name: it is opened and written in place.
Status resolve(const std::string& path, std::string* target) {
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

// An old regular file we may not write (mode 0444 for its owner, another user's file) is not
// replaced either, although its folder would allow the rename: erd writes what `>` could write.
Status refuse_read_only(const std::string& path, const std::string& target) {
    struct stat st;
    if (::stat(target.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return Status::success();
    if (::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) == 0 || errno != EACCES) return Status::success();
    return Status::failure(escape_name(path) + ": " + std::strerror(EACCES) + " (a read-only file; erd does not replace it)");
}

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
    split(normalise(path), &dir, &base);
    char* real = ::realpath(dir.c_str(), nullptr);
    id.key = real ? std::string(real) + "/" + base : normalise(path);
    std::free(real);
    return id;
}

// One temporary's way onto its target, prepared before the fork so the child only makes
// system calls.
struct Move {
    int dirfd = -1, fd = -1;
    std::string base;      // the target's name in dirfd
    std::string named;     // a named temporary: renamed onto base
    std::string proc;      // an O_TMPFILE: its /proc/self/fd path, linked in ...
    std::string link_tmp;  // ... under this name first when it replaces a file (or base exists)
    std::string backup;    // a second name of the old file while the commit runs (several moves)
    bool replace = false;
};

bool is_fd(int dirfd, const std::string& name, int fd) {
    struct stat a, b;
    return ::fstat(fd, &a) == 0 && ::fstatat(dirfd, name.c_str(), &b, AT_SYMLINK_NOFOLLOW) == 0 && a.st_dev == b.st_dev &&
           a.st_ino == b.st_ino;
}

bool link_fd(const Move& m, const std::string& name) {
    if (::linkat(AT_FDCWD, m.proc.c_str(), m.dirfd, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
    // No /proc: AT_EMPTY_PATH (needs CAP_DAC_READ_SEARCH).
    return errno == ENOENT && ::linkat(m.fd, "", m.dirfd, name.c_str(), AT_EMPTY_PATH) == 0;
}

// One temporary onto its target; the errno of a failure, or 0.
int move_one(const Move& m) {
    if (!m.named.empty()) return ::renameat(m.dirfd, m.named.c_str(), m.dirfd, m.base.c_str()) == 0 ? 0 : errno;
    if (!m.replace && link_fd(m, m.base)) return 0;
    if (!m.replace && errno != EEXIST) return errno;
    if (!link_fd(m, m.link_tmp)) return errno;
    if (::renameat(m.dirfd, m.link_tmp.c_str(), m.dirfd, m.base.c_str()) != 0) {
        const int err = errno;
        ::unlinkat(m.dirfd, m.link_tmp.c_str(), 0);
        return err;
    }
    return 0;
}

// Undoes moves[0..n): a target that holds our file gets its old file back from the backup name
// (one rename, so it is never missing), or is removed when there was none before. Worked out from
// the names alone, so it also serves after the child was killed midway. Returns false when a
// replaced old file had no backup (the file system refused the second name).
bool roll_back(const std::vector<Move>& moves, std::size_t n) {
    bool whole = true;
    for (std::size_t k = n; k-- > 0;) {
        const Move& m = moves[k];
        struct stat st;
        const bool backed = !m.backup.empty() && ::fstatat(m.dirfd, m.backup.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0;
        if (is_fd(m.dirfd, m.base, m.fd)) {
            if (backed) ::renameat(m.dirfd, m.backup.c_str(), m.dirfd, m.base.c_str());
            else if (!m.replace) ::unlinkat(m.dirfd, m.base.c_str(), 0);
            else whole = false;
        } else if (backed) {
            ::unlinkat(m.dirfd, m.backup.c_str(), 0);  // the old file never left its name
        }
        if (!m.link_tmp.empty() && is_fd(m.dirfd, m.link_tmp, m.fd)) ::unlinkat(m.dirfd, m.link_tmp.c_str(), 0);
    }
    return whole;
}

// Moves every temporary onto its target, in order, all or nothing: with several moves, each old
// file first gets a second name (a hard link), so a failure of a later move puts the earlier ones
// back. Returns the errno of the first failure (after the roll-back), or 0; *failed = its index.
int move_all(const std::vector<Move>& moves, std::size_t* failed) {
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const Move& m = moves[k];
        // No second name where the file system has none (EPERM, ENOTSUP, EMLINK): this old file
        // then cannot come back (docs/DECISIONS.md "Outputs").
        if (!m.backup.empty()) (void)::linkat(m.dirfd, m.base.c_str(), m.dirfd, m.backup.c_str(), 0);
        if (const int err = move_one(m)) {
            roll_back(moves, k + 1);
            *failed = k;
            return err;
        }
    }
    for (const Move& m : moves)
        if (!m.backup.empty()) ::unlinkat(m.dirfd, m.backup.c_str(), 0);
    return 0;
}

}  // namespace

namespace {

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

// Outputs::check, and with whole = false only its clashes (Outputs::clashes).
Status check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, bool whole) {
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
            Status s = resolve(out, &target);
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
        outs.add(id, i);
    }
    return Status::success();
}

}  // namespace

Status Outputs::check(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) const {
    return check_outputs(outputs, inputs, true);
}

Status Outputs::clashes(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
    return check_outputs(outputs, inputs, false);
}

Status Outputs::stage(const std::string& path, const std::string& bytes) {
    if (path.empty()) return Status::bad_input("empty output file name");
    Staged s;
    s.path = path;
    if (path == "-") {
        s.special = true;
        s.target = "-";
        s.bytes = bytes;
        staged_.push_back(std::move(s));
        return Status::success();
    }
    if (Status r = resolve(path, &s.target); !r) return r;
    struct stat st;
    s.existed = ::stat(s.target.c_str(), &st) == 0;
    if (s.existed && S_ISDIR(st.st_mode)) return Status::failure(escape_name(path) + ": is a directory");
    if (Status r = refuse_read_only(path, s.target); !r) return r;
    if (s.existed && !S_ISREG(st.st_mode)) {
        s.special = true;
        s.bytes = bytes;
        staged_.push_back(std::move(s));
        return Status::success();
    }
    std::string dir;
    split(s.target, &dir, &s.base);
    if (s.base.empty()) return Status::failure(escape_name(path) + ": not a file name");
    s.dirfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (s.dirfd < 0) return Status::failure(os_error(path, errno));
    // Ownership of the Staged from here on: a failure below is cleaned up by discard().
    staged_.push_back(std::move(s));
    Staged& t = staged_.back();
    auto give_up = [&](int err) {
        if (t.fd >= 0) ::close(t.fd);
        if (!t.tmp.empty()) ::unlinkat(t.dirfd, t.tmp.c_str(), 0);
        release_slot(&t.slot);
        ::close(t.dirfd);
        staged_.pop_back();
        return Status::failure(os_error(path, err));
    };
#ifdef O_TMPFILE
    // ERD_NO_TMPFILE=1 takes the named path as on a file system without O_TMPFILE (tests).
    const char* no_tmpfile = std::getenv("ERD_NO_TMPFILE");
    const bool forced = no_tmpfile && std::strcmp(no_tmpfile, "1") == 0;
    if (!forced) t.fd = ::openat(t.dirfd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    const bool unsupported = forced || (t.fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL));
#else
    const bool unsupported = true;
#endif
    if (t.fd < 0 && !unsupported) return give_up(errno);
    if (t.fd < 0) {
        // A named temporary, registered before it exists so a signal removes it.
        for (int attempt = 0; attempt < 100 && t.fd < 0; ++attempt) {
            t.tmp = temp_name();
            t.slot = claim_slot(t.dirfd, t.tmp);
            if (t.slot < 0) { errno = EMFILE; break; }
            t.fd = ::openat(t.dirfd, t.tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (t.fd < 0) {
                int err = errno;
                release_slot(&t.slot);
                errno = err;
                if (err != EEXIST) break;
            }
        }
        if (t.fd < 0) {
            const int err = errno == 0 ? EMFILE : errno;
            t.tmp.clear();
            return give_up(err);
        }
    }
    int err = 0;
    bool ok = write_all(t.fd, bytes, &err);
    // An old file keeps its permissions (and, for root, its owner).
    if (ok && t.existed && ::fchmod(t.fd, st.st_mode & 07777) != 0) { err = errno; ok = false; }
    if (ok && t.existed && ::geteuid() == 0) (void)::fchown(t.fd, st.st_uid, st.st_gid);
    if (ok && ::fsync(t.fd) != 0) { err = errno; ok = false; }
    if (!ok) return give_up(err);
    return Status::success();
}

void Outputs::discard() {
    for (Staged& s : staged_) {
        if (s.fd >= 0) ::close(s.fd);
        if (!s.tmp.empty()) ::unlinkat(s.dirfd, s.tmp.c_str(), 0);
        release_slot(&s.slot);
        if (s.dirfd >= 0) ::close(s.dirfd);
    }
    staged_.clear();
}

Outputs::~Outputs() { discard(); }

Status Outputs::commit() {
    // Special files first, in place: one that fails leaves every regular target untouched. Not
    // under blocked signals: opening a FIFO waits for its reader, and Ctrl-C must still work.
    for (Staged& s : staged_) {
        if (!s.special) continue;
        int fd = s.target == "-" ? 1 : ::open(s.target.c_str(), O_WRONLY | O_CLOEXEC);
        int err = fd < 0 ? errno : 0;
        bool ok = fd >= 0 && write_all(fd, s.bytes, &err);
        if (fd > 1 && ::close(fd) != 0 && ok) { err = errno; ok = false; }
        if (!ok) {
            const std::string name = s.target == "-" ? std::string("stdout") : s.path;
            discard();
            return Status::failure(os_error(name, err));
        }
    }
    // Then every temporary onto its target, in a child process with the handled signals held:
    // a SIGKILL of erd between a linkat and its rename (or between two renames) would leave a
    // name behind, but the child, which nothing but a KILL of the whole process group reaches,
    // finishes them. Without fork (no memory for one) the same runs here.
    std::vector<Move> moves;
    std::vector<std::size_t> staged_of;  // moves[k] is staged_[staged_of[k]]
    bool wrote_special = false;
    for (Staged& s : staged_) {
        wrote_special = wrote_special || s.special;
        if (s.special) continue;
        staged_of.push_back(std::size_t(&s - staged_.data()));
        Move m;
        m.dirfd = s.dirfd;
        m.fd = s.fd;
        m.base = s.base;
        m.named = s.tmp;
        if (s.tmp.empty()) {
            m.proc = "/proc/self/fd/" + std::to_string(s.fd);
            m.link_tmp = temp_name();
            s.slot = claim_slot(s.dirfd, m.link_tmp);
            s.tmp = m.link_tmp;  // removed by discard() unless committed
        }
        m.replace = s.existed;
        moves.push_back(std::move(m));
    }
    if (moves.size() > 1)
        for (Move& m : moves)
            if (m.replace) m.backup = temp_name();
    sigset_t held, old;
    sigemptyset(&held);
    for (int sig : kSignals) sigaddset(&held, sig);
    ::sigprocmask(SIG_BLOCK, &held, &old);
    int err = 0;
    std::size_t failed = 0;
    // Only a move through a name needs the child (a new file is linked in by one system call).
    bool through_name = false;
    for (const Move& m : moves) through_name = through_name || m.replace || !m.named.empty();
    int report[2] = {-1, -1};  // the child's failed index
    if (through_name && ::pipe(report) != 0) through_name = false;
    const pid_t pid = through_name ? ::fork() : -1;
    if (pid == 0) {
        const int e = move_all(moves, &failed);
        const std::uint32_t index = std::uint32_t(failed);
        if (e && ::write(report[1], &index, sizeof index) != ssize_t(sizeof index)) {
        }
        ::_exit(e);
    }
    if (report[1] >= 0) ::close(report[1]);
    if (pid < 0) {
        err = move_all(moves, &failed);
    } else {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        err = WIFEXITED(status) ? WEXITSTATUS(status) : EIO;
        std::uint32_t index = 0;
        if (err && ::read(report[0], &index, sizeof index) == ssize_t(sizeof index)) failed = index;
        if (!WIFEXITED(status)) roll_back(moves, moves.size());  // killed midway: back to the old files
        else if (err == 0)
            for (const Move& m : moves)
                if (!m.backup.empty()) ::unlinkat(m.dirfd, m.backup.c_str(), 0);
    }
    if (report[0] >= 0) ::close(report[0]);
    // Which targets are ours now: the ones whose inode is that of our temporary.
    std::string replaced;  // the targets that hold the new file after a failure
    for (Staged& s : staged_) {
        if (s.special) continue;
        struct stat mine, there;
        const bool moved = ::fstat(s.fd, &mine) == 0 && ::fstatat(s.dirfd, s.base.c_str(), &there, 0) == 0 &&
                           mine.st_dev == there.st_dev && mine.st_ino == there.st_ino;
        if (!moved) continue;  // discard() removes its temporary
        if (err) replaced += (replaced.empty() ? "" : ", ") + escape_name(s.path);
        // Committed: the temporary's name (if any) is the target's now, or gone.
        if (!s.tmp.empty() && ::fstatat(s.dirfd, s.tmp.c_str(), &there, AT_SYMLINK_NOFOLLOW) == 0 &&
            there.st_ino == mine.st_ino)
            ::unlinkat(s.dirfd, s.tmp.c_str(), 0);  // linked, the rename not done: cannot happen
        s.tmp.clear();
        release_slot(&s.slot);
        (void)::fsync(s.dirfd);  // the new name durable; nothing visible is lost if this fails
    }
    Status result = Status::success();
    if (err) {
        const std::string& path = failed < staged_of.size() ? staged_[staged_of[failed]].path : staged_.front().path;
        std::string what = replaced.empty() ? "; every file is as it was" : "; written nevertheless: " + replaced;
        if (wrote_special) what += " (devices, FIFOs and stdout were written already)";
        result = Status::failure(os_error(path, err) + what);
    }
    discard();
    ::sigprocmask(SIG_SETMASK, &old, nullptr);
    return result;
}

}  // namespace erd::cli
