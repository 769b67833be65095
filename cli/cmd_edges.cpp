// erd edges IMAGE -o EDGES [-p POLYLINES] [--draw-polylines FILE] [-b beta -r r -e eps -l len]
// [--plain-canny]: the first stage of ERDED and ERDGPI (thesis 3.4.1 steps 1.1-1.3) on its own,
// so each stage can be looked at: the half-pixel edge map and the simplified polylines.
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/imaging/bilinear.h"
#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/model/model_io.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "cli/outputs.h"
#include "cli/report.h"

namespace erd::cli {

namespace {

// Edge map as an 8-bit image: 255 = edge, 0 = background.
Image edge_image(const Grid<std::uint8_t>& edges) {
    Image im(edges.width, edges.height, 255);
    for (std::size_t i = 0; i < edges.data.size(); ++i) im.samples[i] = edges.data[i] ? 255 : 0;
    return im;
}

// The simplified polylines drawn in black on the half-pixel grid (so the picture has the edge
// map's size and coordinates), kept vertices as 3x3 dots; on white, or over a lightened copy of
// phi_bar (larger files).
Image polyline_image(const Image& src, const std::vector<Polyline>& lines, bool over_image) {
    const Grid<double> hp = half_pixel(to_grid(src));
    Image im(hp.width, hp.height, 255);
    const double scale = src.maxval > 0 ? 255.0 / src.maxval : 1.0;
    for (std::size_t i = 0; i < hp.data.size(); ++i)
        im.samples[i] = over_image ? std::uint16_t(140.0 + 0.45 * hp.data[i] * scale + 0.5) : 255;
    auto plot = [&](int x, int y, std::uint16_t v) {
        if (x >= 0 && y >= 0 && x < im.width && y < im.height) im.at(x, y) = v;
    };
    for (const Polyline& l : lines) {
        for (std::size_t k = 0; k + 1 < l.size(); ++k) {
            // Bresenham between consecutive vertices.
            int x0 = l[k].x, y0 = l[k].y;
            const int x1 = l[k + 1].x, y1 = l[k + 1].y;
            const int dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y0 - y1 : y1 - y0;
            const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
            int err = dx + dy;
            for (;;) {
                plot(x0, y0, 0);
                if (x0 == x1 && y0 == y1) break;
                const int e2 = 2 * err;
                if (e2 >= dy) { err += dy; x0 += sx; }
                if (e2 <= dx) { err += dx; y0 += sy; }
            }
        }
        for (LatticePoint p : l)
            for (int oy = -1; oy <= 1; ++oy)
                for (int ox = -1; ox <= 1; ++ox) plot(p.x + ox, p.y + oy, 0);
    }
    return im;
}

const CommandLine kEdges = {
    "edges",
    "erd edges IMAGE -o EDGES [-p POLYLINES] [--draw-polylines FILE] [-b beta -r r -e eps -l len]",
    "Locates edges at half-pixel resolution (modified Canny on the bilinear interpolant,\n"
    "thesis 3.4.1 step 1.1), traces them into polylines and simplifies them (steps 1.2, 1.3).\n"
    "Statistics go to stderr.",
    {
        {'o', "output", "FILE", "edge map, (2W-1) x (2H-1), 255 = edge (.png -> PNG, else PGM)"},
        {'p', "polylines", "FILE", "simplified polylines, format erd-polylines 1 (doubled coordinates)"},
        {0, "draw-polylines", "FILE", "picture of the simplified polylines (half-pixel grid, black on white)"},
        {0, "over-image", nullptr, "draw the polylines over a lightened copy of the image"},
        {0, "gray", nullptr, "colour input: detect edges on its BT.601 luma without a warning"},
        {'b', "beta", "X", "fraction of half-pixel grid points at or above tau_high (default 0.055)"},
        {'r', "ratio", "X", "tau_low = r * tau_high (default 0.4)"},
        {'e', "tolerance", "X", "Douglas-Peucker tolerance in pixels, as erd generate -e (default 1)"},
        {'l', "min-length", "N", "drop polylines traced with fewer than N points (default 5)"},
        {0, "length-after", nullptr, "count -l on the simplified polyline instead"},
        {0, "plain-canny", nullptr, "plain Canny (no junction repair of Ding and Goshtasby)"},
        kProgressOption,
    },
    "no warnings or statistics", 1, 1, "expected one IMAGE",
};

}  // namespace

static int run_edges(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("missing -o EDGES");

    Status st;
    // The library's defaults (algorithms/imaging/edge_polylines.h), as erd generate starts from.
    EdgePolylineParams params;
    params.canny.beta = args.real("beta", params.canny.beta, 1e-9, 1.0, &st);
    if (st) params.canny.r = args.real("ratio", params.canny.r, 0.0, 1.0, &st);
    if (st) params.epsilon = args.real("tolerance", params.epsilon, 0.0, 1e6, &st);
    if (st) params.min_length = int(args.integer("min-length", params.min_length, 0, 1000000000, &st));
    if (!st) return rep.usage(st.message);
    params.canny.modified = !args.has("plain-canny");
    if (args.has("length-after")) params.length_rule = LengthRule::after_simplification;

    const std::string in = args.positional()[0];
    std::vector<std::string> outs = {args.str("output")};
    if (args.has("polylines")) outs.push_back(args.str("polylines"));
    if (args.has("draw-polylines")) outs.push_back(args.str("draw-polylines"));
    Outputs outputs;
    if (!(st = outputs.check(outs, {in}))) return rep.fail(st);

    Image im;
    if (!(st = read_input_image(in, args.has("gray") ? ColourInput::luma_asked : ColourInput::luma_warn, rep, &im)))
        return rep.fail(st);

    EdgePolylineResult chain;
    {
        Progress progress = progress_for("edges", args, rep);
        params.progress = progress.hook();
        st = edge_polylines(im, params, &chain);
    }
    if (!st) return rep.fail(st);
    const Grid<std::uint8_t>& edges = chain.edges;
    const CannyStats& stats = chain.stats;
    const std::vector<Polyline>& lines = chain.polylines;
    std::size_t points = 0;
    for (const Polyline& l : lines) points += l.size();
    rep.note("tau_high " + std::to_string(stats.tau_high) + ", tau_low " + std::to_string(stats.tau_low) + ", " +
             std::to_string(stats.edge_points) + " edge points (" + std::to_string(stats.added_points) +
             " added at junctions), " + std::to_string(chain.traced) + " traced polylines, " +
             std::to_string(lines.size()) + " kept with " + std::to_string(points) + " vertices");

    // All outputs committed together at the end: a failure leaves every old file as it was.
    std::string bytes;
    if (!(st = encode_image(args.str("output"), edge_image(edges), WriteOptions(), &bytes)) ||
        !(st = outputs.stage(args.str("output"), bytes)))
        return rep.fail(st);
    if (args.has("polylines")) {
        std::string text;
        write_polylines(lines, &text);
        if (!(st = outputs.stage(args.str("polylines"), text))) return rep.fail(st);
    }
    if (args.has("draw-polylines")) {
        const std::string draw = args.str("draw-polylines");
        if (!(st = encode_image(draw, polyline_image(im, lines, args.has("over-image")), WriteOptions(), &bytes)) ||
            !(st = outputs.stage(draw, bytes)))
            return rep.fail(st);
    }
    if (!(st = outputs.commit())) return rep.fail(st);
    return 0;
}

int cmd_edges(int argc, char** argv) { return run_command(kEdges, argc, argv, run_edges); }

}  // namespace erd::cli
