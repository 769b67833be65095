// The format of an output file: from --format, else from the file name's extension.
#pragma once
#include <string>

#include "kernel/file_name.h"
#include "kernel/status.h"

namespace erd::cli {

// *format = `given` (the --format value) when not empty, else `a` or `b` as the extension of `out`
// says (".a", ".b"). Fails (Code::input, a message for the usage line) when neither tells, or
// `given` is neither a nor b.
Status output_format(const std::string& given, const std::string& out, const char* a, const char* b, std::string* format);

}  // namespace erd::cli
