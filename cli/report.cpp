#include "cli/report.h"

#include <cstdio>

namespace erd::cli {

int Reporter::fail(const Status& st) const {
    if (st.ok()) return 0;
    std::fprintf(stderr, "erd %s: %s\n", sub_.c_str(), st.message.c_str());
    return st.exit_code();
}

int Reporter::usage(const std::string& message) const {
    std::fprintf(stderr, "erd %s: %s\nusage: %s\n(erd %s --help for details)\n", sub_.c_str(), message.c_str(),
                 usage_.c_str(), sub_.c_str());
    return 2;
}

void Reporter::warn(const std::string& message) const {
    if (quiet_ || message.empty()) return;
    std::string::size_type i = 0;
    while (i < message.size()) {
        std::string::size_type j = message.find('\n', i);
        if (j == std::string::npos) j = message.size();
        std::fprintf(stderr, "erd %s: warning: %s\n", sub_.c_str(), message.substr(i, j - i).c_str());
        i = j + 1;
    }
}

void Reporter::note(const std::string& message) const {
    if (quiet_ || message.empty()) return;
    std::fprintf(stderr, "erd %s: %s\n", sub_.c_str(), message.c_str());
}

}  // namespace erd::cli
