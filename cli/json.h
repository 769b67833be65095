// The one JSON writer of the erd program: every JSON text it prints (erd generate --stats,
// erd info --json, erd psnr --json) is built here, so every string goes through the same
// escaping.
//
// Strings come from the outside world (file names are bytes, not text), so json_string() writes
// valid UTF-8 whatever it is given: each byte that is not part of a well-formed UTF-8 sequence
// (a stray continuation byte, 0xC0/0xC1/0xF5..0xFF, an overlong form, a surrogate, a code point
// above U+10FFFF, a sequence cut short) becomes U+FFFD, written "\ufffd". Control characters
// are escaped (\n, \t, ..., else \u00XX), as are '"' and '\'. docs/DECISIONS.md, "CLI and thesis
// aliases" (JSON).
#pragma once
#include <cstdint>
#include <string>

namespace erd::cli {

// A JSON string literal, quotes included (see above).
std::string json_string(const std::string& s);

// A JSON number: integers without an exponent, else the shortest "%.*g" that reads back to the
// same double; "null" for NaN or infinity (JSON has neither).
std::string json_number(double v);

// One JSON object on one line, keys in the order they are added: no spaces, as the tests and
// scripts that read it expect.
//
//     JsonObject o;
//     o.str("file", path).num("width", w);
//     std::string text = o.text();   // {"file":"...","width":512}
class JsonObject {
public:
    JsonObject& str(const char* key, const std::string& value) { return raw(key, json_string(value)); }
    JsonObject& num(const char* key, double value) { return raw(key, json_number(value)); }
    JsonObject& integer(const char* key, long long value) { return raw(key, std::to_string(value)); }
    JsonObject& boolean(const char* key, bool value) { return raw(key, value ? "true" : "false"); }
    JsonObject& null(const char* key) { return raw(key, "null"); }
    JsonObject& object(const char* key, const JsonObject& value) { return raw(key, value.text()); }
    // A value that is JSON text already (an array built by the caller).
    JsonObject& raw(const char* key, const std::string& json);

    std::string text() const { return body_ + "}"; }

private:
    std::string body_ = "{";
};

}  // namespace erd::cli
