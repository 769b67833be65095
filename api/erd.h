// The public C++ API of liberd: mesh an image, reconstruct an image from a mesh, measure PSNR.
//
// Installed as <prefix>/include/erd/api/erd.h (also reachable as <erd/erd.h>), with the kernel/
// and algorithms/ headers it includes beside it and no others (`make public-headers` lists them);
// `pkg-config --cflags --libs erd` gives -I<prefix>/include/erd and -lerd. C++17.
//
//     #include "api/erd.h"
//     erd::api::ImageView view{width, height, 255, samples};   // samples: uint16_t[width*height]
//     // colour: {width, height, 255, rgb, 0, 3} with rgb: uint16_t[width*height*3], R G B per pixel
//     erd::api::Options opt;                                   // thesis defaults: erdgpi, 3%
//     opt.generate.density = 1.0;                              // percent of the pixels
//     erd::Model model;
//     erd::Status st = erd::api::generate(erd::api::Method::erdgpi, view, opt, &model);
//     // erd::api::thesis_options() instead: the thesis's method exactly
//     if (!st) fprintf(stderr, "%s\n", st.message.c_str());
//     erd::Image approx;
//     st = erd::api::reconstruct(model, true, &approx);        // 4x4 supersampling
//     double db = 0;
//     st = erd::api::psnr(view, erd::api::view_of(approx), &db);
//
// Errors: every call returns an erd::Status (kernel/status.h): ok, or a code (input = bad
// arguments or data, runtime = an internal limit, density = the exact vertex count was not
// reached and Options::exact is ExactMode::fail) with a one-line message. Nothing throws, prints,
// exits or touches files. Memory is allocated only through std::vector inside the calls;
// built with -fno-exceptions a failed allocation aborts the process (docs/DECISIONS.md, "Public
// API and packaging"), so set Options::max_memory to refuse jobs that would not fit before they
// start.
//
// Threads: there is no global or static mutable state. Calls on different images run
// concurrently on different threads without locking. One object (Model, Image, Cdt) must not
// be used by two threads at once unless all of them only read it; note that Cdt::locate is
// const but updates a walk cache, so even a shared Cdt needs one thread at a time.
//
// The triangulation alone: kernel/cdt.h (included below) is the constrained Delaunay
// triangulation with exact integer predicates that the methods use; erd::Cdt is usable on its
// own (reset, insert_point, insert_constraint, verify). triangulate() rebuilds the Cdt of a model.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/methods/options.h"
#include "kernel/cdt.h"
#include "kernel/status.h"

