// TEMPORARY (issue 21 ablation): reading switches from the environment. Removed before merge.
#pragma once
#include <cstdlib>
namespace erd {
inline double abl(const char* name, double def) {
    const char* s = std::getenv(name);
    return s && *s ? std::atof(s) : def;
}
}  // namespace erd
