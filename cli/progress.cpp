#include "cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace erd::cli {

const OptionSpec kProgressOption = {0, "progress", nullptr, "show progress (a bar on a terminal, lines with percentages elsewhere)"};

Progress::Progress(std::string sub, bool enabled, bool forced)
    : sub_(std::move(sub)), enabled_(enabled), forced_(forced), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_(start_), stage_start_(start_) {}

bool Progress::should_show(bool forced, bool quiet) {
    if (quiet) return false;
    return forced || isatty(STDERR_FILENO) != 0;
}

void Progress::callback(void* ctx, const char* stage, double fraction) {
    static_cast<Progress*>(ctx)->update(stage, fraction);
}

std::string Progress::time_left(double fraction, std::chrono::steady_clock::time_point now) const {
    const double spent = std::chrono::duration<double>(now - stage_start_).count();
    if (fraction < 0.02 || fraction >= 1.0 || spent < 1.0) return "";
    const double left = spent * (1.0 - fraction) / fraction;
    char buf[48];
    if (left < 90) std::snprintf(buf, sizeof buf, "about %.0f s left", std::max(1.0, left));
    else std::snprintf(buf, sizeof buf, "about %.0f min left", left / 60);
    return buf;
}

void Progress::update(const char* stage, double fraction) {
    if (!enabled_ || !stage) return;
    const auto now = std::chrono::steady_clock::now();
    if (!std::isfinite(fraction)) fraction = 0;
    fraction = std::clamp(fraction, 0.0, 1.0);
    // A new stage, or the same one started again (its fraction falls back).
    const bool new_stage = stage_ != stage;
    if (new_stage || fraction + 0.05 < fraction_) {
        pass_ = ++starts_[stage];
        stage_ = stage;
        stage_start_ = now;
        percent_ = -1;
    }
    fraction_ = fraction;
    if (!forced_ && now - start_ < std::chrono::seconds(1)) return;
    const int pct = int(fraction * 100);
    std::string name = stage_;
    if (pass_ > 1) name += " (pass " + std::to_string(pass_) + ")";
    const std::string left = time_left(fraction, now);
    if (tty_) {
        if (pct == percent_ || (percent_ >= 0 && now - last_ < std::chrono::milliseconds(100))) return;
        constexpr int kWidth = 24;
        const int full = int(fraction * kWidth);
        const std::string bar = std::string(std::size_t(full), '#') + std::string(std::size_t(kWidth - full), '.');
        std::fprintf(stderr, "\rerd %s: %s [%s] %3d%%%s%s\x1b[K", sub_.c_str(), name.c_str(), bar.c_str(), pct,
                     left.empty() ? "" : "  ", left.c_str());
    } else {
        // Whole lines without control characters: a stage's start and each tenth.
        if (percent_ >= 0 && pct / 10 <= percent_ / 10) return;
        std::fprintf(stderr, "erd %s: %s %d%%%s%s%s\n", sub_.c_str(), name.c_str(), pct, left.empty() ? "" : " (",
                     left.c_str(), left.empty() ? "" : ")");
    }
    std::fflush(stderr);
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
