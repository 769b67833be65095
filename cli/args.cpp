#include "cli/args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/report.h"

namespace erd::cli {

static const OptionSpec* lookup_long(const std::vector<OptionSpec>& specs, const std::string& name) {
    for (const auto& s : specs)
        if (name == s.long_name) return &s;
    return nullptr;
}

static const OptionSpec* lookup_short(const std::vector<OptionSpec>& specs, char c) {
    for (const auto& s : specs)
        if (s.short_name == c) return &s;
    return nullptr;
}

Status Args::parse(int argc, char** argv, int first, const std::vector<OptionSpec>& specs) {
    given_.clear();
    positional_.clear();
    bool options_done = false;
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (options_done || a.size() < 2 || a[0] != '-' || (a[1] >= '0' && a[1] <= '9') || a[1] == '.') {
            positional_.push_back(a);
            continue;
        }
        if (a == "--") { options_done = true; continue; }
        const OptionSpec* spec = nullptr;
        std::string value;
        bool have_value = false;
        if (a[1] == '-') {
            std::string name = a.substr(2);
            std::size_t eq = name.find('=');
            if (eq != std::string::npos) { value = name.substr(eq + 1); name.resize(eq); have_value = true; }
            spec = lookup_long(specs, name);
            if (!spec) return Status::bad_input("unknown option --" + name);
        } else {
            spec = lookup_short(specs, a[1]);
            if (!spec) return Status::bad_input(std::string("unknown option -") + a[1]);
            if (a.size() > 2) {
                if (!spec->value) return Status::bad_input("option -" + std::string(1, a[1]) + " takes no value");
                value = a.substr(2);
                have_value = true;
            }
        }
        if (spec->value && !have_value) {
            if (i + 1 >= argc) return Status::bad_input(std::string("option --") + spec->long_name + " needs a value (" + spec->value + ")");
            value = argv[++i];
        } else if (!spec->value && have_value) {
            return Status::bad_input(std::string("option --") + spec->long_name + " takes no value");
        }
        given_.push_back({spec->long_name, value});
    }
    return Status::success();
}

const Args::Given* Args::find(const char* long_name) const {
    const Given* last = nullptr;  // the last occurrence wins, as in most Unix tools
    for (const auto& g : given_)
        if (g.name == long_name) last = &g;
    return last;
}

bool Args::has(const char* long_name) const { return find(long_name) != nullptr; }

std::string Args::str(const char* long_name, const std::string& fallback) const {
    const Given* g = find(long_name);
    return g ? g->value : fallback;
}

// "[lo, hi]" for a message, reals in their shortest form.
static std::string range_text(double lo, double hi, bool lo_open = false) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%c%g, %g]", lo_open ? '(' : '[', lo, hi);
    return buf;
}

// Every numeric option is checked against its range on the text, before any conversion can
// overflow: a value too large for the type is "outside the range", never a wrapped number.
long long Args::integer(const char* long_name, long long fallback, long long lo, long long hi, Status* st) const {
    const Given* g = find(long_name);
    if (!g) return fallback;
    const char* s = g->value.c_str();
    char* end = nullptr;
    errno = 0;
    long long v = std::strtoll(s, &end, 10);
    const std::string shown = escape_name(g->value);
    if (g->value.empty() || *end != '\0' || end == s) {
        if (st->ok()) *st = Status::bad_input("--" + g->name + ": '" + shown + "' is not an integer (allowed: [" +
                                              std::to_string(lo) + ", " + std::to_string(hi) + "])");
        return fallback;
    }
    if (errno == ERANGE || v < lo || v > hi) {
        if (st->ok())
            *st = Status::bad_input("--" + g->name + ": " + shown + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return fallback;
    }
    return v;
}

double Args::real(const char* long_name, double fallback, double lo, double hi, Status* st, bool lo_open) const {
    const Given* g = find(long_name);
    if (!g) return fallback;
    const char* s = g->value.c_str();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s, &end);
    const bool overflow = errno == ERANGE && std::isinf(v);  // underflow: a tiny value, checked below
    const std::string shown = escape_name(g->value);
    if (g->value.empty() || *end != '\0' || end == s || std::isnan(v)) {
        if (st->ok()) *st = Status::bad_input("--" + g->name + ": '" + shown + "' is not a number (allowed: " + range_text(lo, hi, lo_open) + ")");
        return fallback;
    }
    if (overflow || std::isinf(v) || v < lo || v > hi || (lo_open && v == lo)) {
        if (st->ok()) *st = Status::bad_input("--" + g->name + ": " + shown + " is outside " + range_text(lo, hi, lo_open));
        return fallback;
    }
    return v;
}

std::string describe(const std::vector<OptionSpec>& specs) {
    std::string out = "Options:\n";
    for (const auto& s : specs) {
        std::string left = "  ";
        left += s.short_name ? std::string("-") + s.short_name + ", " : std::string("    ");
        left += std::string("--") + s.long_name;
        if (s.value) left += std::string(" ") + s.value;
        if (left.size() < 28) left.resize(28, ' ');
        else left += "  ";
        out += left + s.help + "\n";
    }
    return out;
}

}  // namespace erd::cli
