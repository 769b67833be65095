// The public API (api/erd.h): thin wrappers over the method registry, the reconstruction
// and the metrics, plus the checks a caller-owned view needs before it is trusted.
#include "api/erd.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <unordered_set>
#include <vector>

#include "algorithms/imaging/real_image.h"
#include "algorithms/methods/memory_estimate.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/quality_target.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd::api {

namespace {

// A real view (ImageView::reals): its values, NaN where nodata, into a real Image.
Status copy_real_view(const ImageView& v, Image* out) {
    if (v.channels != 1 && v.channels != 3)
        return Status::bad_input("image view has " + std::to_string(v.channels) + " channels (1 gray or 3 RGB)");
    const std::size_t C = std::size_t(v.channels), row = std::size_t(v.width) * C, stride = v.stride ? v.stride : row;
    if (stride < row) return Status::bad_input("image view stride is smaller than its width times its channels");
    std::vector<double> values(row * std::size_t(v.height));
    for (std::size_t y = 0; y < std::size_t(v.height); ++y)
        for (std::size_t i = 0; i < row; ++i) {
            const double x = v.reals[y * stride + i];
            values[y * row + i] = v.has_nodata && x == v.nodata ? std::numeric_limits<double>::quiet_NaN() : x;
        }
    RasterMeta meta;
    meta.type = v.type;
    meta.has_nodata = v.has_nodata;
    meta.nodata = v.nodata;
    return make_real_image(v.width, v.height, v.channels, std::move(values), meta, out);
}

// Validates a caller's view and copies it into an Image. Every sample is checked against
// maxval, because the methods index tables by sample value.
Status copy_view(const ImageView& v, Image* out) {
    if (v.width < 1 || v.height < 1 || v.width > kMaxImageSide || v.height > kMaxImageSide)
        return Status::bad_input("image size " + std::to_string(v.width) + "x" + std::to_string(v.height) +
                                 " outside 1.." + std::to_string(kMaxImageSide));
    if (std::int64_t(v.width) * v.height > kMaxImagePixels)
        return Status::bad_input("image has more than " + std::to_string(kMaxImagePixels) + " pixels");
    if (v.reals) return copy_real_view(v, out);
    if (v.maxval < 1 || v.maxval > 65535) return Status::bad_input("maxval " + std::to_string(v.maxval) + " outside 1..65535");
    if (!v.samples) return Status::bad_input("image view has no samples");
    if (v.channels != 1 && v.channels != 3)
        return Status::bad_input("image view has " + std::to_string(v.channels) + " channels (1 gray or 3 RGB)");
    const std::size_t C = std::size_t(v.channels), row_samples = std::size_t(v.width) * C;
    const std::size_t stride = v.stride ? v.stride : row_samples;
    if (stride < row_samples)
        return Status::bad_input(C == 1 ? "image view stride is smaller than its width"
                                        : "image view stride is smaller than its width times its channels");
    *out = Image(v.width, v.height, v.maxval, v.channels);
    for (int y = 0; y < v.height; ++y) {
        const std::uint16_t* row = v.samples + std::size_t(y) * stride;
        for (std::size_t i = 0; i < row_samples; ++i) {
            if (row[i] > v.maxval)
                return Status::bad_input("sample " + std::to_string(row[i]) + " at (" + std::to_string(i / C) + "," +
                                         std::to_string(y) + ")" + (C > 1 ? " channel " + std::to_string(i % C) : "") +
                                         " exceeds maxval " + std::to_string(v.maxval));
        }
        std::memcpy(&out->samples[std::size_t(y) * row_samples], row, row_samples * sizeof(std::uint16_t));
    }
    return Status::success();
}

}  // namespace

ImageView view_of(const Image& image) {
    ImageView v;
    v.width = image.width;
    v.height = image.height;
    v.maxval = image.maxval;
    v.samples = image.samples.data();
    v.stride = std::size_t(image.width) * std::size_t(image.channels);
    v.channels = image.channels;
    if (image.real()) {
        v.reals = image.reals.data();
        v.type = image.meta.type;
    }
    return v;
}

