// erd tiles: a raster larger than one process meshed in tiles that meet exactly (issue 48).
//
//   erd tiles -m gpi -i big.tif --tile 4096 -o out/ [--merge all.glb] [generate's options]
//       = --plan, then every --task K in turn, then --finish
//   erd tiles ... -o out/ --plan     reads the raster once by windows (rows, strips or tiles),
//                                    decides the shared borders' vertices and every tile's budget,
//                                    writes out/plan.txt (tiles_plan.h): the task list
//   erd tiles -o out/ --task K       one tile: its window read, meshed with its sides fixed, written
//                                    as out/tile_J_I.model or .erd (and .EXT with --format)
//   erd tiles -o out/ --finish [--merge FILE]  out/index.json, the seams checked, the merged mesh
//
// Tasks are independent and deterministic (one thread each), so any order and any engine (GNU
// parallel, a Slurm array, Dask: docs/manual.md) gives the same bytes. The decisions (borders by
// the 1-D greedy, budgets by the tiles' error weight) are algorithms/methods/tiles.h's.
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "algorithms/codec/erdz.h"
#include "algorithms/imaging/edge_kind.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/result.h"
#include "algorithms/methods/options.h"
#include "algorithms/methods/tiles.h"
#include "algorithms/model/model.h"
#include "algorithms/model/reconstruct.h"
#include "algorithms/output/export.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "cli/json.h"
#include "cli/model_file.h"
#include "cli/outputs.h"
#include "cli/report.h"
#include "cli/tiles_merge.h"
#include "cli/tiles_plan.h"
#include "cli/tiles_scan.h"
#include "imageio/raster_window.h"

