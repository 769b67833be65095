// The version erd prints for --version (erd --version, erd SUB --version, erd help --version).
#pragma once

#ifndef ERD_VERSION
#define ERD_VERSION "0.1.0"
#endif

namespace erd::cli {

inline constexpr const char* kVersion = ERD_VERSION;

}  // namespace erd::cli
