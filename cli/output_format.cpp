#include "cli/output_format.h"

namespace erd::cli {

Status output_format(const std::string& given, const std::string& out, const char* a, const char* b, std::string* format) {
    *format = given;
    const std::string sa(a), sb(b);
    if (format->empty()) {
        if (has_extension(out, ("." + sa).c_str())) *format = sa;
        else if (has_extension(out, ("." + sb).c_str())) *format = sb;
        else
            return Status::bad_input("cannot tell the format from '" + out + "': name it ." + sa + " or ." + sb +
                                     ", or give --format");
    }
    if (*format != sa && *format != sb) return Status::bad_input("--format must be " + sa + " or " + sb + ", not '" + *format + "'");
    return Status::success();
}

}  // namespace erd::cli
