// "Did you mean": the nearest of a list of names to a mistyped one, shared by the unknown
// subcommand (cli/main.cpp) and the unknown --method (cli/cmd_generate.cpp).
#pragma once
#include <string>
#include <vector>

namespace erd::cli {

// The candidate within edit distance 3 of name that is nearest (the first of equals), or
// nullptr.
const char* nearest_name(const std::string& name, const std::vector<const char*>& candidates);

// " Did you mean 'X'?" for the nearest candidate, or "" when none is near.
std::string did_you_mean(const std::string& name, const std::vector<const char*>& candidates);

}  // namespace erd::cli
