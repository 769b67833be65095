// Status values: how every library call in erd reports failure.
//
// The library never throws, prints or exits. A call that can fail returns a Status; the caller
// (usually cli/) decides what to print. The codes double as the documented exit statuses of `erd`.
#pragma once
#include <string>
#include <utility>

namespace erd {

enum class Code : int {
    ok = 0,
    runtime = 1,   // the work itself failed (write error, internal limit)
    input = 2,     // bad usage or bad input data
    density = 3,   // target sampling density not achieved exactly (thesis -x mode 0)
};

struct Status {
    Code code = Code::ok;
    std::string message;  // one line, no trailing newline; empty when ok

    bool ok() const { return code == Code::ok; }
    explicit operator bool() const { return ok(); }
    int exit_code() const { return static_cast<int>(code); }

    static Status success() { return {}; }
    static Status error(Code c, std::string m) { return Status{c, std::move(m)}; }
    static Status bad_input(std::string m) { return error(Code::input, std::move(m)); }
    static Status failure(std::string m) { return error(Code::runtime, std::move(m)); }
};

}  // namespace erd