Status image_of(const ImageView& view, Image* out) { return copy_view(view, out); }

namespace {

// The registry row of m, or nullptr for a value outside the enum.
const MethodInfo* entry_of(Method m) {
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    const std::size_t i = std::size_t(m);
    return i < count ? &table[i] : nullptr;
}

}  // namespace

const char* method_name(Method m) {
    const MethodInfo* e = entry_of(m);
    return e ? e->name : "?";
}

Status method_from_name(const std::string& name, Method* out) {
    std::size_t count = 0;
    const MethodInfo* table = methods(&count);
    for (std::size_t i = 0; i < count; ++i) {
        if (name == table[i].name) {
            *out = Method(i);
            return Status::success();
        }
    }
    return Status::bad_input("unknown method '" + name + "' (" + method_names() + ")");
}

Options thesis_options() {
    Options o;
    o.generate = erd::thesis_options();
    o.exact = ExactMode::fail;
    return o;
}

std::size_t memory_estimate(Method m, int width, int height, const Options& options) {
    const MethodInfo* e = entry_of(m);
    if (!e || width < 1 || height < 1) return 0;
    return memory_bound(*e, width, height, 1, options.generate);
}

std::size_t memory_estimate(Method m, const ImageView& image, const Options& options) {
    const MethodInfo* e = entry_of(m);
    Image copy;
    if (!e || !copy_view(image, &copy)) return 0;
    return erd::memory_estimate(*e, copy, options.generate);
}

Status generate(Method m, const ImageView& image, const Options& options, Model* model, GenerateInfo* info) {
    if (!model) return Status::bad_input("generate: no model to fill");
    const MethodInfo* entry = entry_of(m);
    if (!entry) return Status::bad_input("generate: no such method");

    Image copy;
    Status st = copy_view(image, &copy);
    if (!st) return st;
    // The content estimate is never above the size bound: made only when the bound does not fit.
    if (options.max_memory && memory_bound(*entry, image.width, image.height, image.channels, options.generate) > options.max_memory) {
        // From the content (the ERD methods sample step 1's gradient), once the copy exists:
        // the size alone bounds an edge-rich image and would refuse most photos 3 times over.
        const std::size_t need = erd::memory_estimate(*entry, copy, options.generate);
        if (need > options.max_memory)
            return Status::failure("meshing a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   " image with " + method_name(m) + " needs about " + std::to_string(need) +
                                   " bytes, more than max_memory " + std::to_string(options.max_memory));
    }
    GenerateResult result;
    st = run_method(*entry, copy, options.generate, &result);
    if (!st) return st;
    *model = std::move(result.model);
    std::string warning;
    st = check_exact_count(result.requested, result.achieved, options.exact, &warning);
    if (info) {
        info->requested = result.requested;
        info->achieved = result.achieved;
        info->warning = warning;
        info->stats = result.stats;
        info->stages = std::move(result.stages);
    }
    return st;
}

Status reconstruct(const Model& model, bool supersample, Image* out, int threads) {
    if (!out) return Status::bad_input("reconstruct: no image to fill");
    return erd::reconstruct(model, supersample, out, {}, threads);
}

Status psnr(const ImageView& original, const ImageView& approx, double* db, int threads) {
    if (!db) return Status::bad_input("psnr: no result to fill");
    Image a, b;
    Status st = copy_view(original, &a);
    if (!st) return Status::bad_input("original: " + st.message);
    st = copy_view(approx, &b);
    if (!st) return Status::bad_input("approximation: " + st.message);
    return erd::psnr(a, b, db, threads);
}