namespace erd::cli {

namespace {

// generate's flags that `erd tiles` passes on to every tile (the others are its own or make no
// sense for a tile: outputs, batches, stdin, the .erdz rate flags, user constraints, --optimize,
// the count search and bad-point replacement of generate's run (a tile is one method run), the
// removal methods' flags).
bool forwarded(const char* name) {
    static const char* const kNot[] = {"method", "input", "output", "triangulation", "polylines", "exit-mode", "constraints",
                                       "no-detect", "max-memory", "stats", "psnr-report", "progress", "jobs", "summary",
                                       "step", "bpp", "step-psnr", "choose-density", "gray", "optimize", "count-search", "bpr",
                                       "oversample", "removal-refit", "removal-cycles", "removal-stages", "id-cycles", "id-share",
                                       "lazy"};
    for (const char* n : kNot)
        if (std::strcmp(n, name) == 0) return false;
    return true;
}

const CommandLine& tiles_command_line() {
    static const CommandLine cl = [] {
        CommandLine c = {
            "tiles",
            "erd tiles -m METHOD -i RASTER --tile T -o DIR [--merge FILE] [--format EXT] [generate's options]\n"
            "       erd tiles -m METHOD -i RASTER --tile T -o DIR --plan [generate's options]\n"
            "       erd tiles -o DIR --task K\n"
            "       erd tiles -o DIR --finish [--merge FILE] [--zscale Z]",
            "Mesh a raster larger than memory in tiles of T pixels that meet exactly: the vertices of\n"
            "every shared border are chosen once from the border's own samples (the greedy rule in 1-D)\n"
            "and both tiles keep them, no other point on a tile's side; -d/-n and --triangles are split\n"
            "between the tiles by their error (sum of |second difference|^(1/2)), --max-error and --psnr\n"
            "hold in every tile. The raster is read by windows (TIFF strips or tiles, PFM, raw PGM, PNG rows).\n"
            "Out: DIR/tile_J_I.model or .erd per tile (row J, column I), DIR/index.json (grid, bounds,\n"
            "counts, files, georeferencing) and with --merge one mesh of all tiles, written as it goes.\n"
            "On a cluster: --plan once, then --task K for K = 0 .. tiles-1 in any order on any machines\n"
            "sharing DIR (GNU parallel, Slurm arrays, Dask: docs/manual.md), then --finish: the same bytes\n"
            "as one run. Methods gpi and erdgpi.",
            {
                {'m', "method", "NAME", "gpi or erdgpi"},
                {'i', "input", "RASTER", "the raster: TIFF/GeoTIFF, PFM, raw PGM or PNG (gray, no nodata)"},
                {0, "tile", "T", "tile size in pixels, 2 to 16383 (tiles of T + 1 samples share their border lines)"},
                {'o', "output", "DIR", "the folder of the plan, the tiles and the index (made if missing)"},
                {0, "merge", "FILE", "also write all tiles as one mesh: .obj, .ply, .stl or .glb"},
                {0, "zscale", "Z", "--merge: z = value * Z (default max(W, H) / (10 * range))"},
                {0, "format", "EXT", "each tile also exported as obj, ply, stl or glb (in the tile's own frame)"},
                {0, "plan", nullptr, "only write DIR/plan.txt (the task list)"},
                {0, "task", "K", "only run task K of DIR/plan.txt (0 .. tiles-1)"},
                {0, "finish", nullptr, "only write DIR/index.json (and --merge) from the finished tasks"},
                {0, "psnr-report", nullptr, "also reconstruct every tile: the whole raster's PSNR and largest error in the index (each pixel once)"},
            },
            "no summary lines",
        };
        // --max-error and --psnr are each tile's greedy stop (generate's one run, --count-search 0).
        for (OptionSpec o : generate_command_line().options) {
            if (!forwarded(o.long_name)) continue;
            if (std::strcmp(o.long_name, "max-error") == 0) o.help = "every tile: the greedy stops when its largest abs error <= E (the sides: the 1-D greedy's)";
            if (std::strcmp(o.long_name, "psnr") == 0) o.help = "every tile: the greedy stops when its PSNR reaches P dB (so does the whole raster's)";
            c.options.push_back(o);
        }
        return c;
    }();
    return cl;
}

// A raster read by windows may be larger than an image read whole: 2^20 a side, 2^40 pixels (a
// window, a tile, stays within the usual limits: --tile at most 16383).
imageio::ImageLimits raster_limits() {
    imageio::ImageLimits l;
    l.max_side = 1 << 20;
    l.max_pixels = std::int64_t(1) << 40;
    return l;
}

std::string plan_path(const std::string& dir) { return dir + "/plan.txt"; }

// The absolute path of an existing file (tasks may run elsewhere in the tree).
std::string absolute(const std::string& path) {
    char* r = ::realpath(path.c_str(), nullptr);
    if (!r) return path;
    std::string s = r;
    std::free(r);
    return s;
}

Status make_dir(const std::string& dir) {
    if (::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST) {
        struct stat st {};
        if (::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return Status::success();
        return Status::bad_input(escape_name(dir) + ": not a folder");
    }
    return Status::failure(escape_name(dir) + ": " + std::strerror(errno));
}

// Generate's options of a tile, from the plan's flags.
Status tile_options(const TilesPlan& plan, GenerateOptions* o) {
    std::vector<std::string> words = {"tiles"};
    for (const std::string& a : plan.args) words.push_back(a);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(&w[0]);
    Args a;
    Status st = a.parse(int(argv.size()), argv.data(), 1, tiles_command_line().options);
    if (!st) return Status::bad_input("plan: " + st.message);
    int exit_mode = 0;
    parse_generate_options(a, o, &exit_mode, &st);
    return st ? st : Status::bad_input("plan: " + st.message);
}

// --plan: the raster read once, by bands of rows: the border lines' samples and each tile's weight.
Status make_plan(const Args& a, const std::string& dir, TilesPlan* plan) {
    Status st;
    const MethodInfo* method = find_method(a.str("method"));
    if (!method) return Status::bad_input("unknown method '" + a.str("method") + "' (tiles: gpi or erdgpi)");
    if (std::strcmp(method->name, "gpi") != 0 && std::strcmp(method->name, "erdgpi") != 0)
        return Status::bad_input(std::string("method ") + method->name +
                                 " cannot keep a tile's sides fixed (its error diffusion places points anywhere); use gpi or erdgpi");
    const int T = int(a.integer("tile", 0, 2, 16383, &st));
    if (!st) return st;
    plan->method = method->name;
    if (a.has("format")) {
        plan->format = a.str("format");
        if (plan->format != "obj" && plan->format != "ply" && plan->format != "stl" && plan->format != "glb")
            return Status::bad_input("--format: '" + plan->format + "' is not obj, ply, stl or glb");
    }
    for (const OptionSpec& o : generate_command_line().options) {
        if (!forwarded(o.long_name)) continue;
        for (const std::string& v : a.all(o.long_name)) {
            plan->args.push_back(std::string("--") + o.long_name);
            if (o.value) plan->args.push_back(v);
        }
    }
    for (const std::string& s : plan->args)
        if (s.find('\n') != std::string::npos) return Status::bad_input("an option's value holds a line break");
    GenerateOptions opt;
    if (!(st = tile_options(*plan, &opt))) return st;

    const std::string in = a.str("input");
    if (in.find('\n') != std::string::npos) return Status::bad_input(escape_name(in) + ": a name with a line break");
    imageio::RasterWindow rw;
    if (!(st = rw.open(in, raster_limits()))) return Status::bad_input(escape_name(in) + ": " + st.message);
    if (rw.channels() != 1) return Status::bad_input(escape_name(in) + ": tiles take gray rasters (one channel)");
    const int W = rw.width(), H = rw.height();
    if (W < 2 || H < 2) return Status::bad_input(escape_name(in) + ": too small (" + std::to_string(W) + " x " + std::to_string(H) + ")");
    plan->raster = absolute(in);
    const TileGrid g = make_tile_grid(W, H, T);
    plan->grid = g;

    BorderScan scan(g, T);
    if (method->model == ModelKind::erd) {
        scan.band = true;
        scan.near_cols.assign(2 * std::size_t(g.nx + 1), std::vector<double>(std::size_t(H)));
        scan.near_rows.assign(2 * std::size_t(g.ny + 1), std::vector<double>());
    }
    const int band = std::max(1, int((std::size_t(1) << 22) / std::size_t(W)));
    bool first = true, real = false;
    // The ERD methods' kind of edge, measured once for the raster (the sum of the bands'
    // counts) and given to every tile, unless --edges says.
    const bool erd_method = method->model == ModelKind::erd;
    EdgeKindStats kinds;
    std::uint32_t maxval = 0;
    Image im;
    std::string warning;
    for (int y0 = 0; y0 < H; y0 += band) {
        const int y1 = std::min(H, y0 + band);
        if (!(st = rw.read(0, y0, W, y1, &im, &warning))) return Status::bad_input(escape_name(in) + ": " + st.message);
        if (first) {
            real = im.real();
            maxval = im.maxval;
            plan->geo = im.meta.geo;
            if (!real) scan.ints.start(maxval);
            first = false;
        }
        if (im.real() != real) return Status::bad_input(escape_name(in) + ": its windows differ in type");
        if (erd_method) {
            const EdgeKindStats k = measure_edge_kind(im);
            kinds.hard += k.hard, kinds.soft += k.soft, kinds.steps += k.steps, kinds.clean += k.clean;
        }
        if (im.has_holes())
            return Status::bad_input(escape_name(in) + ": a raster with nodata pixels is not tiled (the outline of the valid region would cross the tiles' sides)");
        for (int y = y0; y < y1; ++y) {
            const std::size_t at = std::size_t(y - y0) * std::size_t(W);
            if (real) scan.reals.row(im.reals.data() + at, y, &scan);
            else scan.ints.row(im.samples.data() + at, y, &scan);
        }
    }
    const std::vector<std::vector<double>>& cols = scan.cols;
    const std::vector<std::vector<double>>& rows = scan.rows;
    const std::vector<double>& weight = scan.weight;
    const double lo = real ? scan.reals.lo : double(scan.ints.lo), hi = real ? scan.reals.hi : double(scan.ints.hi);
    if (erd_method && !a.has("edges") && !a.has("thesis")) {
        plan->args.push_back("--edges");
        plan->args.push_back(kinds.is_hard() ? "hard" : "soft");
    }
    plan->real = real;
    plan->maxval = maxval;
    plan->lo = lo;
    plan->hi = hi;

    // The budget: N of the whole raster as generate would take it.
    const std::int64_t N = target_points(opt, W, H);
    if (!(st = check_target(N, W, H))) return Status::bad_input(escape_name(in) + ": " + st.message);
    const std::vector<std::int64_t> first_split = split_budget(N, weight);
    auto area = [&](int k) {
        int x0, y0, x1, y1;
        plan->window(k, &x0, &y0, &x1, &y1);
        return double(x1 - x0 + 1) * double(y1 - y0 + 1);
    };
    auto density = [&](int i, int j) {
        if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) return -1.0;
        const int k = j * g.nx + i;
        return double(first_split[std::size_t(k)]) / area(k);  // NOLINT
    };
    // A border's cap: its length times the spacing of the points of its tiles, sqrt of their mean
    // density (about how many vertices a mesh of that density has along a line). With --max-error
    // alone, none: the error decides.
    const bool capped = !(opt.max_error >= 0 && !opt.density_given && opt.points == 0);
    auto rule_for = [&](double d0, double d1, int len) {
        ProfileRule r;
        r.max_error = opt.max_error;
        r.rounded = !real && opt.round_values && plan->method == "gpi";
        if (capped) {
            const double d = d0 < 0 ? d1 : d1 < 0 ? d0 : 0.5 * (d0 + d1);
            r.max_interior = std::size_t(std::min<double>(double(len - 1), double(std::llround(double(len) * std::sqrt(std::max(0.0, d))))));
        }
        return r;
    };
    plan->vborder.assign(std::size_t(g.nx + 1), std::vector<std::vector<int>>(std::size_t(g.ny)));
    plan->hborder.assign(std::size_t(g.ny + 1), std::vector<std::vector<int>>(std::size_t(g.nx)));
    std::int64_t border = std::int64_t(g.nx + 1) * std::int64_t(g.ny + 1);
    for (int i = 0; i <= g.nx; ++i)
        for (int j = 0; j < g.ny; ++j) {
            const int a0 = g.row(j), a1 = g.row(j + 1);
            const std::vector<double> z(cols[std::size_t(i)].begin() + a0, cols[std::size_t(i)].begin() + a1 + 1);
            plan->vborder[std::size_t(i)][std::size_t(j)] = simplify_profile(z, rule_for(density(i - 1, j), density(i, j), a1 - a0));
            border += std::int64_t(plan->vborder[std::size_t(i)][std::size_t(j)].size()) - 2;
        }
    for (int j = 0; j <= g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const int a0 = g.column(i), a1 = g.column(i + 1);
            const std::vector<double> z(rows[std::size_t(j)].begin() + a0, rows[std::size_t(j)].begin() + a1 + 1);
            plan->hborder[std::size_t(j)][std::size_t(i)] = simplify_profile(z, rule_for(density(i, j - 1), density(i, j), a1 - a0));
            border += std::int64_t(plan->hborder[std::size_t(j)][std::size_t(i)].size()) - 2;
        }
    // ERD: where a discontinuity crosses a border between two tiles (both tiles end a constrained
    // edge there): the strong-step rule of the edge kind along the border's profile, going on
    // across it (tiles.h profile_crossings).
    if (erd_method && hi > lo) {
        const double strong = real ? kStrongStep * (hi - lo) : double(std::max(1, int(kStrongStep * double(maxval) + 0.5)));
        plan->vcross.assign(plan->vborder.size(), std::vector<std::vector<int>>(std::size_t(g.ny)));
        plan->hcross.assign(plan->hborder.size(), std::vector<std::vector<int>>(std::size_t(g.nx)));
        // The crossings of the border a0 .. a1 of `line` (before, after: its neighbours in the band).
        auto crossings = [&](const std::vector<double>& line, const std::vector<double>& before, const std::vector<double>& after,
                             int a0, int a1) {
            auto piece = [&](const std::vector<double>& l) { return std::vector<double>(l.begin() + a0, l.begin() + a1 + 1); };
            std::vector<int> c = profile_crossings(piece(line), piece(before), piece(after), strong);
            border += std::int64_t(c.size());
            return c;
        };
        for (int i = 1; i < g.nx; ++i)
            for (int j = 0; j < g.ny; ++j)
                plan->vcross[std::size_t(i)][std::size_t(j)] = crossings(cols[std::size_t(i)], scan.near_cols[std::size_t(2 * i)],
                                                                         scan.near_cols[std::size_t(2 * i + 1)], g.row(j), g.row(j + 1));
        for (int j = 1; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                plan->hcross[std::size_t(j)][std::size_t(i)] = crossings(rows[std::size_t(j)], scan.near_rows[std::size_t(2 * j)],
                                                                         scan.near_rows[std::size_t(2 * j + 1)], g.column(i), g.column(i + 1));
    }
    if (border > N)
        return Status::bad_input(escape_name(in) + ": the tiles' borders take " + std::to_string(border) + " of the " +
                                 std::to_string(N) + " points; raise -d or -n, or the tile size");
    const std::vector<std::int64_t> inner = split_budget(N - border, weight);
    const std::vector<std::int64_t> tris =
        opt.triangles > 0 ? split_budget(opt.triangles, weight) : std::vector<std::int64_t>(std::size_t(g.count()), 0);
    plan->points.resize(std::size_t(g.count()));
    plan->triangles.resize(std::size_t(g.count()));
    for (int k = 0; k < g.count(); ++k) {
        const std::int64_t sides = std::int64_t(plan->side_points(k).size() + plan->side_crossings(k).size()) - 4;  // corners twice
        plan->points[std::size_t(k)] = std::min<std::int64_t>(std::int64_t(area(k)), inner[std::size_t(k)] + sides);
        plan->triangles[std::size_t(k)] = opt.triangles > 0 ? std::max<std::int64_t>(1, tris[std::size_t(k)]) : 0;
    }
    (void)dir;
    return Status::success();
}

Status load_plan(const std::string& dir, TilesPlan* plan) {
    std::string text;
    Status st = read_file(plan_path(dir), &text);
    if (!st) return st;
    st = parse_plan(text, plan);
    return st ? st : Status::bad_input(escape_name(plan_path(dir)) + ": " + st.message);
}

std::string model_ext(const TilesPlan& plan) {
    const MethodInfo* m = find_method(plan.method);
    return m && m->model == ModelKind::erd ? ".erd" : ".model";
}

// --task K.
Status run_task(const TilesPlan& plan, const std::string& dir, int k, const Reporter& rep) {
    const auto t0 = std::chrono::steady_clock::now();
    if (k < 0 || k >= plan.grid.count())
        return Status::bad_input("--task " + std::to_string(k) + ": the plan has tasks 0 to " + std::to_string(plan.grid.count() - 1));
    const MethodInfo* method = find_method(plan.method);
    if (!method) return Status::bad_input("plan: unknown method '" + plan.method + "'");
    GenerateOptions opt;
    Status st = tile_options(plan, &opt);
    if (!st) return st;
    opt.density_given = false;
    opt.points = plan.points[std::size_t(k)];
    opt.triangles = plan.triangles[std::size_t(k)];
    opt.lock_border = true;
    opt.border_points = plan.side_points(k);
    opt.border_crossings = plan.side_crossings(k);
    opt.threads = 1;
    int x0, y0, x1, y1;
    plan.window(k, &x0, &y0, &x1, &y1);
    imageio::RasterWindow rw;
    if (!(st = rw.open(plan.raster, raster_limits()))) return Status::bad_input(escape_name(plan.raster) + ": " + st.message);
    if (rw.width() != plan.grid.width || rw.height() != plan.grid.height)
        return Status::bad_input(escape_name(plan.raster) + ": not the raster of the plan (its size changed)");
    Image image;
    if (!(st = rw.read(x0, y0, x1 + 1, y1 + 1, &image))) return Status::bad_input(escape_name(plan.raster) + ": " + st.message);
    GenerateResult res;
    if (!(st = method->run(image, opt, &res))) return st.code == Code::input ? Status::bad_input(plan.tile_name(k) + ": " + st.message) : st;
    pin_side_values(image, &res.model);
    Outputs outputs;
    const std::string model_out = dir + "/" + plan.tile_name(k) + model_ext(plan);
    std::vector<std::string> outs = {model_out};
    const std::string export_out = plan.format.empty() ? "" : dir + "/" + plan.tile_name(k) + "." + plan.format;
    if (!export_out.empty()) outs.push_back(export_out);
    if (!(st = outputs.check(outs, {plan.raster}))) return st;
    std::string bytes;
    if (!(st = encode_model_file(model_out, res.model, ErdzOptions(), &bytes))) return st;
    if (!(st = outputs.stage(model_out, bytes))) return st;
    if (!export_out.empty()) {
        ExportOptions eo;
        eo.format = plan.format == "obj" ? MeshFormat::obj : plan.format == "ply" ? MeshFormat::ply
                    : plan.format == "stl" ? MeshFormat::stl : MeshFormat::glb;
        std::string mesh;
        if (!(st = export_mesh(res.model, eo, &mesh))) return st;
        if (!(st = outputs.stage(export_out, mesh))) return st;
    }
    if (!(st = outputs.commit())) return st;
    char line[300];
    std::snprintf(line, sizeof line, "task %d (%s): %zu points, %zu faces from %d x %d in %.2f s", k, plan.tile_name(k).c_str(),
                  res.model.vertices.size(), res.model.faces.size(), image.width, image.height, seconds_since(t0));
    if (!opt.border_crossings.empty())
        std::snprintf(line + std::strlen(line), sizeof line - std::strlen(line), "; %zu side crossings, %zu reached by a detected edge",
                      opt.border_crossings.size(), res.stats.erd.joined_crossings);
    rep.note(line);
    return Status::success();
}

std::string json_list(const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + json_number(v[i]);
    return s + "]";
}

// --finish: every tile read back; its sides' vertices checked against the plan (the seams); the
// index; the merged mesh.
Status finish(const TilesPlan& plan, const std::string& dir, const Args& a, const Reporter& rep) {
    Status st;
    const std::string ext = model_ext(plan);
    std::string tiles = "[";
    long long faces = 0, copies = 0;
    const bool want_psnr = a.has("psnr-report");
    double sse = 0, worst = 0;
    imageio::RasterWindow rw;
    if (want_psnr && !(st = rw.open(plan.raster, raster_limits()))) return Status::bad_input(escape_name(plan.raster) + ": " + st.message);
    for (int k = 0; k < plan.grid.count(); ++k) {
        const std::string path = dir + "/" + plan.tile_name(k) + ext;
        Model m;
        std::string warning;
        if (!(st = load_model_file(path, &m, &warning))) return Status::bad_input(escape_name(path) + ": " + st.message);
        int x0, y0, x1, y1;
        plan.window(k, &x0, &y0, &x1, &y1);
        if (m.width != x1 - x0 + 1 || m.height != y1 - y0 + 1)
            return Status::bad_input(escape_name(path) + ": not the model of this tile");
        std::vector<LatticePoint> want = plan.side_points(k), have;
        for (LatticePoint p : plan.side_crossings(k)) want.push_back(p);
        const std::int32_t mx = 2 * (x1 - x0), my = 2 * (y1 - y0);
        for (LatticePoint p : m.vertices)
            if (p.x == 0 || p.y == 0 || p.x == mx || p.y == my) have.push_back(p);
        auto less = [](LatticePoint p, LatticePoint q) { return p.y != q.y ? p.y < q.y : p.x < q.x; };
        std::sort(want.begin(), want.end(), less);
        want.erase(std::unique(want.begin(), want.end(), [](LatticePoint p, LatticePoint q) { return p.x == q.x && p.y == q.y; }), want.end());
        std::sort(have.begin(), have.end(), less);
        bool same = want.size() == have.size();
        for (std::size_t i = 0; same && i < want.size(); ++i) same = want[i].x == have[i].x && want[i].y == have[i].y;
        if (!same)
            return Status::bad_input(escape_name(path) + ": its sides' vertices are not the plan's (" + std::to_string(have.size()) +
                                     " instead of " + std::to_string(want.size()) + "): the seam would crack");
        faces += (long long)m.faces.size();
        copies += (long long)m.vertices.size();
        if (want_psnr) {
            // The tile's own pixels: its window less its right column and bottom row, which the
            // next tile owns (the last column and row of the raster are the last tiles').
            Image orig, rec;
            if (!(st = rw.read(x0, y0, x1 + 1, y1 + 1, &orig))) return Status::bad_input(escape_name(plan.raster) + ": " + st.message);
            if (!(st = reconstruct(m, supersampled(m), &rec))) return st;
            const int ex = x1 == plan.grid.width - 1 ? x1 - x0 + 1 : x1 - x0, ey = y1 == plan.grid.height - 1 ? y1 - y0 + 1 : y1 - y0;
            const std::size_t w = std::size_t(x1 - x0 + 1);
            for (int y = 0; y < ey; ++y)
                for (int x = 0; x < ex; ++x) {
                    const std::size_t i = std::size_t(y) * w + std::size_t(x);
                    const double o = orig.real() ? orig.reals[i] : double(orig.samples[i]);
                    const double r = rec.real() ? rec.reals[i] : double(rec.samples[i]);
                    sse += (o - r) * (o - r);
                    worst = std::max(worst, std::fabs(o - r));
                }
        }
        JsonObject t;
        t.integer("task", k).integer("row", k / plan.grid.nx).integer("column", k % plan.grid.nx);
        t.raw("bounds", "[" + std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(x1) + "," + std::to_string(y1) + "]");
        t.str("file", plan.tile_name(k) + ext);
        if (!plan.format.empty()) t.str("export", plan.tile_name(k) + "." + plan.format);
        t.integer("budget", plan.points[std::size_t(k)]).integer("vertices", (long long)m.vertices.size());
        t.integer("faces", (long long)m.faces.size()).integer("side_vertices", (long long)have.size());
        tiles += (k ? "," : "") + t.text();
    }
    tiles += "]";
    long long border = 0;  // distinct vertices on the shared lines, counted once
    for (const auto& l : plan.vborder)
        for (const auto& b : l) border += (long long)b.size() - 2;
    for (const auto& l : plan.hborder)
        for (const auto& b : l) border += (long long)b.size() - 2;
    for (const auto* c : {&plan.vcross, &plan.hcross})
        for (const auto& l : *c)
            for (const auto& b : l) border += (long long)b.size();
    border += (long long)(plan.grid.nx + 1) * (plan.grid.ny + 1);
    long long side_sum = 0;
    for (int k = 0; k < plan.grid.count(); ++k) {
        side_sum += (long long)(plan.side_points(k).size() + plan.side_crossings(k).size()) - 4;
    }
    JsonObject idx;
    idx.str("format", "erd-tiles-index 1").str("raster", plan.raster).str("method", plan.method);
    idx.integer("width", plan.grid.width).integer("height", plan.grid.height).integer("tile", plan.grid.tile);
    idx.raw("grid", "[" + std::to_string(plan.grid.nx) + "," + std::to_string(plan.grid.ny) + "]");
    idx.integer("vertices", copies - side_sum + border).integer("faces", faces).integer("border_vertices", border);
    if (want_psnr) {
        const double peak = plan.real ? plan.hi - plan.lo : double(plan.maxval);
        const double mse = sse / (double(plan.grid.width) * double(plan.grid.height));
        const double db = mse > 0 ? 10.0 * std::log10(peak * peak / mse) : INFINITY;
        idx.num("psnr", db).num("max_error", worst);
        char line[120];
        std::snprintf(line, sizeof line, "erd tiles: psnr: %.4f dB, largest error %.6g", db, worst);
        std::fprintf(stderr, "%s\n", line);
    }
    if (!plan.geo.empty()) {
        JsonObject geo;
        if (!plan.geo.pixel_scale.empty()) geo.raw("pixel_scale", json_list(plan.geo.pixel_scale));
        if (!plan.geo.tiepoints.empty()) geo.raw("tiepoints", json_list(plan.geo.tiepoints));
        if (!plan.geo.transform.empty()) geo.raw("transformation", json_list(plan.geo.transform));
        idx.object("georeferencing", geo);
    }
    idx.raw("tiles", tiles);
    Outputs outputs;
    const std::string index = dir + "/index.json";
    const std::string merge = a.str("merge");
    std::vector<std::string> outs = {index};
    if (!merge.empty()) outs.push_back(merge);
    if (!(st = outputs.check(outs, {plan.raster}))) return st;
    if (!(st = outputs.stage(index, idx.text() + "\n"))) return st;
    if (!merge.empty()) {
        double zs = plan.real ? (plan.hi > plan.lo ? std::max(plan.grid.width, plan.grid.height) / (10.0 * (plan.hi - plan.lo)) : 1.0)
                              : std::max(plan.grid.width, plan.grid.height) / (10.0 * double(std::max<std::uint32_t>(1, plan.maxval)));
        if (a.has("zscale")) {
            zs = a.real("zscale", zs, -1e300, 1e300, &st);
            if (!st) return st;
        }
        MergeCounts mc;
        st = outputs.stage_stream(merge, [&](int fd) { return write_merged(plan, dir, merge, zs, fd, &mc); });
        if (!st) return st;
        rep.note("merged " + std::to_string(mc.vertices) + " vertices, " + std::to_string(mc.faces) + " faces -> " + merge);
    }
    if (!(st = outputs.commit())) return st;
    rep.note(std::to_string(plan.grid.count()) + " tiles, " + std::to_string(faces) + " faces, seams checked -> " + index);
    return Status::success();
}

int run_tiles(const Args& a, const Reporter& rep) {
    if (!a.has("output")) return rep.usage("-o DIR is required");
    const std::string dir = a.str("output");
    if (dir.empty()) return rep.usage("empty -o folder name");
    const int modes = int(a.has("plan")) + int(a.has("task")) + int(a.has("finish"));
    if (modes > 1) return rep.usage("--plan, --task and --finish are separate steps: one at a time");
    if (a.has("merge") && !merge_format_known(a.str("merge"))) return rep.usage("--merge writes .obj, .ply, .stl or .glb");
    if ((a.has("merge") || a.has("zscale")) && (a.has("plan") || a.has("task")))
        return rep.usage("--merge and --zscale go with --finish (or the whole run)");
    Status st;
    if (a.has("task") || a.has("finish")) {
        for (const OptionSpec& o : tiles_command_line().options) {
            const std::string n = o.long_name;
            if (a.has(o.long_name) && n != "output" && n != "task" && n != "finish" && n != "merge" && n != "zscale" && n != "psnr-report" && n != "quiet" &&
                n != "verbose")
                return rep.fail(Status::bad_input("--" + n + ": a task and --finish take their options from " + plan_path(dir)));
        }
        TilesPlan plan;
        if (!(st = load_plan(dir, &plan))) return rep.fail(st);
        if (a.has("task")) {
            const int k = int(a.integer("task", -1, 0, INT_MAX, &st));
            if (!st) return rep.usage(st.message);
            st = run_task(plan, dir, k, rep);
        } else {
            st = finish(plan, dir, a, rep);
        }
        return st ? 0 : rep.fail(st);
    }
    if (!a.has("method")) return rep.usage("-m METHOD is required (gpi or erdgpi)");
    if (!a.has("input")) return rep.usage("-i RASTER is required");
    if (!a.has("tile")) return rep.usage("--tile T is required");
    TilesPlan plan;
    if (!(st = make_plan(a, dir, &plan))) return rep.fail(st);
    if (!(st = make_dir(dir))) return rep.fail(st);  // after the plan: a refused run leaves no folder
    if (!(st = write_file_atomic(plan_path(dir), plan_text(plan)))) return rep.fail(st);
    if (a.has("plan")) {
        rep.note(std::to_string(plan.grid.count()) + " tasks (" + std::to_string(plan.grid.nx) + " x " + std::to_string(plan.grid.ny) +
                 " tiles) -> " + plan_path(dir));
        return 0;
    }
    for (int k = 0; k < plan.grid.count(); ++k)
        if (!(st = run_task(plan, dir, k, rep))) return rep.fail(st);
    st = finish(plan, dir, a, rep);
    return st ? 0 : rep.fail(st);
}

}  // namespace

int cmd_tiles(int argc, char** argv) { return run_command(tiles_command_line(), argc, argv, run_tiles); }

}  // namespace erd::cli
