// erd generate: mesh an image with one of the registered methods (algorithms/methods/methods.h) and write
// the model (.model for the basic model, .erd for the ERD model), optionally the triangulation
// (-t) and the polylines (-p). The thesis's ywb, gpi, erd_ed and erd_gpi in one subcommand.
//
// Exit modes (-x, thesis A.5.1) when the method could not reach N points exactly:
//   0: "ERROR: target sampling density not achieved exactly (requested N but got M)", exit 3, and
//      nothing is written (the thesis's program exits at that point);
//   1: the same line with "WARNING:" and the files are written, exit 0;  2: silent, exit 0.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/methods/memory_estimate.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/quality_target.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "api/erd.h"
#include "cli/batch.h"
#include "cli/command_line.h"
#include "cli/codec_output.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/framing.h"
#include "cli/image_io.h"
#include "cli/memory_cap.h"
#include "cli/model_file.h"
#include "cli/outputs.h"
#include "cli/progress.h"
#include "cli/rd_search.h"
#include "cli/stats_json.h"
#include "cli/suggest.h"

namespace erd::cli {

namespace {

std::string methods_help();

const CommandLine kGenerate = {
    "generate",
    "erd generate --method NAME [-i IMAGE]... [-d D | -n N] -o OUT [-t TRI] [-p POLY] [-x 0|1|2] "
    "[--max-error E] [--psnr P] [--triangles T] [--thesis] [--max-memory SIZE] [--stats FILE] [--psnr-report] "
    "[-j JOBS] [--summary FILE] [--step Q | --bpp B | --step-psnr P [--choose-density]] [-q]",
    "Mesh an image. N = round(D*W*H/100) with -d (default 3%), or -n N.\n"
    "Many images: several -i or a folder, and outputs named by a pattern with {name} (the input's\n"
    "name without its extension): erd generate -m erdgpi -i photos/ -o out/{name}.erd -j 4 --summary s.csv.\n"
    "Each image is meshed on its own; one that fails is reported and the others go on (exit 1).",
    {
        {'m', "method", "NAME", "mesh-generation method (see the list below)"},
        {'i', "input", "FILE", "input image, PGM, PPM, PAM, PNG, JPEG, TIFF/GeoTIFF or PFM (default and - : stdin); repeat it or name a folder for many"},
        {0, "gray", nullptr, "colour input: mesh its BT.601 luma (0.299 R + 0.587 G + 0.114 B) instead of the colour image"},
        {'d', "density", "D", "sampling density in percent of W*H (default 3; wins over -n)"},
        {'n', "points", "N", "number of sample points, corners included"},
        {'o', "output", "FILE", "output model: .model (ed, gpi) or .erd (erded, erdgpi), or .erdz (binary, either); - = stdout"},
        {'t', "triangulation", "FILE", "also write the triangulation (erd-triangulation 1)"},
        {'p', "polylines", "FILE", "also write the polylines (erd-polylines 1; none for ed, gpi)"},
        {'x', "exit-mode", "0|1|2", "N not reached exactly: 0 error (exit 3), 1 warning, 2 silent"},
        {0, "max-error", "E", "the fewest points (up to N, within 2%) whose model has no error above E (every method; a real-valued image: a bound met in one run)"},
        {0, "max-slack", "S", "ERD, real image, --max-error E: the greedy stops at S*E before the minimax fit (default 1.6)"},
        {0, "minimax", "K", "ERD, real image, --max-error: rounds of the minimax fit of the values (default 2; 0: none)"},
        {0, "min-step", "F", "ERD, real image, --max-error E: keep detected edges whose step across is F*E or more (default 4; 0: all)"},
        {0, "psnr", "P", "the fewest points (up to N, within 2%) whose model reaches P dB (every method)"},
        {0, "count-search", "0|1", "--psnr, --max-error: 1 search the fewest points (default), 0 one run (the greedy loop's own stop, before the ERD refit and flips)"},
        {0, "triangles", "T", "greedy methods: also stop when the mesh has T triangles or more"},
        {'l', "min-length", "L", "ERD: minimum polyline length (default automatic)"},
        {'b', "beta", "B", "ERD: Canny hysteresis proportion beta (default automatic)"},
        {'r', "ratio", "R", "ERD: tau_low / tau_high (default automatic: 0.4)"},
        {'e', "epsilon", "E", "ERD: Douglas-Peucker tolerance (default automatic)"},
        {'f', "select", "0|1", "ERDED: 1 error diffusion (default), 0 random points"},
        {'w', "wedge-rule", "0|1", "ERD: wedge values by 1 MMSODD line search (default), 0 fixed distance"},
        {'s', "wedge-order", "K", "ERD: binomial order of the wedge-value MMSODD (default 5)"},
        {'B', "startup", "0|1|2", "ERDED: error-diffusion startup 0 mirror (default), 1 force, 2 none"},
        {'S', "simple", "0|1", "ERD: 0 simple image, 1 not simple (default automatic)"},
        {0, "seed", "S", "ERDED -f 0: random seed (default 1)"},
        {0, "thesis", nullptr, "ERD: the thesis's method exactly: --wedge-fit 0 --flips 0 --moves 0 --alpha-min 1 --alpha-max 1.5 --edge-zero-radius 0 --edges soft --aa-errors 1 --lower-beta 1 (later flags override)"},
        {0, "lower-beta", "0|1", "ERD: the parameter loop lowers beta by 0.75 as it doubles l (1, default, the thesis's) or doubles l alone on one detection (0: faster where the loop repeats, e.g. noisy photos)"},
        {0, "edges", "KIND", "ERD: hard (steps between pixels: drawings, screenshots), soft (blurred: photos) or auto (default: measured)"},
        {0, "wedge-fit", "N", "ERD: least-squares refit of the wedge values, N CGLS iterations (default 6; 0 = thesis values)"},
        {0, "wedge-prior", "W", "ERD refit: each line-search value weighs as W pixels (default 0.01)"},
        {0, "wedge-bounds", "M", "ERD refit: keep each value within its pixels' sample range widened by M times it (default 0.5; -1: off)"},
        {0, "oversample", "K", "GPRFS, ERDGPR: the start holds K*N points before removal (default: GPRFS 8, ERDGPR 1.5)"},
        {0, "removal-refit", "0|1", "ERDGPR: refit the wedge values before each removal stage (default 1)"},
        {0, "removal-cycles", "C", "ERDGPR: C more cycles of insertion to K*N and removal to N (default 0)"},
        {0, "removal-stages", "S", "ERDGPR: removal in S stages, each from a refitted compact mesh (default 1)"},
        {0, "id-cycles", "C", "ID: insertion/removal cycles after growing to N (default 4; the quality-for-time knob)"},
        {0, "id-share", "A", "ID: each cycle inserts and then removes A*N points (default 1)"},
        {0, "lazy", nullptr, "GPR, GPRFS, ERDGPR: recompute stale significances only at the heap's top (cheaper, worse; default: at once)"},
        {0, "bpr", "R", "any method: R rounds of bad-point replacement at the end (default 0)"},
        {0, "refit-stages", "K", "ERDGPI: refit the wedge values K times during refinement (default 0)"},
        {0, "flip-min-share", "F", "ERD: flips skip quadrilaterals whose error is below F of the mean of two faces (default 0.2)"},
        {0, "moves", "K", "ERD: vertex moves after the first K rounds of flips, followed by a refit (default 2, erdgpr 3)"},
        {0, "move-step", "S", "ERD: the first round's move step in half pixels, halved each round after, at least 1 (default 2, erdgpr 4)"},
        {0, "move-min-gain", "G", "ERD: a move predicted to lower its faces' error by less than G of it is not tried (default 0.05, erdgpr 0.02)"},
        {0, "flips", "K", "ERD: K rounds of data-dependent flips of unconstrained edges, each followed by a refit (default 2, erdgpr 3: any of these four given, erdgpr takes the others' defaults; also ED/GPI --optimize)"},
        {0, "optimize", nullptr, "ED, GPI: least-squares vertex values (ours, beyond the thesis)"},
        {0, "alpha-min", "A", "ERD: wedge line search from A pixels along the bisector (default 0.75; thesis 1)"},
        {0, "alpha-max", "B", "ERD: ... to B pixels, steps of 0.05 (default 1; thesis 1.5)"},
        {0, "edge-zero-radius", "R", "ERDED: zero the density within R pixels of edge pixels (default 1; thesis 0)"},
        {0, "aa-errors", "0|1", "ERDGPI: refinement errors against the 4x4-supersampled approximation (default 0; thesis 1)"},
        {0, "constraints", "FILE", "ERD: polylines (erd-polylines 1, doubled coordinates, as -p writes) kept as constrained edges"},
        {0, "no-detect", nullptr, "ERD: no edge detection; the --constraints are the only constrained edges"},
        {0, "max-memory", "SIZE", "refuse a job whose estimated peak memory is above SIZE (e.g. 2G; default: the memory available now; 0 = no cap)"},
        {0, "stats", "FILE", "write run statistics as one JSON line (- = stdout)"},
        {0, "psnr-report", nullptr, "also reconstruct the model and print its PSNR on stderr (also under -q; --stats)"},
        kProgressOption,
        {'j', "jobs", "N", "one image: N threads (default and 0: one per processor); many: N images at a time (default 1)"},
        {0, "summary", "FILE", "many images: a table of file, method, points, PSNR, seconds, status (.csv, or .json)"},
        {0, "step", "Q", ".erdz: value quantisation step (default 1)"},
        {0, "bpp", "B", ".erdz: the finest step whose file has at most B bits per pixel"},
        {0, "step-psnr", "P", ".erdz: the coarsest step whose decoded model reconstructs at P dB or more"},
        {0, "choose-density", nullptr, ".erdz with --bpp or --step-psnr: choose the density too (0.0625-8%): the best PSNR within B bpp, or the smallest file at P dB"},
    },
    "no summary or progress lines", 0, 0, nullptr,
    methods_help,
};

std::string method_list() {
    std::size_t count = 0;
    const MethodInfo* m = methods(&count);
    std::string out;
    for (std::size_t i = 0; i < count; ++i) out += std::string("  ") + m[i].name + "\t" + m[i].summary + "\n";
    return out;
}

// "unknown method 'X'; available: ... Did you mean 'Y'?", as for an unknown subcommand.
std::string unknown_method(const std::string& name) {
    std::size_t count = 0;
    const MethodInfo* m = methods(&count);
    std::vector<const char*> names;
    for (std::size_t i = 0; i < count; ++i) names.push_back(m[i].name);
    return "unknown method '" + name + "'; available: " + method_names() + "." + did_you_mean(name, names);
}

// A model named for the other kind (gpi -o x.erd) would be read by its content, but older tools
// and the thesis's programs go by the name: refused before any work (docs/DECISIONS.md).
Status check_model_name(const std::string& out, const MethodInfo& method) {
    const ModelFileKind named = model_kind_from_name(out);
    const bool erd = method.model == ModelKind::erd;
    const char* right = erd ? ".erd" : ".model";
    if (named == ModelFileKind::unknown || named == (erd ? ModelFileKind::erd : ModelFileKind::basic)) return Status::success();
    return Status::bad_input(out + ": " + method.name + " makes " + (erd ? "an ERD model" : "a basic model") +
                             ", which is a " + right + " file; name the output " + right);
}

// The one line a run prints without -q: what was made, where, how long it took.
std::string summary(const MethodInfo& method, const Image& image, const GenerateResult& res, const std::string& out,
                    double seconds) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s: %zu points, %zu faces from %d x %d in %.2f s -> %s", method.name,
                  res.model.vertices.size(), res.model.faces.size(), image.width, image.height, seconds,
                  out == "-" ? "stdout" : out.c_str());
    return buf;
}

