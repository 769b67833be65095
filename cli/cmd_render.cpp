// erd render MODEL -o OUT.svg|OUT.png: a picture of the mesh, drawn to scale, optionally over the
// original image, the model's own reconstruction, or an error map.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/imaging/luma.h"
#include "algorithms/model/reconstruct.h"
#include "algorithms/output/render.h"
#include "algorithms/output/vector_svg.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "cli/model_file.h"
#include "cli/output_format.h"

namespace erd::cli {

static std::string base64(const std::vector<unsigned char>& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((in.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < in.size(); i += 3) {
        unsigned v = unsigned(in[i]) << 16;
        if (i + 1 < in.size()) v |= unsigned(in[i + 1]) << 8;
        if (i + 2 < in.size()) v |= in[i + 2];
        out += abc[(v >> 18) & 63];
        out += abc[(v >> 12) & 63];
        out += i + 1 < in.size() ? abc[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? abc[v & 63] : '=';
    }
    return out;
}

// PNG bytes of an RGB picture, stored as gray when all three channels agree (a third the size).
static Status encode_rgb_png(const RgbImage& im, std::vector<unsigned char>* png) {
    Image rgb(im.width, im.height, 255, 3);
    for (std::size_t i = 0; i < rgb.samples.size(); ++i) rgb.samples[i] = im.pixels[i];
    gray_if_channels_equal(&rgb);
    std::string bytes;
    Status st = encode_png(rgb, &bytes);
    if (st) png->assign(bytes.begin(), bytes.end());
    return st;
}

// "X,Y,W,H" in pixels: four decimal integers, X, Y >= 0, W, H > 0, each below 2^31.
static bool parse_crop(const std::string& s, RenderOptions* o) {
    long v[4];
    const char* p = s.c_str();
    for (int i = 0; i < 4; ++i) {
        if (*p < '0' || *p > '9') return false;
        char* end = nullptr;
        errno = 0;
        v[i] = std::strtol(p, &end, 10);
        if (errno != 0 || v[i] > 0x7fffffffL) return false;
        p = end;
        if (i < 3 && *p++ != ',') return false;
    }
    if (*p != '\0' || v[2] <= 0 || v[3] <= 0) return false;
    o->crop_x = int(v[0]);
    o->crop_y = int(v[1]);
    o->crop_w = int(v[2]);
    o->crop_h = int(v[3]);
    return true;
}

const CommandLine kRender = {
    "render",
    "erd render MODEL -o OUT.svg|OUT.png [--scale S] [--crop X,Y,W,H] [--vertices] [--no-edges]\n"
    "                  [--over IMAGE | --over-reconstruction | --error ORIGINAL [--error-max E]]\n"
    "       erd render MODEL -o OUT.svg --vector [--scale S] [--crop X,Y,W,H] [--seams layered|crisp|none] [--ramp levels|smooth]",
    "Draws the triangulation of a .model or .erd file: ordinary edges thin and blue, constrained edges\n"
    "(the model's discontinuities: where the two faces beside an edge of an .erd model give an endpoint\n"
    "different values) thick and red. SVG is written as text; PNG is drawn with anti-aliased lines.",
    {
        {'o', "output", "FILE", "output picture: FILE.svg or FILE.png (\"-\" = stdout with --format)"},
        {0, "format", "svg|png", "output format when the file name does not say"},
        {'s', "scale", "S", "output pixels per image pixel (default: 1, or the smallest integer making the larger side >= 512)"},
        {0, "crop", "X,Y,W,H", "draw only this window of the image (pixels)"},
        {0, "vertices", nullptr, "draw the vertices as dots"},
        {0, "no-edges", nullptr, "draw no triangulation (just the background)"},
        {0, "over", "IMAGE", "draw over this image (the original)"},
        {0, "over-reconstruction", nullptr, "draw over the model's own reconstruction (4x4 supersampled for a soft-edged .erd)"},
        {0, "error", "ORIGINAL", "draw over the error map |ORIGINAL - reconstruction| (black 0 .. white >= --error-max)"},
        {0, "error-max", "E", "error shown as white in the error map (default maxval / 8)"},
        {0, "vector", nullptr, "SVG of the approximating function itself: each face a triangle filled with its plane as a linear gradient"},
        {0, "seams", "layered|crisp|none", "--vector: how seams between anti-aliased triangles are avoided (default layered)"},
        {0, "ramp", "levels|smooth", "--vector: each face's gradient paints its plane rounded to 8-bit levels as erd reconstruct does (default), or the plane itself"},
        kProgressOption,
    },
    "no warnings", 1, 1, "expected one MODEL",
};

static int run_render(const Args& args, const Reporter& rep) {
    if (!args.has("output")) return rep.usage("-o OUT.svg or OUT.png is required");
    const std::string in = args.positional()[0], out = args.str("output");
    std::string format;
    Status st = output_format(args.str("format"), out, "svg", "png", &format);
    if (!st) return rep.usage(st.message);
    int backgrounds = int(args.has("over")) + int(args.has("over-reconstruction")) + int(args.has("error"));
    if (backgrounds > 1) return rep.usage("give at most one of --over, --over-reconstruction, --error");

    RenderOptions opt;
    opt.scale = args.real("scale", 0, 1e-3, 1e4, &st);
    if (!st) return rep.usage(st.message);
    if (args.has("crop") && !parse_crop(args.str("crop"), &opt))
        return rep.usage("--crop wants X,Y,W,H (integers, W and H > 0), not '" + args.str("crop") + "'");
    double error_max = args.real("error-max", 0, 1e-9, 1e9, &st);
    if (!st) return rep.usage(st.message);
    const bool vector = args.has("vector");
    VectorSvgOptions vopt;
    if (vector) {
        if (format != "svg") return rep.usage("--vector writes SVG only");
        if (backgrounds > 0 || args.has("vertices") || args.has("no-edges"))
            return rep.usage("--vector draws the surface alone: no --over, --over-reconstruction, --error, --vertices, --no-edges");
        const std::string seams = args.str("seams", "layered");
        if (seams == "layered") vopt.seams = SeamFix::layered;
        else if (seams == "crisp") vopt.seams = SeamFix::crisp;
        else if (seams == "none") vopt.seams = SeamFix::none;
        else return rep.usage("--seams wants layered, crisp or none, not '" + seams + "'");
        const std::string ramp = args.str("ramp", "levels");
        if (ramp == "levels") vopt.ramp = Ramp::levels;
        else if (ramp == "smooth") vopt.ramp = Ramp::smooth;
        else return rep.usage("--ramp wants levels or smooth, not '" + ramp + "'");
        vopt.scale = opt.scale > 0 ? opt.scale : 1;
        vopt.crop_x = opt.crop_x, vopt.crop_y = opt.crop_y, vopt.crop_w = opt.crop_w, vopt.crop_h = opt.crop_h;
    } else if (args.has("seams") || args.has("ramp")) {
        return rep.usage(std::string(args.has("seams") ? "--seams" : "--ramp") + " goes with --vector");
    }
    opt.vertices = args.has("vertices");
    opt.edges = !args.has("no-edges");

    std::vector<std::string> inputs = {in};
    if (args.has("over")) inputs.push_back(args.str("over"));
    if (args.has("error")) inputs.push_back(args.str("error"));
    Model m;
    if (!(st = load_input_model(out, inputs, rep, &m))) return rep.fail(st);
    if (vector) {
        std::string svg;
        st = render_vector_svg(m, vopt, &svg);
        if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
        st = write_file_atomic(out, svg);
        return st ? 0 : rep.fail(st);
    }
    Progress progress = progress_for("render", args, rep);
    opt.progress = progress.hook();
    RenderOptions resolved;
    st = resolve_render(m, opt, &resolved);
    if (!st) return rep.fail(st);

    // The background, in image pixels.
    bool have_bg = false;
    RgbImage bg;
    if (args.has("over") || args.has("error")) {
        const std::string path = args.has("over") ? args.str("over") : args.str("error");
        Image im;
        // --over draws a colour image in colour; --error compares it with the reconstruction's
        // values, channel by channel for a colour model (error_map shows the worst), else in gray.
        st = read_input_image(path, args.has("error") && m.channels == 1 ? ColourInput::luma_warn : ColourInput::keep, rep, &im);
        if (!st) return rep.fail(st);
        if (im.width != m.width || im.height != m.height)
            return rep.fail(Status::bad_input(path + ": image is " + std::to_string(im.width) + "x" + std::to_string(im.height) +
                                              " but the model is " + std::to_string(m.width) + "x" + std::to_string(m.height)));
        if (args.has("over")) {
            bg = image_to_rgb(im);
        } else {
            Image approx;
            st = reconstruct(m, supersampled(m), &approx, progress.hook());
            if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
            approx.maxval = im.maxval;
            st = error_map(im, approx, error_max, &bg);
            if (!st) return rep.fail(Status::error(st.code, path + ": " + st.message));
        }
        have_bg = true;
    } else if (args.has("over-reconstruction")) {
        Image approx;
        st = reconstruct(m, supersampled(m), &approx, progress.hook());
        if (!st) return rep.fail(Status::error(st.code, in + ": " + st.message));
        bg = image_to_rgb(approx);
        have_bg = true;
    }

    std::string bytes;
    if (format == "svg") {
        std::string href;
        if (have_bg) {
            std::vector<unsigned char> png;
            st = encode_rgb_png(bg, &png);
            if (!st) return rep.fail(st);
            href = "data:image/png;base64," + base64(png);
        }
        st = render_svg(m, href, opt, &bytes);
        if (!st) return rep.fail(st);
    } else {
        RgbImage pic;
        st = render_raster(m, have_bg ? &bg : nullptr, opt, &pic);
        progress.finish();
        if (!st) return rep.fail(st);
        std::vector<unsigned char> png;
        st = encode_rgb_png(pic, &png);
        if (!st) return rep.fail(st);
        bytes.assign(png.begin(), png.end());
    }
    st = write_file_atomic(out, bytes);
    if (!st) return rep.fail(st);
    return 0;
}

int cmd_render(int argc, char** argv) { return run_command(kRender, argc, argv, run_render); }

}  // namespace erd::cli
