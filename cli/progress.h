// Progress on stderr for long work.
//
// On a terminal: one line redrawn in place, "erd SUB: stage [#######.....]  42%  about 12 s left",
// at most every 0.1 s and when the percentage or the stage changes. Not on a terminal (a log file,
// a pipe) and --progress given: plain lines, "erd SUB: stage 40% (about 12 s left)", one when a
// stage starts and one per tenth, percentages increasing within each stage. A stage the library
// runs again (ERD methods with hard edges run twice) is shown as "stage (pass 2)".
// Without --progress, only on a terminal and only after the first second, so quick commands stay
// silent; never under -q. finish() ends the line.
#pragma once
#include <chrono>
#include <map>
#include <string>

#include "cli/args.h"
#include "cli/report.h"
#include "kernel/progress.h"

namespace erd::cli {

class Progress {
public:
    // enabled: the caller's decision (see should_show); forced: --progress given (no first-second
    // silence).
    Progress(std::string sub, bool enabled, bool forced = false);
    ~Progress() { finish(); }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // True when progress should be shown: --progress given, or stderr is a terminal; never quiet.
    static bool should_show(bool forced, bool quiet);

    // The hook for a library call (kernel/progress.h); valid while *this lives.
    ProgressHook hook() { return ProgressHook{&Progress::callback, this}; }

    void update(const char* stage, double fraction);
    // Clears the progress line if one was drawn.
    void finish();

private:
    static void callback(void* ctx, const char* stage, double fraction);
    // " (about 12 s left)" from the stage's own pace; empty before 2% or the first second.
    std::string time_left(double fraction, std::chrono::steady_clock::time_point now) const;
    std::string sub_;
    bool enabled_, forced_;
    bool tty_;  // redraw one line in place; otherwise print a line per stage and per 10%
    bool drawn_ = false;
    std::string stage_;   // the library's stage name
    int pass_ = 1;        // how often that stage has started in this run
    std::map<std::string, int> starts_;
    double fraction_ = 0; // the stage's last fraction (a drop starts a new pass)
    int percent_ = -1;    // the percentage last shown
    std::chrono::steady_clock::time_point start_, last_, stage_start_;
};

// --progress, in the option table of every subcommand that can take long.
extern const OptionSpec kProgressOption;

// The progress of a subcommand run: shown as should_show() says for its --progress and -q.
inline Progress progress_for(const char* sub, const Args& args, const Reporter& rep) {
    return Progress(sub, Progress::should_show(args.has("progress"), rep.quiet()), args.has("progress"));
}

}  // namespace erd::cli