std::string methods_help() { return "\nMethods:\n" + method_list(); }

std::string real_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Fills *o from the parsed flags; the first bad value sets *st.
void parse_options(const Args& a, GenerateOptions* o, int* exit_mode, Status* st) {
    const double big = 1e300;
    if (a.has("density")) {
        o->density = a.real("density", 3.0, 0.0, 100.0, st, true);
        o->density_given = true;
    }
    if (a.has("points")) o->points = a.integer("points", 0, 1, (1LL << 40), st);
    *exit_mode = int(a.integer("exit-mode", 0, 0, 2, st));
    if (a.has("max-error")) o->max_error = a.real("max-error", -1.0, 0.0, big, st);
    if (a.has("triangles")) o->triangles = a.integer("triangles", 0, 1, (1LL << 40), st);
    if (a.has("psnr")) {
        o->psnr = a.real("psnr", 0.0, 0.0, 1000.0, st, true);
    }
    o->min_length = int(a.integer("min-length", -1, 1, 1 << 20, st));
    if (a.has("beta")) o->beta = a.real("beta", -1.0, 1e-9, 1.0, st);
    if (a.has("ratio")) o->ratio = a.real("ratio", -1.0, 1e-9, 1.0, st);
    if (a.has("epsilon")) o->epsilon = a.real("epsilon", -1.0, 0.0, big, st);
    o->ed_select = int(a.integer("select", 1, 0, 1, st));
    o->wedge_rule = int(a.integer("wedge-rule", 1, 0, 1, st));
    o->wedge_order = int(a.integer("wedge-order", 5, 1, 31, st));
    if (st->ok() && o->wedge_order % 2 == 0)
        *st = Status::bad_input("--wedge-order: " + escape_name(a.str("wedge-order")) + " is not an odd filter order (allowed: 1, 3, ..., 31)");
    o->startup = int(a.integer("startup", 0, 0, 2, st));
    if (a.has("simple")) o->simple = int(a.integer("simple", -1, 0, 1 << 30, st));
    if (a.has("seed")) o->seed = std::uint64_t(a.integer("seed", 1, 0, (1LL << 62), st));
    // --thesis first, so an explicit flag beside it still wins.
    if (a.has("thesis")) set_thesis_preset(o);
    if (a.has("lower-beta")) o->lower_beta = a.integer("lower-beta", 1, 0, 1, st) == 1;
    if (a.has("edges")) {
        const std::string e = a.str("edges");
        if (e == "hard" || e == "soft" || e == "auto")
            o->edges = e == "hard" ? EdgeChoice::hard : e == "soft" ? EdgeChoice::soft : EdgeChoice::automatic;
        else if (st->ok())
            *st = Status::bad_input("--edges: '" + e + "' is not hard, soft or auto");
    }
    if (a.has("wedge-fit")) o->wedge_fit = int(a.integer("wedge-fit", o->wedge_fit, 0, 1000, st));
    if (a.has("wedge-prior")) o->wedge_prior = a.real("wedge-prior", o->wedge_prior, 0.0, 1e9, st);
    if (a.has("wedge-bounds")) o->wedge_bounds = a.real("wedge-bounds", o->wedge_bounds, -1.0, 1e6, st);
    if (a.has("oversample")) o->oversample = a.real("oversample", 0.0, 1.0, 64.0, st);
    if (a.has("id-cycles")) o->id_cycles = int(a.integer("id-cycles", 4, 0, 1000, st));
    if (a.has("id-share")) o->id_share = a.real("id-share", 1.0, 0.0, 4.0, st);
    if (a.has("lazy")) o->removal_lazy = true;
    if (a.has("removal-refit")) o->removal_refit = int(a.integer("removal-refit", 1, 0, 1, st));
    if (a.has("removal-cycles")) o->removal_cycles = int(a.integer("removal-cycles", 0, 0, 16, st));
    if (a.has("removal-stages")) o->removal_stages = int(a.integer("removal-stages", 1, 1, 16, st));
    if (a.has("bpr")) o->bpr = int(a.integer("bpr", 0, 0, 1000, st));
    if (a.has("refit-stages")) o->refit_stages = int(a.integer("refit-stages", 0, 0, 64, st));
    if (a.has("optimize")) o->optimize = true;
    if (a.has("flips")) o->flips = int(a.integer("flips", 0, 0, 64, st));
    if (a.has("flip-min-share")) o->flip_min_share = a.real("flip-min-share", 0.0, 0.0, 1e9, st);
    if (a.has("moves")) o->moves = int(a.integer("moves", 0, 0, 64, st));
    if (a.has("move-step")) o->move_step = int(a.integer("move-step", 2, 1, 64, st));
    if (a.has("move-min-gain")) o->move_min_gain = a.real("move-min-gain", 0.0, 0.0, 1e9, st);
    o->ending_given = a.has("flips") || a.has("moves") || a.has("move-step") || a.has("move-min-gain");
    if (a.has("alpha-min")) o->alpha_min = a.real("alpha-min", o->alpha_min, 0.0, 64.0, st);
    if (a.has("alpha-max")) o->alpha_max = a.real("alpha-max", o->alpha_max, 0.0, 64.0, st);
    if (st->ok() && o->alpha_max < o->alpha_min)
        *st = Status::bad_input("--alpha-max " + real_text(o->alpha_max) + " is below --alpha-min " +
                                real_text(o->alpha_min));
    if (a.has("edge-zero-radius"))
        o->edge_zero_radius = int(a.integer("edge-zero-radius", o->edge_zero_radius, 0, 64, st));
    if (a.has("count-search")) o->count_search = a.integer("count-search", 1, 0, 1, st) == 1;
    if (a.has("aa-errors")) o->supersampled_errors = a.integer("aa-errors", 0, 0, 1, st) == 1;
    if (a.has("max-slack")) o->max_slack = a.real("max-slack", o->max_slack, 1.0, 16.0, st);
    if (a.has("minimax")) o->minimax_rounds = int(a.integer("minimax", o->minimax_rounds, 0, 64, st));
    if (a.has("min-step")) o->min_step_factor = a.real("min-step", o->min_step_factor, 0.0, 1e6, st);
}

}  // namespace

