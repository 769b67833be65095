// The thesis's seven programs (Appendix A.5) as names of the one `erd` binary: main() passes the
// basename of argv[0] here first. The four mesh generators are read from the method registry
// (algorithms/methods/methods.h: program name and flag letters); the other three are listed here.
//
// Each program checks its arguments against exactly the thesis's flag list (single letters, each
// with a value; no long forms, no positionals), then hands a translated argv to the erd
// subcommand that does the same job, so `ywb -i a.pgm -d 3 -o a.model` and
// `erd generate --method ed -i a.pgm -d 3 -o a.model` run the same code and write the same bytes:
//
//   ywb        generate --method ed      -i -d -n -o -t -p -x
//   gpi        generate --method gpi     -i -d -n -o -t -p -x
//   erd_ed     generate --method erded   the above and -l -b -r -e -f -w -s -B -S
//   erd_gpi    generate --method erdgpi  the above and -l -b -r -e -w -s -S
//   imgsyn     reconstruct - -o - --no-aa --plain   (.model on stdin, plain PGM on stdout)
//   imgsyn_aa  reconstruct - -o - --plain           (.erd on stdin, 4x4 supersampled, plain PGM)
//   Cal_PSNR   psnr ORIGINAL RECONSTRUCTED
//
// The thesis's flag texts say "if the value is 1 ... otherwise ..." for -f and -w and "0 simple,
// otherwise non-simple" for -S, so any other integer is mapped onto the erd subcommand's 0/1.
// When -d is given -n is dropped (the thesis: "$num is ignored"). Stage timings are silenced
// (-q); without -i the image comes from standard input, without -o the model goes to standard
// output. Error lines are those of the erd subcommand ("erd generate: FILE: problem"), except
// usage errors against the thesis's flag lists, which name the program ("ywb: unknown option -l").
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "algorithms/methods/methods.h"
#include "cli/commands.h"
#include "cli/report.h"

