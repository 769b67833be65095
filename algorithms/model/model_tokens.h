// The tokenizer of the model files (model_io.h): whitespace-separated tokens, '#' comments, line
// numbers for messages, and the number parsers every reader shares. Internal to model_io.cpp.
#pragma once
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "algorithms/imaging/image.h"
#include "algorithms/model/float_chars.h"
#include "kernel/status.h"

namespace erd {
namespace model_text {

// Values further from zero than this are refused: no approximating function of a 16-bit image
// needs them, and they keep every plane computation far from overflow.
constexpr double kMaxAbsValue = 1e9;
// Largest doubled coordinate of an accepted image.
constexpr std::int64_t kMaxDoubled = 2 * std::int64_t(kMaxImageSide) - 2;

inline std::string show(std::string_view tok) {
    std::string s;
    for (char ch : tok.substr(0, 24)) {
        const unsigned char u = static_cast<unsigned char>(ch);
        if (u >= 32 && u < 127) {
            s += ch;
        } else {
            static const char hex[] = "0123456789abcdef";
            s += "\\x";
            s += hex[u >> 4];
            s += hex[u & 15];
        }
    }
    if (tok.size() > 24) s += "...";
    return s;
}

// What a token should be, for messages: text, or a callable building it (only on error, so the
// hot path builds no strings).
inline std::string str(const char* s) { return s; }
template <class F>
std::string str(const F& f) {
    return f();
}

// Whitespace-separated tokens with '#' comments; tracks line numbers for messages.
class Tokens {
public:
    explicit Tokens(const std::string& text) : s_(text) {}

    // The next token, or false at the end of the text.
    bool next(std::string_view* tok) {
        skip();
        if (pos_ >= s_.size()) return false;
        line_ = cur_line_;
        const std::size_t b = pos_;
        while (pos_ < s_.size() && !space(s_[pos_]) && s_[pos_] != '#') ++pos_;
        *tok = std::string_view(s_).substr(b, pos_ - b);
        return true;
    }
    bool at_end() {
        skip();
        return pos_ >= s_.size();
    }
    // True when the next token is `word` (nothing is consumed).
    bool peek_is(std::string_view word) {
        skip();
        return s_.compare(pos_, word.size(), word.data(), word.size()) == 0 &&
               (pos_ + word.size() == s_.size() || space(s_[pos_ + word.size()]) || s_[pos_ + word.size()] == '#');
    }
    // The line of the next token, 0 at the end of the text (nothing is consumed).
    int next_line() {
        skip();
        return pos_ < s_.size() ? cur_line_ : 0;
    }
    std::size_t remaining() {
        skip();
        return s_.size() - pos_;
    }
    int line() const { return line_; }
    std::string where() const { return "line " + std::to_string(line_) + ": "; }
    // Values of any finite size (a real-valued model, whose values are in the data's units).
    void allow_any_finite() { max_abs_ = 1.7976931348623157e308; }

    // Plain decimal digits, at most max_len of them (the common case, parsed without from_chars).
    static bool digits(std::string_view t, std::size_t max_len, std::uint64_t* x) {
        if (t.empty() || t.size() > max_len) return false;
        std::uint64_t v = 0;
        for (char c : t) {
            if (c < '0' || c > '9') return false;
            v = v * 10 + std::uint64_t(c - '0');
        }
        *x = v;
        return true;
    }

    // Unsigned integer in [lo, hi].
    template <class What>
    Status uint(const What& what, std::uint64_t lo, std::uint64_t hi, std::uint64_t* v) {
        return integer(what, lo, hi, v);
    }

    // Signed integer (coordinates: a '-' gets "outside the image" rather than "junk").
    template <class What>
    Status sint(const What& what, std::int64_t lo, std::int64_t hi, std::int64_t* v) {
        return integer(what, lo, hi, v);
    }

    // A finite real of moderate size.
    template <class What>
    Status real(const What& what, double* v) {
        std::string_view t;
        if (!next(&t)) return Status::bad_input("file ends early: expected " + str(what));
        std::uint64_t u = 0;
        if (digits(t, 9, &u)) {  // below 1e9: exact, in range
            *v = double(u);
            return Status::success();
        }
        double x = 0.0;
        const char* b = t.data();
        if (!t.empty() && t[0] == '+') ++b;  // from_chars refuses a leading '+'
        const auto r = read_double(b, t.data() + t.size(), &x);
        if (t.empty() || r.ptr != t.data() + t.size() || r.ec == std::errc::invalid_argument)
            return Status::bad_input(where() + "expected " + str(what) + ", found '" + show(t) + "'");
        if (r.ec == std::errc::result_out_of_range || !std::isfinite(x))
            return Status::bad_input(where() + str(what) + " '" + show(t) + "' is not a finite number");
        if (std::fabs(x) > max_abs_)
            return Status::bad_input(where() + str(what) + " " + show(t) + " out of range (|value| <= 1e9)");
        *v = x;
        return Status::success();
    }

private:
    // uint and sint: plain digits in range take the fast path; anything else is read by
    // from_chars for the message. T signed means a coordinate (the range named "the image").
    template <class T, class What>
    Status integer(const What& what, T lo, T hi, T* v) {
        constexpr bool coordinate = std::is_signed_v<T>;
        std::string_view t;
        if (!next(&t)) return Status::bad_input("file ends early: expected " + str(what));
        std::uint64_t u = 0;
        if (digits(t, 18, &u) && T(u) >= lo && T(u) <= hi) {
            *v = T(u);
            return Status::success();
        }
        T x = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), x);
        if (t.empty() || t[0] == '+' || (!coordinate && t[0] == '-') || r.ptr != t.data() + t.size())
            return Status::bad_input(where() + "expected " + str(what) + ", found '" + show(t) + "'");
        if (r.ec == std::errc::result_out_of_range)
            return Status::bad_input(where() + str(what) + " " + show(t) +
                                     (coordinate ? " outside the image (0.." : " is too large (at most ") + std::to_string(hi) + ")");
        if (x < lo || x > hi)
            return Status::bad_input(where() + str(what) + " " + std::to_string(x) +
                                     (coordinate ? " outside the image (" : " out of range (") + std::to_string(lo) + ".." +
                                     std::to_string(hi) + ")");
        *v = x;
        return Status::success();
    }

