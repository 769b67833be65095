// The outputs of one command, committed together at the end (docs/DECISIONS.md, "Outputs").
//
//     Outputs outs;
//     if (!(st = outs.check({out, tri}, {in}))) ...   // before the work: clashes refused
//     ... compute ...
//     if (!(st = outs.stage(out, bytes))) ...          // a temporary beside the target
//     if (!(st = outs.stage(tri, tri_bytes))) ...
//     if (!(st = outs.commit())) ...                   // every target replaced, or none
//
// A regular file (or a name that does not exist yet) is written to an unnamed temporary in the
// target's own folder (O_TMPFILE; a named ".erd-PID-N.tmp" where the file system lacks it) and
// fsync'ed; commit() links each into place (rename over an old file), so until then every old
// file is exactly as it was, and a failure anywhere before commit leaves them all untouched.
// Special files (devices, FIFOs, sockets) and "-" (stdout) cannot be replaced: they are written
// in place, first in commit(), and are never unlinked. A symbolic link is followed: its target
// is replaced in the target's folder and the link stays; a link to a special file (/dev/stdout,
// /dev/fd/N) is written in place; a link to nothing is refused. An old file we may not write
// (read-only for us) is refused although its folder would allow the rename.
//
// Signals (install_output_signal_handlers, below): INT, TERM, HUP, QUIT and PIPE remove any named temporary before the process dies
// (the handler only unlinks fixed buffers, async-signal-safe); SIGXFSZ is ignored so a file-size
// limit is an ordinary write error. An unnamed temporary cannot outlive the process, KILL
// included; replacing an old file links it under a short-lived name and renames that over the
// target (linkat cannot replace), with the signals above held. The only names ever created are
// the short ones above, so they fit NAME_MAX whatever the output name. ERD_NO_TMPFILE=1 in the
// environment takes the named path everywhere (for the tests of it).
//
// Killed (SIGKILL, which no handler sees) at any moment: before commit() nothing is changed and
// no name is left (the unnamed temporaries vanish with the process); from commit() on, the moves
// run in a child out of erd's process group (output_moves.h), which finishes them: every regular
// output is its old file or every one its complete new file. Only a kill of that child too (of
// every process) between two of its renames leaves some new and some old, each file whole, and
// the old files' second names. ERD_TEST_COMMIT_PAUSE_MS=N (tests only, 1..10000) pauses N ms
// before each move so that a test's kill can land inside the commit (tests/test_kill.cpp).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "kernel/status.h"

namespace erd::cli {

class Outputs {
public:
    Outputs() = default;
    Outputs(const Outputs&) = delete;
    Outputs& operator=(const Outputs&) = delete;
    ~Outputs();  // discards every temporary not committed

    // Refuses (Code::input) an output that is the same file as an input (device and inode, stdin
    // and stdout included; different spellings and hard links are the same file), two outputs
    // that are the same file, a second "-", an output that is a folder, a symbolic link to
    // nothing, a read-only file we could not write in place, or a name whose folder is missing or
    // not writable for us (all before any work; nothing is created). Devices may repeat (/dev/null as
    // two outputs) and may be inputs too; a FIFO or pipe may not (stdout a pipe and /dev/stdout).
    Status check(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) const;

    // Refuses (Code::runtime) an output whose file cannot be made: its folder missing, not a
    // folder, or not writable for us (check_output_folder, cli/output_names.h). check() does this
    // too; a batch asks it for every output of every file up front, before any work.
    static Status folders(const std::vector<std::string>& outputs);

    // The clashes of check() alone (an output that is an input, two outputs one file), for every
    // file of a batch up front; a bad output name (a folder, a dangling link) is left to its job.
    static Status clashes(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

    // Writes `bytes` for `path` ("-" = stdout): to a temporary beside a regular target, or kept
    // for commit() when the target is special. Failures (Code::runtime) name the path.
    Status stage(const std::string& path, const std::string& bytes);

    // The same for an output written as it is made (a raster larger than memory, by rows): `write`
    // gets the temporary's descriptor (read-write, at offset 0) and may seek in it. Needs a
    // regular file (or a new name): "-" and special files are refused. Its failure is returned
    // as it is, the temporary removed.
    Status stage_stream(const std::string& path, const std::function<Status(int fd)>& write);

    // Writes the special outputs in place, then moves every temporary onto its target. A failed
    // special output leaves every regular target untouched. Signals are held until it is done.
    Status commit();

    // Removes every temporary staged so far (also done by the destructor).
    void discard();

private:
    Status stage_file(const std::string& path, const std::string* bytes, const std::function<Status(int fd)>* write);
    struct Staged {
        std::string path;    // as given, for messages
        std::string target;  // the file to replace (symbolic links resolved)
        std::string bytes;   // special targets only: written at commit
        bool special = false;
        int fd = -1;          // the temporary, open
        int dirfd = -1;       // the target's folder
        std::string base;     // the target's name in it
        std::string tmp;      // the temporary's name when named (no O_TMPFILE), else empty
        int slot = -1;        // its entry in the signal handler's list
        bool existed = false; // an old file is replaced (else the new one is linked in)
    };
    std::vector<Staged> staged_;
};

// Installs the handlers described above (INT, TERM, HUP, QUIT, PIPE remove named temporaries;
// SIGXFSZ ignored); a signal the process ignores stays ignored (nohup). The erd program calls it
// first thing; a library user (the Python module, the tests) keeps its own signal handling.
void install_output_signal_handlers();

// Puts /dev/null on each of descriptors 0, 1, 2 that is closed (`erd ... >&- 2>&-`), so no file
// erd opens takes that number and receives what is printed to stdout or stderr (a message in the
// middle of an output model). It is opened write-only as stdin and read-only as stdout and
// stderr: using a closed stream still fails (EBADF, "stdout: Bad file descriptor"). erd calls it
// first thing.
void guard_standard_streams();

}  // namespace erd::cli