namespace {

std::uint64_t edge_key(VertInd a, VertInd b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The ERD methods' data-dependent flips (their default) leave faces that are not the constrained
// Delaunay ones: flip every unconstrained edge of *cdt that the model lacks into the other
// diagonal when the model has that one, pass after pass until nothing changes; a model edge
// still missing then goes in as a constraint, and again. Code::input when the result still lacks
// an edge of the model (faces that are no triangulation of its points).
Status restore_flips(const Model& model, const std::vector<VertInd>& index, Cdt* cdt) {
    std::unordered_set<std::uint64_t> edges;
    for (const auto& f : model.faces) {
        if (f[0] >= index.size() || f[1] >= index.size() || f[2] >= index.size())
            return Status::bad_input("triangulate: a face refers to a vertex beyond the model's");
        for (int k = 0; k < 3; ++k) edges.insert(edge_key(index[f[std::size_t(k)]], index[f[std::size_t((k + 1) % 3)]]));
    }
    auto missing = [&](EdgeInd e) { return edges.count(edge_key(cdt->org(e), cdt->dest(e))) == 0; };
    // Each round inserts every missing model edge as a constraint (inserting retriangulates its
    // cavity, which can undo flips there, hence the rounds); the constraints only grow.
    for (;;) {
        for (bool changed = true; changed;) {
            changed = false;
            for (EdgeInd e = 0; e < 3 * cdt->face_count(); ++e) {
                if (cdt->on_hull(e) || cdt->constrained(e) || cdt->org(e) > cdt->dest(e) || !missing(e) ||
                    !cdt->can_flip(e))
                    continue;
                const EdgeInd d = cdt->flip_edge(e);
                if (missing(d))
                    cdt->flip_edge(d);  // the model has neither diagonal here yet: back, try later
                else
                    changed = true;
            }
        }
        // A model edge still missing is crossed by more than one edge: insert it as a constraint
        // (which flips its way in), as the .erdz encoder does.
        bool inserted = false;
        for (const auto& f : model.faces)
            for (int k = 0; k < 3; ++k) {
                const VertInd a = index[f[std::size_t(k)]], b = index[f[std::size_t((k + 1) % 3)]];
                if (a < b && cdt->find_edge(a, b) == noEdge) {
                    const Status st = cdt->insert_constraint(a, b);
                    if (!st) return st;
                    inserted = true;
                }
            }
        if (!inserted) break;
    }
    for (EdgeInd e = 0; e < 3 * cdt->face_count(); ++e)
        if (missing(e))
            return Status::bad_input("triangulate: the model's faces are not a triangulation of its vertices and constraints");
    return Status::success();
}

}  // namespace

Status triangulate(const Model& model, Cdt* cdt) {
    if (!cdt) return Status::bad_input("triangulate: no triangulation to fill");
    if (model.width < 1 || model.height < 1 || model.vertices.empty())
        return Status::bad_input("triangulate: empty model");
    const std::int32_t max_x = 2 * (model.width - 1), max_y = 2 * (model.height - 1);
    if (max_x < 1 || max_y < 1) return Status::bad_input("triangulate: the model's rectangle has no area");
    Status st = cdt->reset(max_x, max_y);
    if (!st) return st;
    for (LatticePoint p : model.vertices)
        if (p.x < 0 || p.y < 0 || p.x > max_x || p.y > max_y)
            return Status::bad_input("triangulate: vertex (" + std::to_string(p.x) + "," + std::to_string(p.y) +
                                     ") outside the model's rectangle");
    std::vector<VertInd> index;
    st = cdt->insert_points(model.vertices, &index);
    if (!st) return st;
    for (const auto& c : model.constraints) {
        if (c[0] >= index.size() || c[1] >= index.size())
            return Status::bad_input("triangulate: constraint refers to vertex " + std::to_string(std::max(c[0], c[1])) +
                                     " of " + std::to_string(index.size()));
        st = cdt->insert_constraint(index[c[0]], index[c[1]]);
        if (!st) return st;
    }
    return restore_flips(model, index, cdt);
}

}  // namespace erd::api
