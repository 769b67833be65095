#include "cli/output_temporaries.h"

#include <unistd.h>

#include <atomic>
#include <cstring>

#include "cli/outputs.h"

namespace erd::cli {

namespace {

// The named temporaries that exist right now, for the signal handler: fixed buffers, so the
// handler touches no allocator. This is the one piece of process-wide state in erd; it exists
// because a signal handler can reach nothing else.
constexpr int kSlots = 32;
struct Slot {
    volatile sig_atomic_t used;
    int dirfd;
    char name[48];
};
Slot g_slots[kSlots];
const int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

extern "C" void remove_temporaries_and_die(int sig) {
    for (Slot& s : g_slots)
        if (s.used) ::unlinkat(s.dirfd, s.name, 0);
    ::signal(sig, SIG_DFL);
    ::raise(sig);  // delivered when the handler returns: the usual death by this signal
}

}  // namespace

void install_output_signal_handlers() {
    for (int sig : kSignals) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup stays
        struct sigaction sa {};
        sa.sa_handler = remove_temporaries_and_die;
        sigfillset(&sa.sa_mask);
        ::sigaction(sig, &sa, nullptr);
    }
    // A file-size limit (ulimit -f) then fails the write with EFBIG instead of killing us.
    ::signal(SIGXFSZ, SIG_IGN);
}

int claim_slot(int dirfd, const std::string& name) {
    if (name.size() >= sizeof g_slots[0].name) return -1;
    for (int k = 0; k < kSlots; ++k) {
        if (g_slots[k].used) continue;
        g_slots[k].dirfd = dirfd;
        std::memcpy(g_slots[k].name, name.c_str(), name.size() + 1);
        std::atomic_signal_fence(std::memory_order_seq_cst);
        g_slots[k].used = 1;
        return k;
    }
    return -1;
}

void release_slot(int* k) {
    if (*k >= 0) g_slots[*k].used = 0;
    *k = -1;
}

std::string temp_name() {
    static unsigned counter = 0;
    return ".erd-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
}

void add_handled_signals(sigset_t* set) {
    for (int sig : kSignals) sigaddset(set, sig);
}

}  // namespace erd::cli
