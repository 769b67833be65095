#include "cli/report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

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

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += char(c);
                }
        }
    }
    return out + "\"";
}

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[40];
    if (v == std::floor(v) && std::fabs(v) < 1e15) {
        std::snprintf(buf, sizeof buf, "%.0f", v);  // integers without an exponent
        return buf;
    }
    // The shortest precision that reads back to the same double.
    for (int prec = 1; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace erd::cli
