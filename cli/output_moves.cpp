#include "cli/output_moves.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <cstdint>

namespace erd::cli {

namespace {

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
int move_all(const std::vector<Move>& moves, std::size_t* failed, long pause_ms) {
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const Move& m = moves[k];
        if (pause_ms > 0) {
            struct timespec t = {pause_ms / 1000, (pause_ms % 1000) * 1000000L};
            while (::nanosleep(&t, &t) != 0 && errno == EINTR) {
            }
        }
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

int commit_moves(const std::vector<Move>& moves, std::size_t* failed, long pause_ms) {
    int err = 0;
    // One new file is linked in by one system call; anything more needs the child.
    bool child = moves.size() > 1;
    for (const Move& m : moves) child = child || m.replace || !m.named.empty();
    int report[2] = {-1, -1};  // the child's failed index
    if (child && ::pipe(report) != 0) child = false;
    const pid_t pid = child ? ::fork() : -1;
    if (pid == 0) {
        // Out of erd's process group, so a kill of the group does not reach it either (both
        // sides call setpgid: whichever runs first, the child is out before its first move).
        ::setpgid(0, 0);
        const int e = move_all(moves, failed, pause_ms);
        const std::uint32_t index = std::uint32_t(*failed);
        if (e && ::write(report[1], &index, sizeof index) != ssize_t(sizeof index)) {
        }
        ::_exit(e);
    }
    if (pid > 0) ::setpgid(pid, pid);
    if (report[1] >= 0) ::close(report[1]);
    if (pid < 0) {
        err = move_all(moves, failed, pause_ms);
    } else {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        err = WIFEXITED(status) ? WEXITSTATUS(status) : EIO;
        std::uint32_t index = 0;
        if (err && ::read(report[0], &index, sizeof index) == ssize_t(sizeof index)) *failed = index;
        if (!WIFEXITED(status)) roll_back(moves, moves.size());  // killed midway: back to the old files
        else if (err == 0)
            for (const Move& m : moves)
                if (!m.backup.empty()) ::unlinkat(m.dirfd, m.backup.c_str(), 0);
    }
    if (report[0] >= 0) ::close(report[0]);
    return err;
}

}  // namespace erd::cli
