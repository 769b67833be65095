// The subcommands of `erd`. Each takes (argc, argv) with argv[0] = its own name and returns
// the process exit status: 0 success, 1 runtime failure, 2 usage or input error,
// 3 target sampling density not achieved (thesis -x mode 0).
#pragma once

#include "algorithms/methods/options.h"
#include "cli/args.h"
#include "kernel/status.h"

namespace erd::cli {

struct CommandLine;

using CommandFn = int (*)(int argc, char** argv);

struct Command {
    const char* name;
    const char* summary;  // one line for `erd help`
    CommandFn run;
};

int cmd_info(int argc, char** argv);
int cmd_synth(int argc, char** argv);
int cmd_psnr(int argc, char** argv);
int cmd_edges(int argc, char** argv);
int cmd_generate(int argc, char** argv);
int cmd_reconstruct(int argc, char** argv);
int cmd_render(int argc, char** argv);
int cmd_export(int argc, char** argv);
int cmd_convert(int argc, char** argv);
int cmd_tiles(int argc, char** argv);

// generate's option table and its flags into *o (the first bad value sets *st): `erd tiles`
// takes the same method options.
const CommandLine& generate_command_line();
void parse_generate_options(const Args& a, GenerateOptions* o, int* exit_mode, Status* st);

// The thesis's seven programs (Appendix A.5), reached through argv[0] (issue: packaging).
int thesis_alias(const char* name, int argc, char** argv, bool* handled);

// The whole program without main's process setup: argv[0] picks a thesis alias, argv[1] the
// subcommand; returns the exit status (cli/main.cpp).
int run(int argc, char** argv);

}  // namespace erd::cli