    static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
    void skip() {
        while (pos_ < s_.size()) {
            const char c = s_[pos_];
            if (c == '\n') {
                ++cur_line_;
                ++pos_;
            } else if (space(c)) {
                ++pos_;
            } else if (c == '#') {
                while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
            } else {
                break;
            }
        }
    }
    const std::string& s_;
    std::size_t pos_ = 0;
    int cur_line_ = 1;
    int line_ = 1;
    double max_abs_ = kMaxAbsValue;
};

// A count of records of at least min_bytes bytes each (separator included) must fit in the rest
// of the text: refuses absurd counts before anything is allocated.
template <class What>
Status count(Tokens& tk, const What& what, std::uint64_t lo, std::uint64_t min_bytes, std::uint64_t* n) {
    if (Status s = tk.uint(what, lo, std::uint64_t(1) << 40, n); !s) return s;
    if (*n > 0 && *n * min_bytes > tk.remaining() + 1)
        return Status::bad_input(tk.where() + str(what) + " " + std::to_string(*n) +
                                 " is more than the rest of the file holds (the file ends early or the count is wrong)");
    return Status::success();
}

// The first line of a file of ours other than a model: its magic word and format version 1.
// `what` names the kind for a text that starts otherwise ("an erd polylines file").
inline Status expect_magic(Tokens& tk, const char* magic, const char* what) {
    if (tk.at_end()) return Status::bad_input("empty file");
    std::string_view t;
    tk.next(&t);
    if (t != magic)
        return Status::bad_input(tk.where() + "not " + what + " (expected '" + magic + " 1', found '" + show(t) + "')");
    std::uint64_t version = 0;
    return tk.uint("format version", 1, 1, &version);
}

// Nothing may follow the last record: "unexpected 'X' after the last WHAT (check the counts)".
inline Status expect_end(Tokens& tk, const char* what) {
    if (tk.at_end()) return Status::success();
    std::string_view t;
    tk.next(&t);
    return Status::bad_input(tk.where() + "unexpected '" + show(t) + "' after the last " + what + " (check the counts)");
}

// Room for at most 65536 records up front: a count that the rest of the file only "holds" as
// whitespace costs nothing until its records actually arrive (vectors grow as they are read).
template <class V>
void reserve_arriving(V* v, std::uint64_t n) {
    v->clear();
    v->reserve(std::size_t(std::min<std::uint64_t>(n, std::uint64_t(1) << 16)));
}

// The values of one record (a vertex line or a wedge line) in `channels` channels into out[0..].
// One channel: a single real, as leniently placed as the thesis's format allows. Several (a
// colour file, model_io.h): all on the line of the record's last token so far and nothing after
// them on it, so that a line with a wrong number of values is named as such instead of shifting
// every later record. `record` names the record ("vertex 7"), `word` its values ("value").
template <class Record>
Status channel_values(Tokens& tk, const Record& record, const char* word, int channels, double* out) {
    if (channels == 1) return tk.real([&] { return word + (" of " + str(record)); }, out);
    static const char* const names[3] = {"red", "green", "blue"};
    const int line = tk.line();
    const auto wrong = [&](const std::string& n) {
        return Status::bad_input("line " + std::to_string(line) + ": " + str(record) + " has " + n + " values on its line, expected " +
                                 std::to_string(channels) + " (the header says channels " + std::to_string(channels) + ")");
    };
    for (int c = 0; c < channels; ++c) {
        const auto what = [&] { return std::string(channels == 3 ? names[c] : "a") + " " + word + " of " + str(record); };
        const int at = tk.next_line();  // 0 at the end of the text: "file ends early" (cli/ framing relies on it)
        if (at != 0 && at != line) return wrong(std::to_string(c));
        if (Status s = tk.real(what, &out[c]); !s) return s;
    }
    if (tk.next_line() == line) return wrong("more than " + std::to_string(channels));
    return Status::success();
}

}  // namespace model_text
}  // namespace erd
