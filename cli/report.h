// How every subcommand talks to the user: errors as "erd SUB: message" on stderr with the exit
// status of the Status code, warnings and progress on stderr (silenced by -q/--quiet), data
// on stdout only. One Reporter per subcommand run; no global state.
#pragma once
#include <string>
#include <utility>

#include "kernel/status.h"

namespace erd::cli {

class Reporter {
public:
    // sub: the subcommand's name; usage_line: its usage, for usage errors.
    Reporter(std::string sub, std::string usage_line) : sub_(std::move(sub)), usage_(std::move(usage_line)) {}

    // -q/--quiet: drop warnings and progress (errors are always printed).
    void set_quiet(bool q) { quiet_ = q; }
    bool quiet() const { return quiet_; }
    // -v/--verbose: also print detail() lines (stage timings, the method's statistics).
    void set_verbose(bool v) { verbose_ = v; }
    bool verbose() const { return verbose_; }
    const std::string& name() const { return sub_; }

    // Prints "erd SUB: message" and returns st.exit_code() (0 prints nothing).
    int fail(const Status& st) const;
    // A usage error: "erd SUB: message" and the usage on one line ("usage: erd SUB ..."); returns 2.
    int usage(const std::string& message) const;
    // "erd SUB: warning: message" unless quiet; empty messages print nothing (may hold several lines).
    void warn(const std::string& message) const;
    // "erd SUB: message" unless quiet: progress, timings.
    void note(const std::string& message) const;
    // note() under -v/--verbose only (and never under -q).
    void detail(const std::string& message) const {
        if (verbose_) note(message);
    }

private:
    std::string sub_;
    std::string usage_;
    bool quiet_ = false;
    bool verbose_ = false;
};

// A file name as it may be printed: control characters, bytes that are not UTF-8 and the C1
// controls (U+0080..U+009F) shown as \n, \t, \xNN, a backslash as \\, so a crafted name can
// neither split a message into two lines nor drive the terminal; other text is kept as it is.
// Every message that names a file uses it; Reporter applies the same to whole messages (without
// doubling backslashes), so whatever it prints is one line per message.
std::string escape_name(const std::string& name);
// The same for a whole message (backslashes kept as they are): one printable line.
std::string escape_message(const std::string& message);
// How a failed system call on a file reads: "NAME: the system's message for errno err", the
// name escaped.
std::string os_error(const std::string& name, int err);

}  // namespace erd::cli
