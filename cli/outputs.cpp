#include "cli/outputs.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "cli/output_moves.h"
#include "cli/output_names.h"
#include "cli/output_temporaries.h"
#include "cli/report.h"

namespace erd::cli {

namespace {

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

}  // namespace

void guard_standard_streams() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        // The lowest free number: fd itself, since the ones below it are open by now.
        const int got = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
        if (got >= 0 && got != fd) ::close(got);
    }
}

Status Outputs::check(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) const {
    return check_output_names(outputs, inputs, true);
}

Status Outputs::clashes(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
    return check_output_names(outputs, inputs, false);
}

Status Outputs::folders(const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs)
        if (Status s = check_output_folder(out); !s) return s;
    return Status::success();
}

Status Outputs::stage(const std::string& path, const std::string& bytes) {
    return stage_file(path, &bytes, nullptr);
}

Status Outputs::stage_stream(const std::string& path, const std::function<Status(int fd)>& write) {
    return stage_file(path, nullptr, &write);
}

Status Outputs::stage_file(const std::string& path, const std::string* bytes_given, const std::function<Status(int fd)>* write) {
    static const std::string kNone;
    const std::string& bytes = bytes_given ? *bytes_given : kNone;
    if (path.empty()) return Status::bad_input("empty output file name");
    if (write && path == "-") return Status::bad_input("-: this output is written as it is made and needs a file, not stdout");
    Staged s;
    s.path = path;
    if (path == "-") {
        s.special = true;
        s.target = "-";
        s.bytes = bytes;
        staged_.push_back(std::move(s));
        return Status::success();
    }
    if (Status r = resolve_output(path, &s.target); !r) return r;
    struct stat st;
    s.existed = ::stat(s.target.c_str(), &st) == 0;
    if (s.existed && S_ISDIR(st.st_mode)) return Status::failure(escape_name(path) + ": is a directory");
    if (Status r = refuse_read_only(path, s.target); !r) return r;
    if (s.existed && !S_ISREG(st.st_mode)) {
        if (write) return Status::bad_input(escape_name(path) + ": this output is written as it is made and needs a regular file");
        s.special = true;
        s.bytes = bytes;
        staged_.push_back(std::move(s));
        return Status::success();
    }
    std::string dir;
    split_path(s.target, &dir, &s.base);
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
    if (!forced) t.fd = ::openat(t.dirfd, ".", O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
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
            t.fd = ::openat(t.dirfd, t.tmp.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
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
    bool ok = true;
    if (write) {
        // The caller writes (and may seek in) the temporary; its message is kept as it is.
        const Status w = (*write)(t.fd);
        if (!w) {
            give_up(0);
            return w;
        }
    } else {
        ok = write_all(t.fd, bytes, &err);
    }
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
    add_handled_signals(&held);
    ::sigprocmask(SIG_BLOCK, &held, &old);
    std::size_t failed = 0;
    // ERD_TEST_COMMIT_PAUSE_MS: the tests' hook that stretches the commit (a pause before each
    // move) so that a kill lands inside it (tests/test_kill.cpp); unset, no pause.
    const char* pause = std::getenv("ERD_TEST_COMMIT_PAUSE_MS");
    const long pause_ms = pause ? std::strtol(pause, nullptr, 10) : 0;
    const int err = commit_moves(moves, &failed, pause_ms > 0 && pause_ms <= 10000 ? pause_ms : 0);
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