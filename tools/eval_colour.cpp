// eval_colour: one colour run of a method through the library, for tools/eval_colour.sh and
// bench/run.sh (the erd program reads colour files once the colour readers are in cli/).
//
//   eval_colour [flags] METHOD DENSITY IMAGE.ppm
//     --luma               run the gray method on the image's luma (the cost baseline)
//     --sum-channels       greedy candidate by the sum of squared channel errors (ColourChoices)
//     --density sum|max|luma   ED/ERDED MMSODD over the channels
//     --shared             one wedge line-search position for all channels
//     --luma-greedy        ERDGPI's greedy loop on the luma (the cheap alternative)
//     --edges luma|dizenzo|max  ERD step 1's gradient (ColourChoices::edges)
//     --fit N              wedge refit iterations (GenerateOptions::wedge_fit)
//     --flips N            rounds of data-dependent flips after the refit (GenerateOptions::flips)
//     --real               greedy errors against the real-valued planes (round_values off)
//     --verify             also check the mesh: the triangulation of its points and constraints
//                          (with the flips that give its faces: api::triangulate) is valid and has
//                          its faces, every wedge's faces carry one value in every channel
//     --no-psnr            stop after the method (bench/run.sh: load and mesh only); prints N
//     --write-luma FILE    write the image's luma as an 8-bit P5 and stop (bench/run.sh's gray
//                          side of the colour rows: erd generate on it)
// Prints "PSNR VERTICES": the RGB-PSNR (MSE averaged over the channels and pixels, peak 255) of
// the model's reconstruction.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "algorithms/imaging/colour.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/reconstruct.h"
#include "api/erd.h"
#include "kernel/cdt.h"

namespace {

// A P6 8-bit reader for the test images alone (no comments, maxval 255).
bool read_p6(const char* path, erd::Image* im) {
    FILE* f = std::fopen(path, "rb");
    if (!f) return false;
    int w = 0, h = 0, mv = 0;
    const bool ok = std::fscanf(f, "P6 %d %d %d", &w, &h, &mv) == 3 && mv == 255 && w > 0 && h > 0 && std::fgetc(f) != EOF;
    if (ok) {
        *im = erd::Image(w, h, 255, 3);
        std::vector<unsigned char> buf(im->samples.size());
        if (std::fread(buf.data(), 1, buf.size(), f) != buf.size()) w = 0;
        for (std::size_t i = 0; i < buf.size(); ++i) im->samples[i] = buf[i];
    }
    std::fclose(f);
    return ok && w > 0;
}

// The triangulation of m's points and constraints, with the flips that give m's faces where
// they are not Delaunay (api::triangulate, as the ERD methods' data-dependent flips made them),
// is valid and has m's faces; in every channel each wedge's faces carry one corner value (ERD
// models). Returns the first problem, or "".
std::string verify(const erd::Model& m) {
    erd::Cdt cdt;
    std::string why;
    if (!erd::api::triangulate(m, &cdt)) return "rebuild failed";
    if (!cdt.verify_topology(&why)) return why;
    if (cdt.face_count() != m.faces.size() || cdt.vertex_count() != m.vertices.size()) return "face or vertex count";
    // Model face and corner of (point of corner, point of next corner).
    std::map<std::pair<std::uint64_t, std::uint64_t>, std::pair<std::size_t, int>> corner;
    const auto key = [](erd::LatticePoint p) { return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x); };
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        for (int i = 0; i < 3; ++i)
            corner[{key(m.vertices[m.faces[f][std::size_t(i)]]), key(m.vertices[m.faces[f][std::size_t((i + 1) % 3)]])}] = {f, i};
    if (m.kind != erd::ModelKind::erd) return "";
    const std::size_t C = std::size_t(m.channels);
    std::vector<erd::Wedge> wedges;
    for (erd::VertInd v = 0; v < cdt.vertex_count(); ++v) {
        cdt.wedges(v, &wedges);
        for (const erd::Wedge& w : wedges) {
            erd::EdgeInd e = w.first;
            std::vector<double> ref;
            for (std::uint32_t k = 0; k < w.count; ++k, e = cdt.rot_next(e)) {
                const auto it = corner.find({key(cdt.point(cdt.org(e))), key(cdt.point(cdt.dest(e)))});
                if (it == corner.end()) return "a face of the rebuilt CDT is not in the model";
                const auto [f, i] = it->second;
                std::vector<double> z(C);
                for (std::size_t c = 0; c < C; ++c) z[c] = m.corner_values[f * C + c][std::size_t(i)];
                if (k == 0) ref = z;
                else if (z != ref) return "a wedge's faces carry different values";
            }
        }
    }
    return "";
}

}  // namespace

