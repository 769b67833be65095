#include "cli/report.h"

#include <cstdio>
#include <cstring>

namespace erd::cli {

namespace {

// The code point of the UTF-8 sequence at s[i] and its length, or 0 for an invalid sequence.
std::size_t utf8_at(const std::string& s, std::size_t i, unsigned* cp) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (len == 0 || i + len > s.size()) return 0;
    unsigned v = len == 1 ? c : c & (0x7fu >> len);
    for (std::size_t k = 1; k < len; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if ((d >> 6) != 2) return 0;
        v = v << 6 | (d & 0x3fu);
    }
    static const unsigned lowest[5] = {0, 0, 0x80, 0x800, 0x10000};  // overlong forms are invalid
    if (v < lowest[len] || v > 0x10ffff || (v >= 0xd800 && v <= 0xdfff)) return 0;
    *cp = v;
    return len;
}

std::string escaped(const std::string& s, bool backslash) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        unsigned cp = 0;
        const std::size_t len = utf8_at(s, i, &cp);
        if (len > 0 && cp >= 0x20 && cp != 0x7f && !(cp >= 0x80 && cp < 0xa0)) {
            if (backslash && cp == '\\') out += '\\';
            out.append(s, i, len);
            i += len;
            continue;
        }
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (c == '\r') out += "\\r";
        else {
            // A C1 control is two bytes in UTF-8: both shown.
            for (std::size_t k = 0; k < (len ? len : 1); ++k) {
                const unsigned char b = static_cast<unsigned char>(s[i + k]);
                out += "\\x";
                out += hex[b >> 4];
                out += hex[b & 15];
            }
        }
        i += len ? len : 1;
    }
    return out;
}

// The usage text as one line: a usage string wrapped over lines joined with single spaces.
std::string one_line(const std::string& s) {
    std::string out;
    bool space = false;
    for (char c : s) {
        if (c == '\n' || c == ' ' || c == '\t') {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += c;
    }
    return out;
}

}  // namespace

std::string escape_name(const std::string& name) { return escaped(name, true); }
std::string escape_message(const std::string& message) { return escaped(message, false); }
std::string os_error(const std::string& name, int err) { return escape_name(name) + ": " + std::strerror(err); }

int Reporter::fail(const Status& st) const {
    if (st.ok()) return 0;
    std::fprintf(stderr, "erd %s: %s\n", sub_.c_str(), escape_message(st.message).c_str());
    return st.exit_code();
}

int Reporter::usage(const std::string& message) const {
    std::fprintf(stderr, "erd %s: %s\nusage: %s\n", sub_.c_str(), escape_message(message).c_str(),
                 one_line(usage_).c_str());
    return 2;
}

void Reporter::warn(const std::string& message) const {
    if (quiet_ || message.empty()) return;
    std::string::size_type i = 0;
    while (i < message.size()) {
        std::string::size_type j = message.find('\n', i);
        if (j == std::string::npos) j = message.size();
        std::fprintf(stderr, "erd %s: warning: %s\n", sub_.c_str(), escape_message(message.substr(i, j - i)).c_str());
        i = j + 1;
    }
}

void Reporter::note(const std::string& message) const {
    if (quiet_ || message.empty()) return;
    std::fprintf(stderr, "erd %s: %s\n", sub_.c_str(), escape_message(message).c_str());
}

}  // namespace erd::cli