namespace erd::api {

// A read-only image owned by the caller: `height` rows of `width` pixels, each pixel `channels`
// samples in [0, maxval] (1: gray; 3: RGB, interleaved R G B), rows `stride` samples apart (0
// means stride = width * channels). Never retained by a call. A gray view is written as before,
// {width, height, maxval, samples}; a colour one adds {..., stride, 3}.
struct ImageView {
    int width = 0;
    int height = 0;
    std::uint32_t maxval = 255;  // 1 .. 65535
    const std::uint16_t* samples = nullptr;
    std::size_t stride = 0;
    int channels = 1;  // 1 or 3
    // A real-valued image instead (issue 47: float, signed, 32-bit rasters): `reals` in place of
    // samples and maxval, the same layout (rows `stride` values apart), every value finite or NaN.
    // NaN, and `nodata` when has_nodata, mark the pixels without data (nodata: neither meshed nor
    // measured; the mesh covers the rest). `type` is the raster's sample type, kept for the outputs.
    const double* reals = nullptr;
    bool has_nodata = false;
    double nodata = 0.0;
    SampleType type = SampleType::f64;
};

// A view of an erd::Image (valid while the image lives and is not resized). A real image's view
// points at its real plane, so it has no nodata (Image::valid): pass such an image itself.
ImageView view_of(const Image& image);

// The Image a view stands for (checked as generate() checks it): what the methods take.
Status image_of(const ImageView& view, Image* out);

// The four methods of the thesis: ED and GPI make a basic model, ERDED and ERDGPI an ERD model;
// then the removal methods of issue 45: GPR, GPRFS and ID (basic), ERDGPR (ERD).
// The values are the rows of the method registry (algorithms/methods/methods.h), in its order;
// the names, model kinds and memory factors are read from there.
enum class Method { ed, gpi, erded, erdgpi, gpr, gprfs, id, erdgpr };

// "ed", "gpi", "erded", "erdgpi", "gpr", "gprfs", "id", "erdgpr".
const char* method_name(Method m);
// The method of that name; Code::input for any other name.
Status method_from_name(const std::string& name, Method* out);

// What to do when the method cannot hit the requested vertex count exactly (thesis -x):
// fail (Code::density; the model is still filled in), warn (ok; GenerateInfo::warning holds the
// sentence) or ignore. The policy itself is erd::check_exact_count (algorithms/methods/options.h).
using ExactMode = erd::ExactMode;

struct Options {
    // Target size and the thesis's parameters (algorithms/methods/options.h), thesis defaults:
    // density 3% of the pixels (-d wins over -n: set density_given or points), automatic ERD
    // parameters.
    GenerateOptions generate;
    ExactMode exact = ExactMode::fail;
    // Refuse (Code::runtime, before meshing) when memory_estimate(m, image, options) exceeds this
    // many bytes.
    // 0 = no limit.
    std::size_t max_memory = 0;
    // Threads: generate.threads (1 by default; 0 = the machine's processors) runs the image
    // stages side by side (kernel/row_parallel.h) with the same model for every count.
};

// The thesis's method exactly, in one call: erd::thesis_options() (the thesis's wedge values,
// no refit, the thesis's ERDED edge rule; what --thesis and erd_ed/erd_gpi run) and the thesis's
// exit mode 0 (ExactMode::fail). Set generate.density or points as usual.
Options thesis_options();

// What a generate() call reports besides the model.
struct GenerateInfo {
    std::size_t requested = 0;  // N asked for
    std::size_t achieved = 0;   // vertices in the model
    std::string warning;        // ExactMode::warn: the one-line warning, else empty
    RunStats stats;             // what the stages measured (algorithms/methods/result.h): the
                                // ERD parameters chosen, greedy and diffusion counts, the refit
    std::vector<StageTime> stages;  // wall time per stage
};

// Upper bound of the bytes a generate() call allocates at its peak for a width x height gray
// image with this method and target (the model it returns included), whatever the content: the
// edge-richest images measured, so 2-4 times the peak of a photo with an ERD method.
std::size_t memory_estimate(Method m, int width, int height, const Options& options);

// The same peak estimated from the image itself, within 25% of the measured peak (docs/DECISIONS.md
// "Memory" has the table): ED and GPI from the size and the target; ERDED and ERDGPI also from
// the edge kind and the points step 1 keeps, which a sample of 1.6% of its rows gives (a few
// percent of step 1's time). Never above the bound above. max_memory is checked against this one.
std::size_t memory_estimate(Method m, const ImageView& image, const Options& options);

// Meshes `image` with method `m`. *model receives the mesh (coordinates doubled, faces with
// positive orientation; algorithms/model/model.h), with the view's channel count (a colour view
// gives a colour model: Model::channels 3, values[v*3 + c]). The view is copied once into an
// erd::Image (2 bytes per sample) for the duration of the call. `info` may be null.
Status generate(Method m, const ImageView& image, const Options& options, Model* model,
                GenerateInfo* info = nullptr);

// Rasterises a model into *out (model's width, height, maxval and channels): point evaluation at every
// pixel (the thesis's imgsyn), or with `supersample` the mean of 4x4 sub-samples per pixel
// (imgsyn_aa). Values rounded to the nearest integer and clamped to [0, maxval]. A model's own
// reconstruction is supersample = supersampled(model): soft-edged ERD models only (model.h). The
// pixels along the edges a model lists in kind_exceptions (edges of the other kind than its own;
// algorithms/model/edge_kinds.h) are evaluated as that kind says whatever `supersample` is; clear
// the list for one evaluation at every pixel.
// threads: the faces or row bands on that many threads (0 = the machine's processors), the same
// image for every count (as Options::generate.threads, 1 by default).
Status reconstruct(const Model& model, bool supersample, Image* out, int threads = 1);

// PSNR of `approx` against `original` in dB, peak 2^p - 1 with p the bits per sample of the
// original; +infinity when the images are equal. Code::input when sizes, maxvals or channel
// counts differ. threads: as reconstruct's, the same result for every count.
Status psnr(const ImageView& original, const ImageView& approx, double* db, int threads = 1);

// Rebuilds the triangulation of a model in *cdt: the constrained Delaunay triangulation of its
// vertices and constrained edges (it depends only on those sets), then the flips that give the
// model's faces where they are not Delaunay (the ERD methods' data-dependent flips, --flips), so
// its faces are the model's faces as point triples; vertex numbers differ (the Cdt numbers the
// four corners 0..3). After such flips the Cdt passes verify_topology(), not verify(); a flipped
// edge that single flips cannot bring back is inserted as a constraint, so cdt->constrained()
// may hold edges beyond model.constraints (the model's own discontinuities are those).
// Code::input for an empty model, one whose points or indices lie outside it, or faces that no
// flips reach.
Status triangulate(const Model& model, Cdt* cdt);

}  // namespace erd::api
