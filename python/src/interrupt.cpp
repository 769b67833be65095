#include "python/src/interrupt.h"

namespace erd::py {

Interrupt::Interrupt() : last_(std::chrono::steady_clock::now()) {
    pybind11::module_ threading = pybind11::module_::import("threading");
    main_thread_ = threading.attr("current_thread")().is(threading.attr("main_thread")());
}

ProgressHook Interrupt::hook() {
    ProgressHook h;
    if (!main_thread_) return h;
    h.fn = &Interrupt::on_progress;
    h.cancel = &Interrupt::on_cancel;
    h.ctx = this;
    return h;
}

void Interrupt::on_progress(void* ctx, const char*, double) {
    auto* self = static_cast<Interrupt*>(ctx);
    if (self->hit_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - self->last_ < std::chrono::milliseconds(50)) return;
    self->last_ = now;
    pybind11::gil_scoped_acquire lock;
    if (PyErr_CheckSignals() != 0) {
        self->hit_ = true;
        self->error_ = std::make_unique<pybind11::error_already_set>();
    }
}

bool Interrupt::on_cancel(void* ctx) { return static_cast<Interrupt*>(ctx)->hit_; }

void Interrupt::rethrow() {
    if (error_) {
        pybind11::error_already_set e = *error_;
        error_.reset();
        throw e;
    }
    // A signal that arrived after the last check is raised here rather than later.
    if (main_thread_ && PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
}

}  // namespace erd::py
