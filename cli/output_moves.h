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

// Moves every temporary onto its target, in order (in a child process when any move goes through
// a name: a new file is linked in by one system call), all or nothing. Returns the errno of the
// first failure, with the moves before it undone, or 0; *failed = its index. The caller holds the
// handled signals (output_temporaries.h).
int commit_moves(const std::vector<Move>& moves, std::size_t* failed);

}  // namespace erd::cli
