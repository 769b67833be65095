// The memory cap of `erd generate`: a job whose estimated peak (api/erd.h memory_estimate, the
// registry's measured factors) exceeds it is refused before it starts, with the estimate in the
// message, instead of running for minutes and then failing (or taking the machine's swap).
// The default cap is the memory this process could get now: MemAvailable of /proc/meminfo, or
// the cgroup's memory.max less its memory.current when that is smaller; --max-memory overrides.
#pragma once
#include <cstddef>
#include <string>

#include "kernel/status.h"

namespace erd::cli {

// Bytes available to this process now; 0 when unknown (no /proc).
std::size_t available_memory();

// "SIZE": a whole number of bytes with an optional binary suffix K, M, G or T ("512M"); 0 means
// no cap. Code::input naming the text and the range when it is anything else.
Status parse_memory_size(const std::string& text, std::size_t* bytes);

// Ok when `need` fits in the cap; else Code::runtime: "... needs about X MiB (estimated), more
// than the Y MiB available|allowed by --max-memory".
Status check_memory(std::size_t need, std::size_t cap, bool cap_given, const std::string& what);

}  // namespace erd::cli
