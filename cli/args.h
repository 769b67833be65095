// A small command-line parser shared by every subcommand.
//
// Each subcommand declares its options in a static table; parse() checks argv against it and
// typed getters validate values, so every command rejects bad flags the same way (exit 2).
#pragma once
#include <string>
#include <vector>

#include "kernel/status.h"

namespace erd::cli {

struct OptionSpec {
    char short_name;        // 0 when the option has only a long form
    const char* long_name;  // without the leading "--"
    const char* value;      // name of the value ("N", "FILE"), or nullptr for a flag
    const char* help;
};

class Args {
public:
    // Parses argv[first..argc). "--" ends options. "-" alone is a positional (stdin/stdout).
    Status parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs);

    bool has(const char* long_name) const;
    std::string str(const char* long_name, const std::string& fallback = "") const;
    // Every value of a repeated option, in the order given (str() gives the last).
    std::vector<std::string> all(const char* long_name) const;
    // Typed getters: a value that does not parse completely, or lies outside [lo, hi], sets *st.
    long long integer(const char* long_name, long long fallback, long long lo, long long hi, Status* st) const;
    // With lo_open the range is (lo, hi]: lo itself is refused.
    double real(const char* long_name, double fallback, double lo, double hi, Status* st, bool lo_open = false) const;
    const std::vector<std::string>& positional() const { return positional_; }

private:
    struct Given { std::string name; std::string value; };
    const Given* find(const char* long_name) const;
    std::vector<Given> given_;
    std::vector<std::string> positional_;
};

// "Options:" block for help text, one line per option.
std::string describe(const std::vector<OptionSpec>& specs);

}  // namespace erd::cli