namespace erd::cli {

namespace {

enum class Kind { generate, reconstruct_point, reconstruct_aa, psnr };

struct Program {
    const char* name;
    Kind kind;
    const char* method;  // generate only
    const char* flags;   // the thesis's option letters, each taking a value
    std::string usage;   // after the name (and for generate, after kMeshUsage)
};

constexpr const char* kMeshUsage = " [-i inputFile] [-d sampleDensity] [-n num] [-o outputFile] [-t triangulationFile]"
                                   " [-p polylineFile] [-x exitMode]";

// The thesis's names of the values of the ERD flags, for the usage line.
std::string flag_usage(char f) {
    switch (f) {
    case 'l': return " [-l minLength]";
    case 'b': return " [-b beta]";
    case 'r': return " [-r ratio]";
    case 'e': return " [-e tolerance]";
    case 'f': return " [-f controlFlag]";
    case 'w': return " [-w dFlag]";
    case 's': return " [-s ksize]";
    case 'B': return " [-B startUp]";
    case 'S': return " [-S isSimple]";
    }
    return "";  // the common flags are in kMeshUsage
}

// The program of a registered method (methods.h: thesis program name and flags).
Program mesh_program(const MethodInfo& m) {
    Program p{m.thesis_program, Kind::generate, m.name, m.thesis_flags, ""};
    for (const char* f = m.thesis_flags; *f; ++f) p.usage += flag_usage(*f);
    return p;
}

const Program kOtherPrograms[] = {
    {"imgsyn", Kind::reconstruct_point, nullptr, "", " < model > image.pnm"},
    {"imgsyn_aa", Kind::reconstruct_aa, nullptr, "", " < model.erd > image.pnm"},
    {"Cal_PSNR", Kind::psnr, nullptr, "", " original_image reconstructed_image"},
};

int usage(const Program& p, const std::string& message) {
    if (!message.empty()) std::fprintf(stderr, "%s: %s\n", p.name, escape_message(message).c_str());
    std::fprintf(stderr, "usage: %s%s%s\n", p.name, p.kind == Kind::generate ? kMeshUsage : "", p.usage.c_str());
    return 2;
}

// Parses one "-f"/"-w"/"-S" value as an integer; the thesis only distinguishes one value.
bool parse_int(const std::string& s, long* out) {
    if (s.empty()) return false;
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0') return false;
    *out = v;
    return true;
}

// Runs an erd subcommand on an argv built from strings.
int run(CommandFn fn, std::vector<std::string> args) {
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (auto& a : args) argv.push_back(&a[0]);
    argv.push_back(nullptr);
    return fn(int(args.size()), argv.data());
}

// Parses the thesis's "-X value" / "-Xvalue" flags (getopt style, the last of a repeated flag
// wins) into values[letter]; anything else is a usage error.
int parse_flags(const Program& p, int argc, char** argv, std::string (&values)[128], bool (&given)[128]) {
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        unsigned char c = static_cast<unsigned char>(a[1]);
        if (a[0] != '-' || c == 0 || c >= 128 || !std::strchr(p.flags, c)) {
            if (a[0] == '-' && a[1] != '\0') return usage(p, std::string("unknown option ") + a);
            return usage(p, std::string("unexpected argument '") + a + "'");
        }
        if (a[2] != '\0') {
            values[c] = a + 2;
        } else {
            if (i + 1 >= argc) return usage(p, std::string("option -") + char(c) + " needs a value");
            values[c] = argv[++i];
        }
        given[c] = true;
    }
    return 0;
}

int run_generate(const Program& p, int argc, char** argv) {
    std::string values[128];
    bool given[128] = {};
    if (int rc = parse_flags(p, argc, argv, values, given)) return rc;

    // -q: the thesis's programs print the -x lines and errors only, no stage timings. Without -i
    // or -o they read standard input or write standard output (erd generate needs both named).
    std::vector<std::string> out = {"generate", "--method", p.method, "-q"};
    // erd_ed and erd_gpi are the thesis's method, not erd's improved defaults (wedge refit, line
    // search range, ERDED edge radius): --thesis sets the thesis's values.
    const MethodInfo* m = find_method(p.method);
    if (m && m->model == ModelKind::erd) out.push_back("--thesis");
    if (!given[int('i')]) out.insert(out.end(), {"-i", "-"});
    if (!given[int('o')]) out.insert(out.end(), {"-o", "-"});
    for (const char* f = p.flags; *f; ++f) {
        const unsigned char c = static_cast<unsigned char>(*f);
        const std::string letter(1, *f);
        if (!given[c]) continue;
        std::string value = values[c];
        if (*f == 'n' && given[int('d')]) continue;
        if (*f == 'f' || *f == 'w' || *f == 'S') {
            long v = 0;
            if (!parse_int(value, &v)) return usage(p, "-" + letter + " needs an integer, not '" + value + "'");
            value = (*f == 'S') ? (v == 0 ? "0" : "1") : (v == 1 ? "1" : "0");
        }
        out.push_back("-" + letter);
        out.push_back(value);
    }
    return run(cmd_generate, out);
}

int run_program(const Program& p, int argc, char** argv) {
    switch (p.kind) {
    case Kind::generate:
        return run_generate(p, argc, argv);
    case Kind::reconstruct_point:
    case Kind::reconstruct_aa: {
        if (argc > 1) return usage(p, std::string("takes no arguments (reads standard input), got '") + argv[1] + "'");
        std::vector<std::string> out = {"reconstruct", "-", "-o", "-", "--plain"};
        if (p.kind == Kind::reconstruct_point) out.push_back("--no-aa");
        return run(cmd_reconstruct, out);
    }
    case Kind::psnr: {
        if (argc != 3) return usage(p, "needs exactly two image files");
        for (int i = 1; i < 3; ++i)
            if (argv[i][0] == '-' && argv[i][1] != '\0') return usage(p, std::string("unknown option ") + argv[i]);
        return run(cmd_psnr, {"psnr", argv[1], argv[2]});
    }
    }
    return 2;
}

}  // namespace

int thesis_alias(const char* name, int argc, char** argv, bool* handled) {
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    for (std::size_t i = 0; i < count; ++i) {
        if (table[i].thesis_program && std::strcmp(name, table[i].thesis_program) == 0) {
            *handled = true;
            return run_program(mesh_program(table[i]), argc, argv);
        }
    }
    for (const auto& p : kOtherPrograms) {
        if (std::strcmp(name, p.name) == 0) {
            *handled = true;
            return run_program(p, argc, argv);
        }
    }
    *handled = false;
    return 0;
}

}  // namespace erd::cli
