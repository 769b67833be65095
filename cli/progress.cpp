#include "cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace erd::cli {

Progress::Progress(std::string sub, bool enabled)
    : sub_(std::move(sub)), enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()), last_(start_) {}

bool Progress::should_show(bool forced, bool quiet) {
    if (quiet) return false;
    return forced || isatty(STDERR_FILENO) != 0;
}

void Progress::callback(void* ctx, const char* stage, double fraction) {
    static_cast<Progress*>(ctx)->update(stage, fraction);
}

void Progress::update(const char* stage, double fraction) {
    if (!enabled_ || !stage) return;
    auto now = std::chrono::steady_clock::now();
    if (now - start_ < std::chrono::seconds(1)) return;
    if (!std::isfinite(fraction)) fraction = 0;
    int pct = int(std::clamp(fraction, 0.0, 1.0) * 100);
    bool same_stage = stage_ == stage;
    if (tty_) {
        if ((same_stage && pct == percent_) || (drawn_ && same_stage && now - last_ < std::chrono::milliseconds(100))) return;
        std::fprintf(stderr, "\rerd %s: %s %3d%%\x1b[K", sub_.c_str(), stage, pct);
    } else {
        // A log file gets whole lines, one per stage and per tenth, without control characters.
        if (same_stage && pct / 10 == percent_ / 10) return;
        std::fprintf(stderr, "erd %s: %s %d%%\n", sub_.c_str(), stage, pct);
    }
    std::fflush(stderr);
    stage_ = stage;
    percent_ = pct;
    last_ = now;
    drawn_ = tty_;
}

void Progress::finish() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\x1b[K");
    std::fflush(stderr);
    drawn_ = false;
}

}  // namespace erd::cli
