// A second thread for a loop of many small parallel steps: the greedy insertion re-scans a few
// faces after each of thousands of insertions, a few microseconds of work a step, where starting a
// thread per step (row_parallel.h's run_parts: tens of microseconds) would cost more than the step.
//
// The helper thread lives as long as the StepHelper (one loop: started by its constructor, joined
// by its destructor, so nothing outside the call that owns it). Between steps it waits by spinning
// for a while, then on a condition variable; a step posted while it spins starts within a fraction
// of a microsecond. On a machine with more runnable threads than processors the two halves wait
// for each other's time slices instead: the caller's wait for the helper's half, next to its own
// half's time, says which (see kWindow), and run() then keeps the steps on the calling thread for
// a while. Compiled with ERD_NO_THREADS, or when not enabled, run() calls both halves on the
// calling thread, one after the other. Callers whose halves write their own results get the same
// results either way.
#pragma once
#include <cstdint>
#ifndef ERD_NO_THREADS
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#endif

namespace erd {

#ifndef ERD_NO_THREADS
// A spin-wait's pause (x86's PAUSE hint; nothing on other processors).
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// About 20-60 microseconds of pause instructions: longer than a caller's work between two steps,
// short enough not to hold a core another thread needs for long.
constexpr int kSpinsBeforeYield = 2000;

// Waits until done() is true: spinning while the other thread is likely running, then yielding,
// since past that it may be waiting for a core (more runnable threads than processors).
template <class Done>
void spin_until(Done done) {
    for (int i = 0; !done(); ++i) {
        if (i < kSpinsBeforeYield) spin_pause();
        else std::this_thread::yield();
    }
}
#endif

class StepHelper {
public:
    explicit StepHelper(bool enabled) {
#ifndef ERD_NO_THREADS
        if (enabled) thread_ = std::thread([this] { serve(); });
#else
        (void)enabled;
#endif
    }
    ~StepHelper() {
#ifndef ERD_NO_THREADS
        if (!thread_.joinable()) return;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_.store(true);
        }
        wake_.notify_one();
        thread_.join();
#endif
    }
    StepHelper(const StepHelper&) = delete;
    StepHelper& operator=(const StepHelper&) = delete;

    bool threaded() const {
#ifndef ERD_NO_THREADS
        return thread_.joinable();
#else
        return false;
#endif
    }

    // The steps run() handed a half of to the helper.
    std::uint32_t two_thread_steps() const { return two_steps_; }

    // Calls fn(0) on the calling thread and fn(1) on the helper; returns when both have returned.
    // What the caller wrote before run() is visible to fn(1), and what fn(1) wrote is visible
    // after run(). Without the helper, fn(0) then fn(1) on the calling thread.
    template <class Fn>
    void run(Fn& fn) {
#ifndef ERD_NO_THREADS
        if (thread_.joinable() && off_ == 0) {
            hand_over(fn);
            return;
        }
        if (off_ > 0) --off_;
#endif
        fn(0);
        fn(1);
    }

private:
    std::uint32_t two_steps_ = 0;
#ifndef ERD_NO_THREADS
    template <class Fn>
    void hand_over(Fn& fn) {
        job_ = &fn;
        call_ = [](void* f) { (*static_cast<Fn*>(f))(1); };
        const std::uint32_t step = posted_.fetch_add(1) + 1;
        if (sleeping_.load()) {
            std::lock_guard<std::mutex> lock(mutex_);  // the helper is in wait() or about to check
        }
        wake_.notify_one();
        const Clock::time_point t0 = Clock::now();
        fn(0);
        const Clock::time_point t1 = Clock::now();
        spin_until([&] { return done_.load(std::memory_order_acquire) == step; });
        ++two_steps_;
        own_ += t1 - t0;
        waited_ += Clock::now() - t1;
        if (step % kWindow == 0) {
            if (waited_ > own_) off_ = kOff;
            own_ = waited_ = Clock::duration::zero();
        }
    }

    void serve() {
        std::uint32_t seen = 0;
        for (;;) {
            // Spin for the next step a while, then sleep until one is posted.
            for (int i = 0; posted_.load() == seen && !stop_.load(); ++i) {
                if (i < kSpinsBeforeYield) {
                    spin_pause();
                    continue;
                }
                std::unique_lock<std::mutex> lock(mutex_);
                sleeping_.store(true);
                wake_.wait(lock, [&] { return posted_.load() != seen || stop_.load(); });
                sleeping_.store(false);
            }
            if (stop_.load()) return;
            seen = posted_.load();
            call_(job_);
            done_.store(seen, std::memory_order_release);
        }
    }

    // Over each kWindow steps on two threads, the time the caller waited for the helper's half
    // after its own, and its own halves' time. On a quiet 2-core machine the wait is ~0.1 of its
    // own (0.25 in the first window, the helper's start); with another process busy on both cores
    // 1.6-2.0 (the helper's half waits for a time slice), and two threads take 1.6x one's time.
    // A wait above the caller's own time keeps the next kOff steps on the calling thread.
    using Clock = std::chrono::steady_clock;
    static constexpr std::uint32_t kWindow = 512, kOff = 8192;
    Clock::duration own_{}, waited_{};
    std::uint32_t off_ = 0;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::atomic<std::uint32_t> posted_{0}, done_{0};
    std::atomic<bool> sleeping_{false}, stop_{false};
    void* job_ = nullptr;                // the step's function object, set before posted_ moves
    void (*call_)(void*) = nullptr;      // calls it with 1
#endif
};

}  // namespace erd