const CommandLine& generate_command_line() { return kGenerate; }

void parse_generate_options(const Args& a, GenerateOptions* o, int* exit_mode, Status* st) {
    parse_options(a, o, exit_mode, st);
}

// The output files of one image.
struct Paths {
    std::string in, out, tri, poly, stats;
};

// One image: read, mesh, write. In a batch (record not null) progress is the batch's, and the
// PSNR is measured for the summary when one is written.
static int generate_one(const Args& a, const Reporter& rep, const Paths& p, int threads, BatchRecord* record) {
    const auto t_start = std::chrono::steady_clock::now();
    const MethodInfo* method = find_method(a.str("method"));
    GenerateOptions opt;
    int exit_mode = 0;
    Status st;
    parse_options(a, &opt, &exit_mode, &st);
    CodecChoice codec;
    parse_codec_options(a, &codec, &st);
    if (!st) return rep.usage(st.message);

    if ((a.has("constraints") || a.has("no-detect")) && method->model != ModelKind::erd)
        return rep.usage(std::string("--constraints and --no-detect are for the ERD methods (erded, erdgpi), not ") + method->name);
    opt.detect = !a.has("no-detect");
    const std::string constraints_in = a.str("constraints");
    if (a.has("constraints") && constraints_in.empty()) return rep.usage("empty --constraints file name");
    if (constraints_in == "-" && a.str("input", "-") == "-") return rep.usage("the image and --constraints cannot both come from stdin");

    std::size_t max_memory = 0;
    const bool have_cap = a.has("max-memory");
    if (have_cap && !(st = parse_memory_size(a.str("max-memory"), &max_memory))) return rep.usage(st.message);

    const std::string &in = p.in, &out = p.out, &tri = p.tri, &poly = p.poly, &stats_out = p.stats;
    std::vector<std::string> outs = {out};
    if (!tri.empty()) outs.push_back(tri);
    if (!poly.empty()) outs.push_back(poly);
    if (!stats_out.empty()) outs.push_back(stats_out);
    Outputs outputs;
    std::vector<std::string> ins = {in};
    if (!constraints_in.empty()) ins.push_back(constraints_in);
    st = outputs.check(outs, ins);
    if (!st) return st.message == "only one output can go to stdout" ? rep.usage(st.message) : rep.fail(st);
    st = check_model_name(out, *method);
    if (!st) return rep.fail(st);
    if (codec.given && !erdz_name(out)) return rep.usage("--step, --bpp and --step-psnr apply to .erdz outputs only");
    if (codec.choose_density && (a.has("density") || a.has("points")))
        return rep.usage("--choose-density chooses the density: not with -d or -n");

    auto t0 = std::chrono::steady_clock::now();
    Image image;
    // The one place where generate decides what a colour image becomes: the methods take colour
    // (issue 17), so it passes through; --gray meshes its luma instead.
    st = read_input_image(in, a.has("gray") ? ColourInput::luma_asked : ColourInput::keep, rep, &image);
    if (!st) return rep.fail(st);
    // A real image (float, signed, 32-bit or with nodata: issue 47).
    if (image.real()) {
        if (erdz_name(out) || codec.choose_density)
            return rep.fail(Status::bad_input(escape_name(out) + ": .erdz holds models of 8- and 16-bit images; a real-valued "
                                              "image's model is written as .erd or .model (its values exactly)"));
        if (opt.optimize && opt.max_error >= 0)
            return rep.usage("--optimize and --max-error on a real-valued image: the least-squares values would break the bound; use one");
    }
    if (!constraints_in.empty()) {
        std::string text;
        // A stream stops at its first definite error: /dev/zero, `yes |` read 4 KiB, not 1 GiB.
        if (!(st = read_file(constraints_in, &text, kMaxInputBytes, polylines_framer()))) return rep.fail(st);
        if (!(st = read_polylines(text, &opt.constraints)))
            return rep.fail(Status::bad_input(escape_name(constraints_in) + ": " + st.message));
    }
    const double read_seconds = seconds_since(t0);

    // Same checks the methods make, here first so the message names the flags.
    // --choose-density: the densest mesh it may try bounds the memory.
    GenerateOptions sized = opt;
    sized.threads = threads;  // edge detection's bands hold memory of their own (memory_estimate.cpp)
    if (codec.choose_density) sized.density = kChoiceMaxDensity, sized.density_given = true;
    std::int64_t n = target_points(sized, image.width, image.height);
    st = check_target(n, image.width, image.height);
    if (!st) return rep.fail(Status::bad_input(in + ": " + st.message));

    // Refused up front when the estimated peak does not fit (cli/memory_cap.h): estimated from
    // the image read (algorithms/methods/memory_estimate.h), within 25% of the measured peak.
    // The estimate is never above the size bound, so when the bound fits the estimate is made
    // only for --stats (it costs an ERD method a sample of step 1's gradient: 3-5% of a photo's run).
    std::size_t need = 0;
    {
        // The library's figures plus the process itself (binary, stdio, buffers): 1.4 MiB, what a
        // run on an 8 x 8 image has above the library's fixed bytes (2 MiB while the program
        // linked iostreams: docs/DECISIONS.md "Memory").
        const std::size_t process = std::size_t(14) * (std::size_t(1) << 20) / 10;
        const std::size_t cap = have_cap ? max_memory : available_memory();
        const std::size_t bound = memory_bound(*method, image.width, image.height, image.channels, sized) + process;
        if ((cap != 0 && bound > cap) || !stats_out.empty()) need = memory_estimate(*method, image, sized) + process;
        st = check_memory(need, cap, have_cap,
                          escape_name(in) + ": meshing " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                              " with " + method->name + " at " + std::to_string(n) + " points");
        if (!st) return rep.fail(st);
    }

    Progress progress("generate", !record && Progress::should_show(a.has("progress"), rep.quiet()), a.has("progress"));
    opt.progress = progress.hook();
    opt.threads = threads;
    GenerateResult res;
    std::string bytes, codec_note;
    DensityChoice choice;
    if (codec.choose_density) st = choose_density(*method, image, opt, codec, &res, &bytes, &choice);
    else st = run_method(*method, image, opt, &res);
    progress.finish();
    if (!st && st.code == Code::input && !constraints_in.empty() && st.message.rfind("constraints: ", 0) == 0)
        return rep.fail(Status::bad_input(escape_name(constraints_in) + ": " + st.message.substr(13)));
    if (!st) return rep.fail(st.code == Code::input ? Status::bad_input(in + ": " + st.message) : st);
    for (const StageTime& s : res.stages) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "%-22s %9.3f ms", s.name.c_str(), s.seconds * 1e3);
        rep.detail(buf);
    }
    for (const std::string& s : result_lines(res.stats)) rep.detail(s);
    if (res.stats.has_quality && !res.stats.quality.reached)
        rep.warn(escape_name(in) + ": " + (opt.psnr > 0 ? "--psnr " + real_text(opt.psnr) : "--max-error " + real_text(opt.max_error)) +
                 " not reached at N = " + std::to_string(res.requested) + " points (raise -d or -n)");
    if (res.stats.has_raster && opt.max_error >= 0 && res.stats.raster.max_error > opt.max_error)
        rep.warn(escape_name(in) + ": the largest error is " + real_text(res.stats.raster.max_error) + ", above --max-error " +
                 real_text(opt.max_error) + ": N points were reached first (raise -d or -n)");

    std::string exact_warning;
    st = check_exact_count(res.requested, res.achieved, ExactMode(exit_mode), &exact_warning);
    if (!st) {
        std::fprintf(stderr, "ERROR: %s\n", st.message.c_str());
        return int(Code::density);
    }
    if (!exact_warning.empty()) std::fprintf(stderr, "WARNING: %s\n", exact_warning.c_str());

    // Every output is staged (a temporary beside its target) and committed together at the end,
    // so a failure anywhere leaves every old file as it was (cli/outputs.h).
    t0 = std::chrono::steady_clock::now();
    codec.erdz.method = method->name;
    if (codec.choose_density) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "density %g%% (%zu tried): step %g, %.4f bpp, %.4f dB", choice.density,
                      choice.trials.size(), choice.rate.step, choice.rate.bpp, choice.rate.psnr);
        codec_note = buf;
        for (const DensityTrial& t : choice.trials) {
            std::snprintf(buf, sizeof buf, "  tried %g%%: %s step %g, %.4f bpp, %.4f dB", t.density, t.rate.met ? "" : "(not met)",
                          t.rate.step, t.rate.bpp, t.rate.psnr);
            rep.detail(std::string("erdz: ") + buf);
        }
    } else {
        st = model_bytes_for(out, res.model, &image, codec, &bytes, &codec_note);
        if (!st) return rep.fail(st);
    }
    if (!codec_note.empty()) rep.detail("erdz: " + codec_note);
    st = outputs.stage(out, bytes);
    if (!st) return rep.fail(st);
    if (!tri.empty()) {
        std::string tri_bytes;
        st = write_triangulation(res.model, &tri_bytes);
        if (!st) return rep.fail(st);
        st = outputs.stage(tri, tri_bytes);
        if (!st) return rep.fail(st);
    }
    if (!poly.empty()) {
        std::string poly_bytes;
        write_polylines(res.polylines, &poly_bytes);
        st = outputs.stage(poly, poly_bytes);
        if (!st) return rep.fail(st);
    }
    const double write_seconds = seconds_since(t0);

    // The reported PSNR is that of the model's own reconstruction: imgsyn for a basic model,
    // 4x4-supersampled imgsyn_aa for a soft-edged ERD model (../shared/spec/NOTES.md), imgsyn for a
    // hard-edged one.
    bool have_psnr = false;
    double db = 0.0, psnr_seconds = 0.0;
    if (a.has("psnr-report") || (record && a.has("summary"))) {
        t0 = std::chrono::steady_clock::now();
        Image rec;
        st = reconstruct(res.model, supersampled(res.model), &rec, {}, threads);
        if (!st) return rep.fail(Status::failure("reconstruct: " + st.message));
        st = psnr(image, rec, &db, threads);
        if (!st) return rep.fail(st);
        have_psnr = true;
        psnr_seconds = seconds_since(t0);
        // Asked for explicitly, so printed under -q too (stderr: stdout may carry the model).
        if (!a.has("psnr-report")) {
        } else if (std::isinf(db)) std::fprintf(stderr, "erd generate: psnr: inf\n");
        else std::fprintf(stderr, "erd generate: psnr: %.4f dB\n", db);
    }
    if (!stats_out.empty()) {
        GenerateStats gs = collect_stats(method->name, image, res);
        gs.stages.insert(gs.stages.begin(), StageTime{"read image", read_seconds});
        gs.stages.push_back({"write", write_seconds});
        if (have_psnr) {
            gs.stages.push_back({"psnr", psnr_seconds});
            gs.has_psnr = true;
            gs.psnr = db;
        }
        gs.total_seconds = seconds_since(t_start);
        gs.peak_memory_bytes = peak_memory_bytes();
        gs.memory_estimate_bytes = (long long)need;
        st = outputs.stage(stats_out, stats_json(gs));
        if (!st) return rep.fail(st);
    }
    st = outputs.commit();
    if (!st) return rep.fail(st);
    rep.note(summary(*method, image, res, out, seconds_since(t_start)));
    if (record) {
        record->method = method->name;
        record->points = (long long)res.model.vertices.size();
        record->has_psnr = have_psnr;
        record->psnr = db;
    }
    return 0;
}

