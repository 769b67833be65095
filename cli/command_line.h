// The start every subcommand shares: its option table, usage line and help text in one
// CommandLine, and start_command(), which parses argv against it, prints the help for -h/--help,
// prints the version for --version, reports a usage error (exit 2) for a bad option or a wrong
// number of positionals, and sets -q/--quiet and -v/--verbose on the Reporter. run_command()
// does that and hands the parsed options to the subcommand's body, which only reads them:
//
//     int cmd_info(int argc, char** argv) { return run_command(kInfo, argc, argv, run_info); }
#pragma once
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/report.h"

namespace erd::cli {

struct CommandLine {
    const char* name;   // the subcommand: messages read "erd NAME: ..."
    const char* usage;  // the usage line(s), printed after "usage: "
    const char* about;  // what the subcommand does, for --help (no trailing newline)
    std::vector<OptionSpec> options;  // the subcommand's own; -q, -v, -h and --version are added
    const char* quiet;  // what -q/--quiet leaves out, for --help ("no warnings")
    std::size_t min_positional = 0;
    std::size_t max_positional = 0;
    // The usage error for another number of positionals; without one (max_positional 0),
    // "unexpected argument 'X'".
    const char* positional_error = nullptr;
    std::string (*more_help)() = nullptr;  // appended to --help after the options (may be null)
};

// One run of a subcommand after start_command(): its parsed options and its Reporter.
struct Invocation {
    Args args;
    Reporter rep;
    int status = -1;  // the exit status when the run is over already (help printed, usage error)

    bool done() const { return status >= 0; }
};

// Parses argv[1..argc) (argv[0] is the subcommand's name) against cl.options plus -q, -v, -h
// and --version.
// Prints the help on stdout for -h/--help (status 0); a bad option or positional count is a
// usage error on stderr (status 2). Otherwise status stays -1 and the subcommand goes on.
Invocation start_command(const CommandLine& cl, int argc, char** argv);

// start_command(), then body(args, reporter) unless the run is over; returns the exit status.
using CommandBody = int (*)(const Args& args, const Reporter& rep);
int run_command(const CommandLine& cl, int argc, char** argv, CommandBody body);

}  // namespace erd::cli
