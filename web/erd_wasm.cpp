// The C entry points of erd's WebAssembly build (make web): the page's worker passes gray pixels
// in and reads the results out of the module's memory. One job at a time (the worker is serial),
// so the results live in one static slot until the next erd_mesh call.
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/model/model_io.h"
#include "algorithms/output/render.h"
#include "algorithms/output/vector_svg.h"
#include "api/erd.h"

namespace {

struct Job {
    std::string error, model_text, vector_svg, mesh_svg;
    std::vector<std::uint8_t> recon;
    double psnr = 0;
    std::size_t vertices = 0;
};
Job job;

}  // namespace

extern "C" {

// Meshes a w x h 8-bit gray image with `method` ("ed", "gpi", "erded", "erdgpi") at `density`
// percent, as `erd generate -x 1` does, then reconstructs it (4x4 for ERD models) and measures
// the PSNR. Returns 0, or the status code with erd_error() set.
int erd_mesh(const std::uint8_t* pixels, int w, int h, const char* method, double density) {
    job = Job{};
    std::vector<std::uint16_t> samples(pixels, pixels + std::size_t(w) * std::size_t(h));
    erd::api::ImageView view{w, h, 255, samples.data(), 0};
    erd::api::Method m;
    erd::Status st = erd::api::method_from_name(method, &m);
    erd::api::Options opt;
    opt.generate.density = density;
    opt.generate.density_given = true;
    opt.exact = erd::api::ExactMode::warn;
    erd::Model model;
    if (st) st = erd::api::generate(m, view, opt, &model);
    erd::Image approx;
    if (st) st = erd::api::reconstruct(model, model.kind == erd::ModelKind::erd, &approx);
    if (st) st = erd::api::psnr(view, erd::api::view_of(approx), &job.psnr);
    if (st) st = erd::write_model(model, &job.model_text);
    if (st) st = erd::render_vector_svg(model, erd::VectorSvgOptions{}, &job.vector_svg);
    erd::RenderOptions ro;
    ro.scale = 1;
    if (st) st = erd::render_svg(model, "", ro, &job.mesh_svg);
    if (!st) {
        job.error = st.message;
        return st.exit_code();
    }
    job.vertices = model.vertices.size();
    job.recon.resize(approx.samples.size());
    for (std::size_t i = 0; i < approx.samples.size(); ++i) job.recon[i] = std::uint8_t(approx.samples[i]);
    return 0;
}

const char* erd_error() { return job.error.c_str(); }
const char* erd_model_text() { return job.model_text.c_str(); }
const char* erd_vector_svg() { return job.vector_svg.c_str(); }
const char* erd_mesh_svg() { return job.mesh_svg.c_str(); }
const std::uint8_t* erd_reconstruction() { return job.recon.data(); }
double erd_psnr() { return job.psnr; }
int erd_vertices() { return int(job.vertices); }

}  // extern "C"
