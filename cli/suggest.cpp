#include "cli/suggest.h"

#include <algorithm>

namespace erd::cli {

namespace {

// Levenshtein distance.
int distance(const std::string& a, const std::string& b) {
    std::string::size_type n = b.size();
    std::basic_string<int> row(n + 1, 0);
    for (std::string::size_type j = 0; j <= n; ++j) row[j] = int(j);
    for (char ca : a) {
        int diag = row[0];
        row[0] += 1;
        for (std::string::size_type j = 1; j <= n; ++j) {
            int up = row[j];
            row[j] = std::min(std::min(row[j] + 1, row[j - 1] + 1), diag + (ca == b[j - 1] ? 0 : 1));
            diag = up;
        }
    }
    return row[n];
}

}  // namespace

const char* nearest_name(const std::string& name, const std::vector<const char*>& candidates) {
    // A beginning of exactly one name ("gen", "recon") means that name, however far it is.
    const char* prefix_of = nullptr;
    int prefixes = 0;
    for (const char* c : candidates)
        if (!name.empty() && std::string(c).compare(0, name.size(), name) == 0) prefix_of = c, ++prefixes;
    if (prefixes == 1) return prefix_of;
    int best = 1 << 30;
    const char* guess = nullptr;
    for (const char* c : candidates) {
        int d = distance(name, c);
        if (d < best) { best = d; guess = c; }
    }
    return guess && best <= 3 ? guess : nullptr;
}

std::string did_you_mean(const std::string& name, const std::vector<const char*>& candidates) {
    const char* guess = nearest_name(name, candidates);
    return guess ? std::string(" Did you mean '") + guess + "'?" : std::string();
}

}  // namespace erd::cli
