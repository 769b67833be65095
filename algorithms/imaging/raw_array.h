// Arrays in malloc'd memory for the edge detector's streaming store (canny_pass.h).
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>

namespace erd {

// What a failed allocation does, as `new` does in this build: throw std::bad_alloc, or abort where
// exceptions are off (the embedded build).
[[noreturn]] inline void out_of_memory() {
#if defined(__cpp_exceptions)
    throw std::bad_alloc();
#else
    std::abort();
#endif
}

// An array of trivially copyable T that resize() grows or shrinks keeping its first elements
// (realloc): a shrink is made in place, so the pass's store becomes its kept arrays without a
// second copy beside the first.
template <class T>
class RawArray {
public:
    RawArray() = default;
    ~RawArray() { std::free(p_); }
    RawArray(const RawArray&) = delete;
    RawArray& operator=(const RawArray&) = delete;
    RawArray(RawArray&& o) noexcept : p_(o.p_) { o.p_ = nullptr; }
    RawArray& operator=(RawArray&& o) noexcept {
        if (this != &o) {
            std::free(p_);
            p_ = o.p_;
            o.p_ = nullptr;
        }
        return *this;
    }
    T* data() { return p_; }
    const T* data() const { return p_; }
    T& operator[](std::size_t k) { return p_[k]; }
    void resize(std::size_t n) {
        if (n == 0) { reset(); return; }
        void* q = std::realloc(p_, n * sizeof(T));
        if (!q) out_of_memory();
        p_ = static_cast<T*>(q);
    }
    void reset() {
        std::free(p_);
        p_ = nullptr;
    }

private:
    T* p_ = nullptr;
};

}  // namespace erd