int main(int argc, char** argv) {
    erd::GenerateOptions o;
    bool luma = false, measure = true, check = false;
    const char* luma_out = nullptr;
    int i = 1;
    for (; i < argc && argv[i][0] == '-' && argv[i][1] == '-'; ++i) {
        const std::string a = argv[i];
        if (a == "--luma") luma = true;
        else if (a == "--no-psnr") measure = false;
        else if (a == "--verify") check = true;
        else if (a == "--real") o.round_values = false;
        else if (a == "--write-luma" && i + 1 < argc) luma_out = argv[++i];
        else if (a == "--sum-channels") o.colour.max_channel_error = false;
        else if (a == "--shared") o.colour.shared_wedge_position = true;
        else if (a == "--luma-greedy") o.colour.greedy_on_luma = true;
        else if (a == "--fit" && i + 1 < argc) o.wedge_fit = std::atoi(argv[++i]);
        else if (a == "--flips" && i + 1 < argc) o.flips = std::atoi(argv[++i]);
        else if (a == "--edges" && i + 1 < argc) {
            const std::string e = argv[++i];
            o.colour.edges = e == "dizenzo" ? erd::ColourGradient::dizenzo : e == "max" ? erd::ColourGradient::max : erd::ColourGradient::luma;
        } else if (a == "--density" && i + 1 < argc) {
            const std::string d = argv[++i];
            o.colour.density = d == "max" ? erd::ColourDensity::max : d == "luma" ? erd::ColourDensity::luma : erd::ColourDensity::sum;
        } else {
            std::fprintf(stderr, "eval_colour: unknown flag %s\n", argv[i]);
            return 2;
        }
    }
    if (argc - i != 3) {
        std::fprintf(stderr, "usage: eval_colour [flags] METHOD DENSITY IMAGE.ppm\n");
        return 2;
    }
    const erd::MethodInfo* method = erd::find_method(argv[i]);
    erd::Image im;
    if (!method || !read_p6(argv[i + 2], &im)) {
        std::fprintf(stderr, "eval_colour: unknown method or unreadable P6 image\n");
        return 2;
    }
    if (luma || luma_out) im = erd::luma_of(im);
    if (luma_out) {
        FILE* f = std::fopen(luma_out, "wb");
        bool ok = f && std::fprintf(f, "P5\n%d %d\n255\n", im.width, im.height) > 0;
        for (std::size_t k = 0; ok && k < im.samples.size(); ++k) ok = std::fputc(int(im.samples[k]), f) != EOF;
        if (f && std::fclose(f) != 0) ok = false;
        if (!ok) std::fprintf(stderr, "eval_colour: cannot write %s\n", luma_out);
        return ok ? 0 : 1;
    }
    o.density = std::atof(argv[i + 1]);
    o.density_given = true;
    erd::GenerateResult r;
    const erd::Status st = method->run(im, o, &r);
    if (!st) {
        std::fprintf(stderr, "eval_colour: %s\n", st.message.c_str());
        return 1;
    }
    if (check) {
        const std::string why = verify(r.model);
        if (!why.empty()) {
            std::fprintf(stderr, "eval_colour: the mesh does not verify: %s\n", why.c_str());
            return 1;
        }
    }
    if (!measure) {
        std::printf("%zu\n", r.model.size());
        return 0;
    }
    erd::Image rec;
    if (!erd::reconstruct(r.model, erd::supersampled(r.model), &rec) || rec.samples.size() != im.samples.size()) {
        std::fprintf(stderr, "eval_colour: reconstruction failed\n");
        return 1;
    }
    // The colour MSE by hand until algorithms/model/metrics compares colour images (colour-io).
    double sse = 0;
    for (std::size_t k = 0; k < im.samples.size(); ++k) {
        const double e = double(im.samples[k]) - double(rec.samples[k]);
        sse += e * e;
    }
    std::printf("%.4f %zu\n", 10.0 * std::log10(255.0 * 255.0 * double(im.samples.size()) / sse), r.model.size());
    return 0;
}
