#include "cli/args.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/report.h"
#include "cli/suggest.h"

namespace erd::cli {

namespace {

// The option named `name` exactly, else the one option whose long name starts with it (GNU
// getopt_long's rule: "--meth" is --method while no other option starts with "meth"). An
// unknown or ambiguous name is an error that names the candidates.
Status lookup_long(const std::vector<OptionSpec>& specs, const std::string& name, const OptionSpec** out) {
    std::vector<const OptionSpec*> starts;
    for (const auto& s : specs) {
        if (name == s.long_name) { *out = &s; return Status::success(); }
        if (!name.empty() && std::strncmp(s.long_name, name.c_str(), name.size()) == 0) starts.push_back(&s);
    }
    if (starts.size() == 1) { *out = starts[0]; return Status::success(); }
    if (starts.size() > 1) {
        std::string list;
        for (const OptionSpec* s : starts) list += std::string(list.empty() ? "" : ", ") + "--" + s->long_name;
        return Status::bad_input("option --" + name + " is ambiguous (" + list + ")");
    }
    std::vector<std::string> dashed;
    for (const auto& s : specs) dashed.push_back(std::string("--") + s.long_name);
    std::vector<const char*> names;
    for (const auto& d : dashed) names.push_back(d.c_str());
    const std::string guess = did_you_mean("--" + name, names);
    return Status::bad_input("unknown option --" + name + (guess.empty() ? "" : "." + guess));
}

const OptionSpec* lookup_short(const std::vector<OptionSpec>& specs, char c) {
    for (const auto& s : specs)
        if (s.short_name == c) return &s;
    return nullptr;
}

}  // namespace

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
        if (a[1] == '-') {
            std::string name = a.substr(2), value;
            std::size_t eq = name.find('=');
            const bool have_value = eq != std::string::npos;
            if (have_value) { value = name.substr(eq + 1); name.resize(eq); }
            const OptionSpec* spec = nullptr;
            if (Status st = lookup_long(specs, name, &spec); !st) return st;
            if (spec->value && !have_value) {
                if (i + 1 >= argc) return Status::bad_input(std::string("option --") + spec->long_name + " needs a value (" + spec->value + ")");
                value = argv[++i];
            } else if (!spec->value && have_value) {
                return Status::bad_input(std::string("option --") + spec->long_name + " takes no value");
            }
            given_.push_back({spec->long_name, value});
            continue;
        }
        // Short options, bundled as getopt does: "-qx2" is -q -x 2. Flags may follow each
        // other; the first option that takes a value takes the rest of the word (or the next
        // word), so a bundle has one reading only.
        for (std::size_t k = 1; k < a.size(); ++k) {
            const OptionSpec* spec = lookup_short(specs, a[k]);
            if (!spec) {
                std::string msg = std::string("unknown option -") + a[k];
                if (k > 1) msg += " (in " + a + ")";
                return Status::bad_input(msg);
            }
            if (!spec->value) {
                given_.push_back({spec->long_name, std::string()});
                continue;
            }
            std::string value = a.substr(k + 1);
            if (value.empty()) {
                if (i + 1 >= argc) return Status::bad_input(std::string("option --") + spec->long_name + " needs a value (" + spec->value + ")");
                value = argv[++i];
            }
            given_.push_back({spec->long_name, value});
            break;
        }
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

std::vector<std::string> Args::all(const char* long_name) const {
    std::vector<std::string> out;
    for (const auto& g : given_)
        if (g.name == long_name) out.push_back(g.value);
    return out;
}

// "[lo, hi]" for a message, reals in their shortest form.
static std::string range_text(double lo, double hi, bool lo_open = false) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%c%g, %g]", lo_open ? '(' : '[', lo, hi);
    return buf;
}

// Decimal text only: strtod and strtoll would also take leading blanks, and strtod hexadecimal
// ("0x10" as 16, "0x1p3" as 8), which no one means for a density or a PSNR.
static bool decimal_text(const std::string& s) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
    return s.find_first_of("xX") == std::string::npos;
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
    if (!decimal_text(g->value) || *end != '\0' || end == s) {
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
    if (!decimal_text(g->value) || *end != '\0' || end == s || std::isnan(v)) {
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
