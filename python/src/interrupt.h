// Long library calls without the interpreter lock, interruptible with Ctrl-C.
//
// The library reports progress through a ProgressHook (kernel/progress.h) and stops
// when the hook's cancel function says so. Python's own SIGINT handler only sets a flag that
// PyErr_CheckSignals turns into KeyboardInterrupt; that needs the lock, so the progress function
// takes it, at most every 50 ms and only on the main thread (the only one Python delivers signals
// to), and asks. The exception is kept and raised again once the call has returned and unwound.
#pragma once
#include <pybind11/pybind11.h>

#include <chrono>
#include <memory>

#include "kernel/progress.h"

namespace erd::py {

class Interrupt {
public:
    // Call with the lock held, before releasing it.
    Interrupt();
    // The hook to put in the options; a null hook off the main thread.
    ProgressHook hook();
    // Call with the lock held after the library call: raises the kept KeyboardInterrupt (or any
    // exception a signal handler raised), if one was caught.
    void rethrow();

private:
    static void on_progress(void* ctx, const char* stage, double fraction);
    static bool on_cancel(void* ctx);
    bool main_thread_ = false;
    bool hit_ = false;
    std::unique_ptr<pybind11::error_already_set> error_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace erd::py
