#include "cli/command_line.h"

#include <cstdio>

#include "cli/version.h"

namespace erd::cli {

Invocation start_command(const CommandLine& cl, int argc, char** argv) {
    Invocation run{Args(), Reporter(cl.name, cl.usage)};
    std::vector<OptionSpec> specs = cl.options;
    specs.push_back({'q', "quiet", nullptr, cl.quiet});
    specs.push_back({'v', "verbose", nullptr, "also print stage timings and details on stderr"});
    specs.push_back({'h', "help", nullptr, "show this help"});
    specs.push_back({0, "version", nullptr, "print erd's version"});
    Status st = run.args.parse(argc, argv, 1, specs);
    if (!st) {
        run.status = run.rep.usage(st.message);
        return run;
    }
    if (run.args.has("help")) {
        const std::string more = cl.more_help ? cl.more_help() : std::string();
        std::printf("usage: %s\n\n%s\n\n%s%s", cl.usage, cl.about, describe(specs).c_str(), more.c_str());
        run.status = 0;
        return run;
    }
    if (run.args.has("version")) {
        std::printf("erd %s\n", kVersion);
        run.status = 0;
        return run;
    }
    run.rep.set_quiet(run.args.has("quiet"));
    run.rep.set_verbose(run.args.has("verbose"));
    const std::vector<std::string>& pos = run.args.positional();
    if (pos.size() < cl.min_positional || pos.size() > cl.max_positional) {
        const std::string message = cl.positional_error          ? std::string(cl.positional_error)
                                    : pos.size() > cl.max_positional ? "unexpected argument '" + pos[cl.max_positional] + "'"
                                                                     : std::string("missing arguments");
        run.status = run.rep.usage(message);
    }
    return run;
}

int run_command(const CommandLine& cl, int argc, char** argv, CommandBody body) {
    const Invocation run = start_command(cl, argc, argv);
    return run.done() ? run.status : body(run.args, run.rep);
}

}  // namespace erd::cli
