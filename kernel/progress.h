// A progress hook the library can call without printing: a function pointer and its context,
// carried in an options struct or passed to a long call (methods, reconstruct, render, export,
// edges). cli/progress.h supplies the function that draws it on a
// terminal; the Python binding (python/src) supplies one that notices Ctrl-C. A null hook costs
// one branch per call.
#pragma once

namespace erd {

// stage: a short fixed name ("edges", "greedy insertion"); fraction: 0..1 of that stage's work.
using ProgressFn = void (*)(void* ctx, const char* stage, double fraction);
// Asked right after each progress call: true makes the method stop at that point and return
// Status::failure(kCancelled). Lets a caller without signals of its own (a Python extension
// holding no interpreter lock) interrupt a long call.
using CancelFn = bool (*)(void* ctx);

constexpr const char* kCancelled = "cancelled";

struct ProgressHook {
    ProgressFn fn = nullptr;
    void* ctx = nullptr;
    CancelFn cancel = nullptr;

    void operator()(const char* stage, double fraction) const {
        if (fn) fn(ctx, stage, fraction);
    }
    // Reports the stage, then whether the caller asked to stop.
    bool report_cancelled(const char* stage, double fraction) const {
        (*this)(stage, fraction);
        return cancel && cancel(ctx);
    }
    explicit operator bool() const { return fn != nullptr || cancel != nullptr; }
};

}  // namespace erd
