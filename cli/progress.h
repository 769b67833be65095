// Progress on stderr for long work: "erd SUB: stage 42%" rewritten in place with '\r'.
//
// Shown only when stderr is a terminal (or --progress forces it) and never under -q; when forced
// onto a file, whole lines at each stage and each 10% instead of redraws. Nothing
// appears during the first second of a run, so quick commands stay silent; afterwards the line is
// redrawn at most every 0.1 s and when the percentage or the stage changes. finish() ends the line.
#pragma once
#include <chrono>
#include <string>

#include "algorithms/methods/progress.h"

namespace erd::cli {

class Progress {
public:
    // enabled: the caller's decision (see should_show).
    Progress(std::string sub, bool enabled);
    ~Progress() { finish(); }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // True when progress should be shown: --progress given, or stderr is a terminal; never quiet.
    static bool should_show(bool forced, bool quiet);

    // The hook for a method's options (algorithms/methods/progress.h); valid while *this lives.
    ProgressHook hook() { return ProgressHook{&Progress::callback, this}; }

    void update(const char* stage, double fraction);
    // Clears the progress line if one was drawn.
    void finish();

private:
    static void callback(void* ctx, const char* stage, double fraction);
    std::string sub_;
    bool enabled_;
    bool tty_;  // redraw one line in place; otherwise print a line per stage and per 10%
    bool drawn_ = false;
    std::string stage_;
    int percent_ = -1;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace erd::cli