static int run_generate(const Args& a, const Reporter& rep) {
    if (!a.has("method")) return rep.usage("--method is required (one of: " + method_names() + ")");
    if (!find_method(a.str("method"))) return rep.usage(unknown_method(a.str("method")));
    // Without -i the image comes on stdin, as for reconstruct; not from a terminal, where the
    // user would wait for nothing.
    if (!a.has("input") && ::isatty(STDIN_FILENO))
        return rep.usage("-i IMAGE is required (or an image on standard input)");
    if (!a.has("output")) return rep.usage("-o OUT is required (- for stdout)");
    Paths p{a.str("input", "-"), a.str("output"), a.str("triangulation"), a.str("polylines"), a.str("stats")};
    if (a.has("triangulation") && p.tri.empty()) return rep.usage("empty -t file name");
    if (a.has("polylines") && p.poly.empty()) return rep.usage("empty -p file name");
    if (a.has("stats") && p.stats.empty()) return rep.usage("empty --stats file name");
    if (a.has("summary") && a.str("summary").empty()) return rep.usage("empty --summary file name");

    // Option errors once, before any image (a batch would report them for each).
    GenerateOptions checked;
    int exit_mode = 0;
    Status st;
    parse_options(a, &checked, &exit_mode, &st);
    CodecChoice codec_checked;
    parse_codec_options(a, &codec_checked, &st);
    std::size_t max_memory = 0;
    if (st && a.has("max-memory")) st = parse_memory_size(a.str("max-memory"), &max_memory);
    if (!st) return rep.usage(st.message);

    const std::vector<std::string> inputs = a.all("input");
    const bool batch = wants_batch(inputs, p.out, a.has("summary"));
    Parallelism par;
    if (!(st = parse_parallelism(a.has("jobs"), a.str("jobs"), batch, &par))) return rep.usage(st.message);
    if (!batch) return generate_one(a, rep, p, par.threads, nullptr);
    std::vector<BatchItem> items;
    st = expand_inputs(inputs, {".pgm", ".pnm", ".png", ".ppm", ".pam", ".jpg", ".jpeg", ".tif", ".tiff", ".pfm"}, &items);
    if (st && !(st = check_patterns(items, {p.out, p.tri, p.poly, p.stats}))) return rep.usage(st.message);
    if (!st) return rep.fail(st);
    const BatchJob job = [&](const BatchItem& it, BatchRecord* rec) {
        const Paths one{it.input, expand_pattern(p.out, it), expand_pattern(p.tri, it), expand_pattern(p.poly, it),
                        expand_pattern(p.stats, it)};
        return generate_one(a, rep, one, par.threads, rec);
    };
    return run_batch(items, par.jobs, job, a.str("summary"), rep, Progress::should_show(a.has("progress"), rep.quiet()),
                     {{p.out, p.tri, p.poly, p.stats}, {a.str("constraints")}});
}

int cmd_generate(int argc, char** argv) { return run_command(kGenerate, argc, argv, run_generate); }

}  // namespace erd::cli
