// The named temporaries of Outputs (outputs.h) that exist right now, for the signal handler that
// removes them before the process dies (install_output_signal_handlers), and their names.
#pragma once
#include <signal.h>

#include <string>

namespace erd::cli {

// Registers a temporary name in folder dirfd before it is created, for the signal handler; the
// slot's number, or -1 when every slot is taken.
int claim_slot(int dirfd, const std::string& name);
// Forgets slot *k (the name is gone or committed) and sets *k to -1; -1 does nothing.
void release_slot(int* k);
// A fresh temporary name, ".erd-PID-N.tmp": short, so it fits NAME_MAX whatever the output name.
std::string temp_name();
// Adds the signals the handler catches to *set (commit holds them while it moves files).
void add_handled_signals(sigset_t* set);

}  // namespace erd::cli
