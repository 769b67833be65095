// A progress hook the library can call without printing: a function pointer and its context,
// carried in a method's options struct. cli/progress.h supplies the function that draws it on a
// terminal. A null hook costs one branch per call.
#pragma once

namespace erd {

// stage: a short fixed name ("edges", "greedy insertion"); fraction: 0..1 of that stage's work.
using ProgressFn = void (*)(void* ctx, const char* stage, double fraction);

struct ProgressHook {
    ProgressFn fn = nullptr;
    void* ctx = nullptr;

    void operator()(const char* stage, double fraction) const {
        if (fn) fn(ctx, stage, fraction);
    }
    explicit operator bool() const { return fn != nullptr; }
};

}  // namespace erd
