// Moving the temporaries of Outputs::commit (outputs.h) onto their targets, all or nothing: in a
// child process when a move goes through a name, so that a SIGKILL of erd midway cannot leave a
// target without its file or a name behind.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace erd::cli {

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

// Moves every temporary onto its target, in order, all or nothing: in a child process in a
// process group of its own whenever there are several moves or one goes through a name (one new
// file is linked in by one system call), so that a SIGKILL of erd, or of erd's process group
// (`kill -9 %1`, timeout -s KILL), at any moment leaves every target old or every target new: the
// child finishes. Only a kill of the child itself (a kill of every process, the OOM killer
// choosing it) between two renames leaves some targets new and some old, each whole, and the old
// files' second names (.erd-PID-N.tmp) beside them (docs/DECISIONS.md "Outputs").
// Returns the errno of the first failure, with the moves before it undone, or 0; *failed = its
// index. The caller holds the handled signals (output_temporaries.h). pause_ms > 0 sleeps that
// long before each move (the tests' ERD_TEST_COMMIT_PAUSE_MS, outputs.h).
int commit_moves(const std::vector<Move>& moves, std::size_t* failed, long pause_ms = 0);

}  // namespace erd::cli
