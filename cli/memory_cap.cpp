#include "cli/memory_cap.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/report.h"

namespace erd::cli {

namespace {

// The number a small text file starts with (after blanks), or -1: no file, no number ("max"),
// or one out of range. C stdio, not iostreams: with no stream in the program, libstdc++'s locale
// machinery is not linked in (docs/DECISIONS.md "Memory", the process's own memory).
long long number_in(const char* path) {
    std::FILE* f = std::fopen(path, "r");
    if (!f) return -1;
    char buf[64];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[n] = '\0';
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(buf, &end, 10);
    return end == buf || errno != 0 ? -1 : v;
}

std::string mib(std::size_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f MiB", double(bytes) / (1024.0 * 1024.0));
    return buf;
}

}  // namespace

std::size_t available_memory() {
    std::size_t avail = 0;
    if (std::FILE* meminfo = std::fopen("/proc/meminfo", "r")) {
        char line[256];
        long long kb = 0;
        while (std::fgets(line, sizeof line, meminfo))
            if (std::sscanf(line, "MemAvailable: %lld kB", &kb) == 1) {
                if (kb > 0) avail = std::size_t(kb) * 1024;
                break;
            }
        std::fclose(meminfo);
    }
    // cgroup v2: "max" reads as no number (-1); a limit below what the machine has wins.
    const long long limit = number_in("/sys/fs/cgroup/memory.max");
    const long long used = number_in("/sys/fs/cgroup/memory.current");
    if (limit > 0 && used >= 0) {
        const std::size_t left = limit > used ? std::size_t(limit - used) : 0;
        if (avail == 0 || left < avail) avail = left;
    }
    return avail;
}

Status parse_memory_size(const std::string& text, std::size_t* bytes) {
    const std::string range = "a number of bytes with an optional K, M, G or T suffix, up to 1024T; 0 = no cap";
    std::size_t i = 0;
    unsigned long long v = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9' && v <= (1ull << 50)) v = v * 10 + unsigned(text[i++] - '0');
    unsigned shift = 0;
    if (i + 1 == text.size()) {
        switch (text[i] | 0x20) {
            case 'k': shift = 10; ++i; break;
            case 'm': shift = 20; ++i; break;
            case 'g': shift = 30; ++i; break;
            case 't': shift = 40; ++i; break;
            default: break;
        }
    }
    if (i == 0 || i != text.size() || text[0] < '0' || text[0] > '9')
        return Status::bad_input("--max-memory: '" + escape_name(text) + "' is not a size (" + range + ")");
    if (v > (1ull << 50) >> shift) return Status::bad_input("--max-memory: " + escape_name(text) + " is outside [0, 1024T]");
    *bytes = std::size_t(v << shift);
    return Status::success();
}

Status check_memory(std::size_t need, std::size_t cap, bool cap_given, const std::string& what) {
    if (cap == 0 || need <= cap) return Status::success();
    return Status::failure(what + " needs about " + mib(need) + " (estimated), more than the " + mib(cap) +
                           (cap_given ? " --max-memory allows" : " of memory available now (--max-memory SIZE overrides)"));
}

}  // namespace erd::cli
