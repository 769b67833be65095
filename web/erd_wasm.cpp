// The C entry points of erd's WebAssembly build (make web): the page's worker passes pixels in
// and reads the results out of the module's memory. One job at a time (the worker is serial),
// so the results live in one static slot until the next erd_mesh call. Progress goes to the page
// as it happens: the library's progress hook posts a message from the worker (EM_JS), at most
// once per stage and per whole percent. The page hands every image over as RGB; it becomes gray
// here, by the library's own rules as the command line's reader applies them (channels all equal,
// or --gray), so the page meshes what `erd generate` meshes for the same file. The page draws
// the mesh itself from erd_mesh_vertices/faces/constraints; its opening picture is erd_builtin.
#include <emscripten.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/luma.h"
#include "algorithms/imaging/synth.h"
#include "algorithms/model/model_io.h"
#include "algorithms/output/vector_svg.h"
#include "api/erd.h"

EM_JS(void, erd_post_progress, (const char* stage, double fraction),
      { postMessage({progress : UTF8ToString(stage), fraction : fraction}); });

namespace {

struct Job {
    erd::Model model;
    std::string error, model_text, vector_svg, timings, edge_kinds;
    std::vector<std::uint8_t> recon;
    std::vector<std::int32_t> vertices_xy;  // doubled coordinates, x y per vertex
    double psnr = 0;
    std::size_t vertices = 0;
    int channels = 1;
};
Job job;
std::vector<std::uint8_t> builtin;

// The opening picture's colours: a ramp through these (gray level, R, G, B) stops, night blue to
// cream, linear between them in integers (rounded half up; the same bytes everywhere).
constexpr int kStops[][4] = {{0, 20, 24, 60}, {90, 40, 90, 140}, {170, 230, 140, 60}, {255, 250, 240, 210}};

struct Posted {
    std::string stage;
    int percent = -1;
};

void on_progress(void* ctx, const char* stage, double fraction) {
    auto* last = static_cast<Posted*>(ctx);
    int percent = int(fraction * 100);
    if (last->stage == stage && last->percent == percent) return;
    last->stage = stage;
    last->percent = percent;
    erd_post_progress(stage, fraction);
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// "name ms" lines, the page's timing table.
void add_timing(const std::string& name, double ms) { job.timings += name + " " + std::to_string(ms) + "\n"; }

}  // namespace

extern "C" {

// Meshes a w x h 8-bit RGB image (interleaved R G B) with `method` ("ed", "gpi", "erded", "erdgpi") at `density`
// percent, as `erd generate -x 1` with these flags does, then reconstructs it (4x4 for soft ERD
// models, as `erd reconstruct`) and measures the PSNR. edges: 0 auto, 1 soft, 2 hard (--edges);
// thesis: --thesis (applied first, so the other flags given beside it win, as on the command
// line); wedge_rule: -w; wedge_fit: --wedge-fit; psnr: --psnr (0 off); max_error: --max-error
// (negative off); gray: --gray (mesh the luma of a colour image). An image whose channels are
// equal at every pixel is meshed gray, as erd reads it. The reconstruction has the model's
// channels (erd_channels()), the PSNR is over all of them (`erd psnr`). The model stays for
// erd_files(). Returns 0, or the status code with erd_error() set.
int erd_mesh(const std::uint8_t* rgb, int w, int h, const char* method, double density, int edges, int thesis,
             int wedge_rule, int wedge_fit, double psnr, double max_error, int gray) {
    job = Job{};
    const auto t0 = Clock::now();
    erd::Image image(w, h, 255, 3);
    std::copy(rgb, rgb + image.samples.size(), image.samples.begin());
    erd::gray_if_channels_equal(&image);
    if (gray) image = erd::luma(image);
    const erd::api::ImageView view = erd::api::view_of(image);
    erd::api::Method m;
    erd::Status st = erd::api::method_from_name(method, &m);
    erd::api::Options opt;
    erd::GenerateOptions& g = opt.generate;
    if (thesis) erd::set_thesis_preset(&g);
    g.density = density;
    g.density_given = true;
    g.edges = edges == 1 ? erd::EdgeChoice::soft : edges == 2 ? erd::EdgeChoice::hard : erd::EdgeChoice::automatic;
    g.wedge_rule = wedge_rule;
    g.wedge_fit = wedge_fit;
    g.psnr = psnr;
    g.max_error = max_error;
    opt.exact = erd::api::ExactMode::warn;
    Posted posted;
    g.progress = erd::ProgressHook{&on_progress, &posted};
    erd::Model& model = job.model;
    erd::api::GenerateInfo info;
    if (st) st = erd::api::generate(m, view, opt, &model, &info);
    for (const erd::StageTime& s : info.stages) add_timing(s.name, s.seconds * 1000);
    add_timing("generate, all stages", ms_since(t0));
    erd::Image approx;
    auto t1 = Clock::now();
    if (st) erd_post_progress("reconstruction", 0);
    if (st) st = erd::api::reconstruct(model, erd::supersampled(model), &approx);
    if (st) st = erd::api::psnr(view, erd::api::view_of(approx), &job.psnr);
    add_timing("reconstruction", ms_since(t1));
    if (!st) {
        job.error = st.message;
        return st.exit_code();
    }
    job.vertices = model.vertices.size();
    job.channels = model.channels;
    job.vertices_xy.reserve(2 * model.vertices.size());
    for (const erd::LatticePoint& p : model.vertices) job.vertices_xy.insert(job.vertices_xy.end(), {p.x, p.y});
    // The kinds of its edges (algorithms/model/edge_kinds.h): "hard", "soft", "hard, 75 soft", ...
    job.edge_kinds.clear();
    if (model.kind == erd::ModelKind::erd) {
        const bool hard = model.edges == erd::EdgeKind::hard;
        job.edge_kinds = hard ? "hard" : "soft";
        if (!model.kind_exceptions.empty())
            job.edge_kinds += ", " + std::to_string(model.kind_exceptions.size()) + (hard ? " soft" : " hard");
    }
    job.recon.resize(approx.samples.size());
    for (std::size_t i = 0; i < approx.samples.size(); ++i) job.recon[i] = std::uint8_t(approx.samples[i]);
    return 0;
}

// The kinds of the last erd_mesh's model's edges ("" for a basic model): its kind, and how many
// edges are of the other one (issue 44), e.g. "hard, 75 soft".
const char* erd_edge_kinds() { return job.edge_kinds.c_str(); }

// The page's opening picture, w x h RGB: `erd synth -W w -H h` (a ramp, a bump, two discs, a
// triangle and a slanted step, mild noise; seed 1) with its gray levels coloured by kStops. Null
// when w x h is outside synth's limits.
const std::uint8_t* erd_builtin(int w, int h) {
    erd::SynthParams p;
    p.width = w;
    p.height = h;
    erd::Image gray;
    if (!erd::synth(p, &gray)) return nullptr;
    builtin.resize(gray.samples.size() * 3);
    for (std::size_t i = 0; i < gray.samples.size(); ++i) {
        const int v = gray.samples[i];
        std::size_t k = 1;
        while (kStops[k][0] < v) ++k;
        const int* a = kStops[k - 1];
        const int* b = kStops[k];
        const int d = b[0] - a[0];
        for (int c = 0; c < 3; ++c)
            builtin[3 * i + std::size_t(c)] = std::uint8_t((2 * (a[c + 1] * (b[0] - v) + b[c + 1] * (v - a[0])) + d) / (2 * d));
    }
    return builtin.data();
}

// The files the page offers for the last erd_mesh's model: its .erd/.model text and the vector
// SVG (`erd render --vector`). Apart from erd_mesh, so the
// page shows the reconstruction and the PSNR while these are written (in the WebAssembly build
// they take about as long as the meshing: the C library's number formatting). erd_timings() then
// holds their times only.
int erd_files() {
    job.timings.clear();
    auto t = Clock::now();
    erd::Status st = erd::write_model(job.model, &job.model_text);
    add_timing("model file", ms_since(t));
    t = Clock::now();
    if (st) st = erd::render_vector_svg(job.model, erd::VectorSvgOptions{}, &job.vector_svg);
    add_timing("vector SVG", ms_since(t));
    if (!st) {
        job.error = st.message;
        return st.exit_code();
    }
    return 0;
}

const char* erd_error() { return job.error.c_str(); }
const char* erd_model_text() { return job.model_text.c_str(); }
const char* erd_vector_svg() { return job.vector_svg.c_str(); }
const char* erd_timings() { return job.timings.c_str(); }
const std::uint8_t* erd_reconstruction() { return job.recon.data(); }
double erd_psnr() { return job.psnr; }
int erd_vertices() { return int(job.vertices); }
int erd_channels() { return job.channels; }
// The last erd_mesh's mesh, for the page to draw: x y per vertex (doubled coordinates: pixel
// x = X / 2), i j k per face, i j per constrained edge.
const std::int32_t* erd_mesh_vertices() { return job.vertices_xy.data(); }
const std::uint32_t* erd_mesh_faces() { return job.model.faces.empty() ? nullptr : job.model.faces[0].data(); }
int erd_faces() { return int(job.model.faces.size()); }
const std::uint32_t* erd_mesh_constraints() { return job.model.constraints.empty() ? nullptr : job.model.constraints[0].data(); }
int erd_constraints() { return int(job.model.constraints.size()); }

}  // extern "C"
