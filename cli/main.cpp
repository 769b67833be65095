// erd: one program, a static table of subcommands, and the thesis's command names via argv[0].
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/commands.h"
#include "cli/outputs.h"
#include "cli/report.h"
#include "cli/suggest.h"
#include "cli/version.h"


namespace erd::cli {

static int cmd_help(int argc, char** argv);

static const Command kCommands[] = {
    {"generate", "mesh an image with one of the methods (erd help generate lists them)", cmd_generate},
    {"reconstruct", "rasterise a .model or .erd back into an image", cmd_reconstruct},
    {"psnr", "PSNR of an approximation against the original", cmd_psnr},
    {"edges", "half-pixel edge map and polylines of an image", cmd_edges},
    {"render", "draw a mesh as SVG or PNG", cmd_render},
    {"export", "write a mesh as OBJ, PLY, STL or glTF (.glb)", cmd_export},
    {"convert", "rewrite a model as .model/.erd text or .erdz binary", cmd_convert},
    {"info", "what an image or a model file holds (size, channels, vertices, bits per pixel)", cmd_info},
    {"synth", "write a deterministic test image", cmd_synth},
    {"tiles", "mesh a raster larger than memory in tiles that meet exactly (plan, tasks, merge)", cmd_tiles},
    {"help", "list subcommands, or show one's help", cmd_help},
};

static const Command* find_command(const char* name) {
    for (const auto& c : kCommands)
        if (std::strcmp(c.name, name) == 0) return &c;
    return nullptr;
}

static void list_commands(FILE* out) {
    std::fprintf(out, "usage: erd SUBCOMMAND [options]   (erd help SUBCOMMAND for details)\n\nSubcommands:\n");
    for (const auto& c : kCommands) std::fprintf(out, "  %-12s %s\n", c.name, c.summary);
    std::fprintf(out, "\nExit status: 0 success, 1 runtime failure, 2 usage or input error,\n"
                      "3 target sampling density not achieved exactly (-x 0).\n");
    // The three commands most people need, last, where the eye lands.
    std::fprintf(out, "\nExamples:\n"
                      "  erd generate -m erdgpi -i photo.png -d 1 -o photo.erd   mesh with 1%% of the pixels as vertices\n"
                      "  erd reconstruct photo.erd -o approx.png                 the image the mesh stands for\n"
                      "  erd psnr photo.png approx.png                           how close it is, in dB\n");
}

static int cmd_help(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) { list_commands(stdout); return 0; }
    if (!std::strcmp(argv[1], "--version")) { std::printf("erd %s\n", kVersion); return 0; }
    const Command* c = find_command(argv[1]);
    if (!c || c->run == cmd_help) {
        if (!c) { std::fprintf(stderr, "erd help: no subcommand '%s'\n", escape_name(argv[1]).c_str()); return 2; }
        list_commands(stdout);
        return 0;
    }
    char help_flag[] = "--help";
    char* sub_argv[] = {argv[1], help_flag, nullptr};
    return c->run(2, sub_argv);
}

static int unknown(const char* name) {
    std::vector<const char*> names;
    for (const auto& c : kCommands) names.push_back(c.name);
    std::fprintf(stderr, "erd: '%s' is not a subcommand.%s See 'erd help'.\n", escape_name(name).c_str(),
                 did_you_mean(name, names).c_str());
    return 2;
}

// Text printed with printf (info, psnr, help) sits in stdio's buffer: a full disk shows only
// when it is flushed, so a run that otherwise succeeded fails here (exit 1) instead of exiting 0.
static int flush_stdout(const char* name, int status) {
    const bool failed = std::fflush(stdout) != 0;
    const int err = errno;
    if (status != 0 || !(failed || std::ferror(stdout))) return status;
    std::fprintf(stderr, "erd %s: stdout: %s\n", name, failed ? std::strerror(err) : "write error");
    return 1;
}

}  // namespace erd::cli

namespace {

// glibc serves blocks above a dynamic threshold (128 KiB at first) with fresh mmaps and unmaps
// them on free, so every whole-image array the pipeline allocates again after freeing one (the
// edge detector's planes between detections, the greedy and refit arrays after them) is paid
// for again in page faults. A fixed threshold above the largest of them takes them from the
// heap, where freed blocks are reused as they are: fewer faults for a little more peak RSS
// (docs/DECISIONS.md "Memory"). The freed top of the heap is kept too (M_TRIM_THRESHOLD, up to
// 256 MiB): ERDGPR's refits, removal cache and flip rounds free and take again arrays of a few MB
// each, which glibc would otherwise give back and fault in again (kodim03 2%: 23.0k -> 5.5k faults).
//
// Not under Valgrind: its tools run glibc's allocator in a brk segment of a few MB, and heap
// growth beyond it fails (std::bad_alloc on lena). Valgrind always preloads its vgpreload_*
// objects, which is how it is recognised here.
[[maybe_unused]] void tune_allocator() {
#if defined(__GLIBC__)
    const char* preload = std::getenv("LD_PRELOAD");
    if (preload && std::strstr(preload, "vgpreload")) return;
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    // One arena for every thread: the -j threads allocate a few arrays each (edge detection's
    // bands), and an arena of their own kept 1.6 MB more at the peak (640 x 480, soft edges).
    mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace

int erd::cli::run(int argc, char** argv) {
    const char* self = argc > 0 && argv[0] ? argv[0] : "erd";
    const char* base = std::strrchr(self, '/');
    base = base ? base + 1 : self;
    bool handled = false;
    int status = thesis_alias(base, argc, argv, &handled);
    if (handled) return flush_stdout(base, status);

    if (argc < 2) { list_commands(stderr); return 2; }
    const char* sub = argv[1];
    if (!std::strcmp(sub, "--version") || !std::strcmp(sub, "version")) { std::printf("erd %s\n", kVersion); return 0; }
    if (!std::strcmp(sub, "--help") || !std::strcmp(sub, "-h")) { list_commands(stdout); return 0; }
    const Command* c = find_command(sub);
    if (!c) return unknown(sub);
    return flush_stdout(sub, c->run(argc - 1, argv + 1));
}

// The Python extension links the CLI without this main and calls run() (python/erd/__main__.py).
#ifndef ERD_CLI_NO_MAIN
int main(int argc, char** argv) {
    erd::cli::guard_standard_streams();
    tune_allocator();
    erd::cli::install_output_signal_handlers();
    return erd::cli::run(argc, argv);
}
#endif
