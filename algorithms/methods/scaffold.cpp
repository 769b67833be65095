#include "algorithms/methods/scaffold.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/imaging/colour.h"
#include "algorithms/methods/bpr.h"
#include "algorithms/methods/erd_removal.h"
#include "algorithms/imaging/edge_kind.h"
#include "algorithms/imaging/real_image.h"
#include "algorithms/imaging/valid_region.h"
#include "algorithms/methods/greedy_models.h"
#include "algorithms/methods/minimax_fit.h"
#include "algorithms/model/edge_kinds.h"
#include "algorithms/model/model_holes.h"
#include "algorithms/methods/optimize.h"
#include "algorithms/methods/wedge_fit.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd {

std::int64_t target_points(const GenerateOptions& o, int width, int height) {
    if (o.points > 0 && !o.density_given) return o.points;
    // D is a percentage; round half away from zero (7864 for 3% of 512 x 512 = 7864.32).
    return std::int64_t(std::llround(o.density * double(width) * double(height) / 100.0));
}

Status check_target(std::int64_t n, int width, int height) {
    std::int64_t pixels = std::int64_t(width) * std::int64_t(height);
    // Size first, so a 1x1 or 1xN image always gets the same "too small" line whatever N is.
    if (width < 2 || height < 2)
        return Status::bad_input("image is " + std::to_string(width) + "x" + std::to_string(height) +
                                 "; meshing needs at least 2x2 pixels");
    if (n < 4)
        return Status::bad_input("target of " + std::to_string(n) +
                                 " points is below 4 (the four corners are always vertices)");
    if (n > pixels)
        return Status::bad_input("target of " + std::to_string(n) + " points exceeds the " +
                                 std::to_string(pixels) + " pixels of the image");
    return Status::success();
}

Status check_exact_count(std::size_t requested, std::size_t achieved, ExactMode mode, std::string* warning) {
    if (warning) warning->clear();
    if (achieved == requested || mode == ExactMode::ignore) return Status::success();
    std::string what = "target sampling density not achieved exactly (requested " + std::to_string(requested) +
                       " but got " + std::to_string(achieved) + ")";
    if (mode == ExactMode::fail) return Status::error(Code::density, what);
    if (warning) *warning = std::move(what);
    return Status::success();
}

void set_thesis_preset(GenerateOptions* o) {
    o->wedge_fit = 0;
    o->flips = 0;
    o->moves = 0;
    o->alpha_min = 1.0;
    o->alpha_max = 1.5;
    o->edge_zero_radius = 0;
    o->edges = EdgeChoice::soft;
    o->supersampled_errors = true;
    o->simple_shortcut = false;
    o->lower_beta = true;
}

GenerateOptions thesis_options() {
    GenerateOptions o;
    set_thesis_preset(&o);
    return o;
}

Status begin_method(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    *result = GenerateResult();
    const std::int64_t n = target_points(options, image.width, image.height);
    Status st = check_target(n, image.width, image.height);
    if (!st) return st;
    result->requested = std::size_t(n);
    return Status::success();
}

Model basic_model(const Cdt& cdt, const Image& image) {
    Model m;
    m.kind = ModelKind::basic;
    m.width = image.width;
    m.height = image.height;
    m.maxval = image.maxval;
    m.channels = image.channels;
    m.vertices = cdt.points();
    m.values.reserve(m.vertices.size() * std::size_t(image.channels));
    for (LatticePoint p : m.vertices)
        for (int c = 0; c < image.channels; ++c)
            m.values.push_back(image.real() ? lattice_value(image, p, c) : double(image.at(p.x / 2, p.y / 2, c)));
    std::vector<std::array<VertInd, 3>> faces;
    cdt.export_faces(&faces);
    m.faces.assign(faces.begin(), faces.end());
    return m;
}

namespace {

std::size_t distinct_points_of(const std::vector<Polyline>& lines) {
    std::vector<std::uint64_t> keys;
    for (const Polyline& pl : lines)
        for (LatticePoint p : pl) keys.push_back((std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x));
    std::sort(keys.begin(), keys.end());
    return std::size_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

}  // namespace

Status insert_border_points(const GenerateOptions& options, Cdt* cdt) {
    if (!options.lock_border || options.border_points.empty()) return Status::success();
    for (LatticePoint p : options.border_points) {
        const bool on_side = p.x == 0 || p.y == 0 || p.x == cdt->max_x() || p.y == cdt->max_y();
        if (!on_side || p.x < 0 || p.y < 0 || p.x > cdt->max_x() || p.y > cdt->max_y() || p.x % 2 || p.y % 2)
            return Status::bad_input("a tile's border point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                     ") is not a pixel on its rectangle's sides");
    }
    std::vector<VertInd> v;
    return cdt->insert_points(options.border_points, &v, false);
}

Status insert_valid_outline(const Image& image, Cdt* cdt, RunStats* stats, std::size_t target) {
    if (!image.has_holes()) return Status::success();
    const std::vector<Polyline> outline = valid_outline(image.valid, image.width, image.height);
    std::size_t dropped = 0;
    if (Status st = insert_polylines(outline, cdt, &dropped, true); !st) return st;
    stats->has_raster = true;
    stats->raster.outline_points = cdt->vertex_count() - 4;
    if (target < cdt->vertex_count())
        return Status::bad_input("target of " + std::to_string(target) + " points is below the " + std::to_string(cdt->vertex_count()) +
                                 " of the corners and the outline of the valid region (nodata)");
    return Status::success();
}

void finish_raster_model(const Image& image, Model* m, RunStats* stats) {
    m->meta = image.meta;
    if (!image.real()) return;
    m->real = true;
    m->holes = image.has_holes();
    m->maxval = 0;
    m->lo = image.lo;
    m->hi = image.hi;
    const DroppedFaces d = drop_faces_over_nodata(image.valid, m);
    if (stats) {
        stats->has_raster = true;
        stats->raster.dropped_faces = d.faces;
        stats->raster.dropped_vertices = d.vertices;
    }
}

namespace {

// --max-error on a real image is a bound on the model given back: after the method's own stages
// (which may move values: a refit, flips, --optimize's fit) greedy insertion goes on, on the
// model's current values, until the largest error over the valid pixels is at most E. N caps it
// for the greedy methods (as their other stop rules); ED and ERDED choose N points first, and the
// bound then wins over N (the exact-count rule, -x, reports the points beyond).
Status max_error_fixup(Cdt& cdt, const Image& image, const GenerateOptions& options, GreedyModel& model,
                       GenerateResult* result, std::vector<FaceInd>* owners = nullptr) {
    if (!image.real() || options.max_error < 0) return Status::success();
    GreedyStats gs;
    const std::size_t cap = result->stats.has_greedy ? result->requested : image.pixels() + cdt.vertex_count();
    GreedyOptions go = greedy_options(options, cap);
    go.owners = owners;
    const Status st = greedy_refine(cdt, image, model, go, &gs);
    result->stats.has_raster = true;
    result->stats.raster.fixup_insertions = gs.insertions;
    return st;
}

// The largest error over the valid pixels of model m of the real image (its reconstruction).
void measure_max_error(const Image& image, const Model& m, const GenerateOptions& options, GenerateResult* result) {
    if (!image.real() || options.max_error < 0) return;
    Image rec;
    double e = -1.0;
    if (reconstruct(m, false, &rec, {}, options.threads) && max_abs_error(image, rec, &e)) result->stats.raster.max_error = e;
}

}  // namespace

Status finish_basic_method(Cdt& cdt, const Image& image, const GenerateOptions& options, StageTimer* timer,
                           GenerateResult* result) {
    if (options.bpr > 0 && !image.real()) {  // --bpr: not on real images (issue 47)
        SampleRemovalModel samples(image);
        result->stats.has_removal = true;
        Status st = bad_point_replacement(&cdt, image, samples, options.round_values, options.bpr, options.progress,
                                          &result->stats.removal);
        if (!st) return st;
        Cdt compact;
        if (!(st = compact_cdt(cdt, &compact))) return st;
        cdt = std::move(compact);
        timer->lap("bad-point replacement");
    }
    if (image.real() && options.max_error >= 0 && !options.optimize) {
        BasicGreedyModel greedy(image);
        if (Status st = max_error_fixup(cdt, image, options, greedy, result); !st) result->stats.raster.fixup_insertions = 0;
    }
    result->model = basic_model(cdt, image);
    result->achieved = result->model.size();
    finish_raster_model(image, &result->model, &result->stats);
    timer->lap("model");
    if (options.optimize) {
        optimize_basic_model(&cdt, image, options, &result->model, &result->stats.wedge_fit);
        finish_raster_model(image, &result->model, nullptr);
        result->stats.has_wedge_fit = true;
        timer->lap("optimize");
    }
    measure_max_error(image, result->model, options, result);
    return Status::success();
}

GreedyOptions greedy_options(const GenerateOptions& options, std::size_t n) {
    GreedyOptions go;
    go.target_vertices = n;
    go.max_error = options.max_error;
    go.psnr = options.psnr;
    go.max_triangles = options.triangles > 0 ? std::size_t(options.triangles) : 0;
    go.round_values = options.round_values;
    go.max_channel_error = options.colour.max_channel_error;
    go.progress = options.progress;
    go.ban_border = options.lock_border;
    go.threads = options.threads;
    return go;
}

WedgeValueOptions wedge_options(const GenerateOptions& options) {
    WedgeValueOptions w;
    w.rule = options.wedge_rule == 0 ? 0 : 1;
    w.smoothing_order = options.wedge_order;
    w.alpha_min = options.alpha_min;
    w.alpha_max = options.alpha_max;
    return w;
}

ErdParamRequest param_request(const GenerateOptions& options) {
    return ErdParamRequest{options.beta, options.ratio, options.min_length, options.epsilon, options.simple,
                           options.simple_shortcut, options.lower_beta,
                           options.simple_test_points};
}

Status begin_erd_method(const Image& image, const GenerateOptions& options, ErdMethod method, Cdt* cdt,
                        InitialMesh* mesh, GenerateResult* result, bool hard_fallback) {
    Status st = begin_method(image, options, result);
    if (!st) return st;
    ErdStepStats& s = result->stats.erd;
    // Colour: the edges (their kind, then step 1) are those of the luma plane (docs/DECISIONS.md
    // "Colour methods"), shared by the channels.
    Image luma;
    if (image.channels > 1) luma = luma_of(image);
    const Image& gray = image.channels > 1 ? luma : image;
    if (options.edges == EdgeChoice::automatic) {
        const EdgeKindStats ek = measure_edge_kind(gray);
        s.edges_measured = true;
        s.hard_steps = ek.hard;
        s.soft_steps = ek.soft;
        s.clean_steps = ek.clean;
        s.all_steps = ek.steps;
        s.hard_edges = ek.is_hard();
        // A real model is point-evaluated everywhere (reconstruct.h): the kinds of its edges change
        // nothing, so a real image tries no second treatment (try_edge_treatments).
        s.stepped = ek.is_stepped() && !image.real();
    } else {
        s.hard_edges = options.edges == EdgeChoice::hard;
    }
    result->model.edges = s.hard_edges ? EdgeKind::hard : EdgeKind::soft;
    if (options.progress.report_cancelled("initial mesh", 0.0)) return Status::failure(kCancelled);
    StageTimer timer(result);
    InitialMeshOptions mo;
    mo.method = method;
    mo.target = result->requested;
    mo.request = param_request(options);
    mo.hard_edges = s.hard_edges;
    mo.hard_fallback = hard_fallback;
    mo.constraints = &options.constraints;
    mo.detect = options.detect;
    // Nodata: the valid region's outline first, detected edges kept two pixels away from the holes.
    std::vector<Polyline> outline;
    std::vector<std::uint8_t> near;
    if (image.has_holes()) {
        outline = valid_outline(image.valid, image.width, image.height);
        near = near_nodata(image.valid, image.width, image.height, 2);
        mo.outline = &outline;
        mo.near_nodata = &near;
    }
    if (image.real() && options.max_error >= 0) {
        mo.min_step = options.min_step_factor * options.max_error;
        // The cliff test (min_step) decides which edges count: no simple-image test, whose own
        // edge detection was half of step 1 (DECISIONS.md "Rasters").
        if (mo.request.simple < 0 && options.min_step_factor > 0) mo.request.simple = 1;
    }
    if (image.channels > 1 && options.colour.edges != ColourGradient::luma) {
        mo.colour = &image;
        mo.colour_gradient = options.colour.edges;
    }
    mo.progress = options.progress;
    mo.threads = options.threads;
    // A tile: detected polylines cut where they reach a side (the sides' vertices are decided).
    std::vector<std::uint8_t> cut;
    if (options.lock_border) {
        cut = near;
        if (cut.empty()) cut.assign(std::size_t(image.width) * std::size_t(image.height), 0);
        for (int x = 0; x < image.width; ++x)
            cut[std::size_t(x)] = cut[std::size_t(image.height - 1) * std::size_t(image.width) + std::size_t(x)] = 1;
        for (int y = 0; y < image.height; ++y)
            cut[std::size_t(y) * std::size_t(image.width)] = cut[std::size_t(y) * std::size_t(image.width) + std::size_t(image.width - 1)] = 1;
        mo.near_nodata = &cut;
        mo.side_crossings = &options.border_crossings;
    }
    st = build_initial_mesh(gray, mo, cdt, mesh);
    if (!st) return st;
    if (!(st = insert_border_points(options, cdt))) return st;
    if (image.has_holes()) {
        result->stats.has_raster = true;
        result->stats.raster.outline_points = distinct_points_of(outline);
    }
    s.plain_fallback = mesh->plain_fallback;
    timer.lap("initial mesh");
    return Status::success();
}

namespace {

// Keeps the better of `before` and *after by the PSNR of their point-evaluated reconstructions
// (*after on a tie or any error), and returns the kept one's PSNR (0 after an error).
double keep_better(const Image& image, Model* before, Model* after, int threads) {
    Image rec;  // one image for both: the second reconstruction reuses the first's memory
    double pa = 0, pb = 0;
    if (!reconstruct(*before, false, &rec, {}, threads) || !psnr(image, rec, &pa, threads) ||
        !reconstruct(*after, false, &rec, {}, threads) || !psnr(image, rec, &pb, threads))
        return 0.0;
    if (pa > pb) *after = std::move(*before);
    return pa > pb ? pa : pb;
}

// The end of finish_erd_method once result->model is made: the step-1 facts and the wedge-value
// counts (of `model`, channel 0 in colour), the polylines; stage "model".
void finish_erd_stats(InitialMesh* mesh, const ErdModel* model, StageTimer* timer, GenerateResult* result) {
    result->achieved = result->model.size();
    result->stats.has_erd = true;
    ErdStepStats& s = result->stats.erd;
    s.params = mesh->params;
    s.polylines = mesh->polylines.size();
    s.initial_vertices = mesh->n0;
    s.dropped_crossing = mesh->dropped_crossing;
    s.joined_crossings = mesh->joined_crossings;
    s.dropped_polylines = mesh->dropped_polylines;
    s.multi_wedges = model->stats().multi_wedges;
    s.alpha_first = model->stats().alpha_first;
    s.alpha_last = model->stats().alpha_last;
    result->polylines = std::move(mesh->polylines);
    // Vertices over nodata dropped from the model still count: N is the mesh's before the drop.
    result->achieved += result->stats.raster.dropped_vertices;
    timer->lap("model");
}

}  // namespace

WedgeFitOptions wedge_fit_options(const GenerateOptions& options) {
    WedgeFitOptions f;
    f.iterations = options.wedge_fit;
    f.prior_weight = options.wedge_prior;
    f.support_bounds = options.wedge_bounds;
    f.threads = options.threads;
    return f;
}

namespace {

ErdModel* fresh_model(const Image& image, const GenerateOptions& options, std::unique_ptr<ErdModel>* out) {
    *out = std::make_unique<ErdModel>(image, wedge_options(options));
    return out->get();
}
ErdChannels* fresh_model(const Image& image, const GenerateOptions& options, std::unique_ptr<ErdChannels>* out) {
    *out = std::make_unique<ErdChannels>(image, wedge_options(options), options.colour.shared_wedge_position,
                                         options.colour.density);
    return out->get();
}

// --bpr on an ERD mesh (not a real image's): bad-point replacement on *model's values, then the
// compact mesh and a fresh model of it (line-search values) in *fresh, which *model then points to.
template <class View, class M>
Status erd_bpr(Cdt& cdt, const Image& image, const GenerateOptions& options, M** model, std::unique_ptr<M>* fresh,
               StageTimer* timer, GenerateResult* result) {
    if (options.bpr <= 0 || image.real()) return Status::success();
    View values(**model);
    result->stats.has_removal = true;
    Status st = bad_point_replacement(&cdt, image, values, false, options.bpr, options.progress, &result->stats.removal);
    if (!st) return st;
    Cdt compact;
    if (!(st = compact_cdt(cdt, &compact))) return st;
    cdt = std::move(compact);
    *model = fresh_model(image, options, fresh);
    (*model)->assign_all(cdt);
    timer->lap("bad-point replacement");
    return Status::success();
}

}  // namespace

Status finish_erd_method(Cdt& cdt, const Image& image, const GenerateOptions& options, InitialMesh* mesh,
                       ErdModel* model, StageTimer* timer, GenerateResult* result,
                       const std::vector<double>* line_search_values) {
    std::unique_ptr<ErdModel> fresh;
    if (Status st = erd_bpr<ErdRemovalModel>(cdt, image, options, &model, &fresh, timer, result); !st) return st;
    if (fresh) line_search_values = nullptr;
    // A real image: the values pinned to the vertices' pixels after each change (ErdModel::
    // pin_pixel_vertices), no guard (its models are not rounded), then the max-error pass.
    const bool real = image.real();
    if (options.wedge_fit > 0) {
        std::vector<double> kept;  // the line-search values, for the refit after the flips
        if (options.flips && !line_search_values) {
            for (std::size_t i = 0; i < model->entry_count(); ++i) kept.push_back(model->entry_value(i));
            line_search_values = &kept;
        }
        MeshSystems systems;  // the flips and the refits after them start from the first refit's
        fit_wedge_values(cdt, image, wedge_fit_options(options), model, &result->stats.wedge_fit,
                         line_search_values, options.progress, options.flips ? &systems : nullptr);
        model->pin_pixel_vertices(cdt);
        result->stats.has_wedge_fit = true;
        timer->lap("wedge refit");
        if (options.flips) {
            // Hard edges are reconstructed by rounded point evaluation, and near-lossless
            // pictures (above 65 dB) can lose by flips that lower the real-valued error: keep
            // the flipped model only when its reconstruction is at least as good.
            const bool guard = result->model.edges == EdgeKind::hard && !real;
            Model before;
            if (guard) {
                before = result->model;  // keeps the fields to_model leaves alone (edges)
                model->to_model(cdt, image.width, image.height, image.maxval, &before);
            }
            optimize_by_flips(&cdt, image, options, model, line_search_values, &result->stats.wedge_fit, &systems);
            model->pin_pixel_vertices(cdt);
            if (!real) model->to_model(cdt, image.width, image.height, image.maxval, &result->model);
            if (guard) result->stats.erd.plain_psnr = keep_better(image, &before, &result->model, options.threads);
            timer->lap("flips");
        }
    }
    // A real image under --max-error: the pixels' faces found once; the minimax fit reads them,
    // the last insertions read and keep them, the measure at the end reads them (minimax_fit.h).
    std::vector<FaceInd> owners;
    if (real) {
        if (options.max_error >= 0) {
            owners = pixel_owners(cdt, image);
            // The values towards the smallest largest error; the vertices' own pixels kept
            // within the bound (the refits moved them too), the rest of the bound enforced by the
            // insertions below.
            if (options.minimax_rounds > 0) fit_minimax(cdt, image, model, options.minimax_rounds, options.progress, &owners);
            model->pin_pixel_vertices(cdt, options.max_error);
            timer->lap("minimax fit");
        }
        ErdGreedyModel greedy(*model);
        if (Status st = max_error_fixup(cdt, image, options, greedy, result, owners.empty() ? nullptr : &owners); !st) {
            result->stats.raster.fixup_insertions = 0;
            owners.clear();  // an insertion may have left faces unscanned
        }
    }
    if (!(options.wedge_fit > 0 && options.flips) || real)
        model->to_model(cdt, image.width, image.height, image.maxval, &result->model);
    finish_raster_model(image, &result->model, &result->stats);
    finish_erd_stats(mesh, model, timer, result);
    // The model's own planes on the mesh, as its reconstruction evaluates them (faces over nodata
    // own no valid pixel): half the cost of reconstructing the model file's (issue 47 speed).
    if (real && options.max_error >= 0)
        result->stats.raster.max_error = largest_error(cdt, image, *model, owners.empty() ? nullptr : &owners);
    return Status::success();
}

Status finish_erd_method(Cdt& cdt, const Image& image, const GenerateOptions& options, InitialMesh* mesh,
                       ErdChannels* model, StageTimer* timer, GenerateResult* result) {
    std::unique_ptr<ErdChannels> fresh;
    if (Status st = erd_bpr<ErdChannelsRemovalModel>(cdt, image, options, &model, &fresh, timer, result); !st) return st;
    const bool real = image.real();  // as gray's
    if (options.wedge_fit > 0) {
        // As gray's refit (prior and support bounds per channel), then its flips.
        std::vector<std::vector<double>> line_search;
        if (options.flips) line_search = model->values();
        // The face systems kept for the flips' refits and moves (faces they did not change).
        ColourSystems systems;
        model->fit(cdt, wedge_fit_options(options), &result->stats.wedge_fit, options.progress, nullptr,
                   options.flips ? &systems : nullptr);
        model->pin_pixel_vertices(cdt);
        result->stats.has_wedge_fit = true;
        timer->lap("wedge refit");
        if (options.flips) {
            const bool guard = result->model.edges == EdgeKind::hard && !real;  // as gray's
            Model before;
            if (guard) {
                before = result->model;
                model->to_model(cdt, image.width, image.height, image.maxval, &before);
            }
            optimize_by_flips(&cdt, options, model, &line_search, &result->stats.wedge_fit, &systems);
            model->pin_pixel_vertices(cdt);
            if (!real) model->to_model(cdt, image.width, image.height, image.maxval, &result->model);
            if (guard) result->stats.erd.plain_psnr = keep_better(image, &before, &result->model, options.threads);
            timer->lap("flips");
        }
    }
    if (real) {
        ColourErdGreedyModel greedy(*model);
        if (Status st = max_error_fixup(cdt, image, options, greedy, result); !st) result->stats.raster.fixup_insertions = 0;
    }
    if (!(options.wedge_fit > 0 && options.flips) || real)
        model->to_model(cdt, image.width, image.height, image.maxval, &result->model);
    finish_raster_model(image, &result->model, &result->stats);
    finish_erd_stats(mesh, &model->channel(0), timer, result);
    measure_max_error(image, result->model, options, result);
    return Status::success();
}

namespace {

// The second run of a hard-edged model (run_erd_method).
Status hard_second_run(const Image& image, const GenerateOptions& options, ErdRun run, GenerateResult* result) {
    Status st;
    const auto point_psnr = [&](const Model& m, double* db) {
        Image rec;
        Status s = reconstruct(m, false, &rec, {}, options.threads);
        return s ? psnr(image, rec, db, options.threads) : s;
    };
    // The flips' guard measured it already (finish_erd_method), unless it did not run.
    double plain = result->stats.erd.plain_psnr;
    if (plain <= 0 && !(st = point_psnr(result->model, &plain))) return st;
    // When no count fell back to the plain curves, the run without the fallback is this run step
    // for step (the same counts, so the same parameters and mesh): its model and PSNR are these.
    double exact = plain;
    if (result->stats.erd.plain_fallback) {
        GenerateResult other;
        if (!(st = run(image, options, false, &other))) return st;
        exact = other.stats.erd.plain_psnr;
        if (exact <= 0 && !(st = point_psnr(other.model, &exact))) return st;
        if (exact > plain) *result = std::move(other);
    }
    result->stats.erd.plain_psnr = plain;
    result->stats.erd.exact_psnr = exact;
    return Status::success();
}

// An image measured stepped (edge_kind.h) after its first run in *result (soft or hard edges as
// measured): the three treatments of its edges, soft detection, hard edges and no
// detected edges, each model with its edges' kinds chosen by fit (edge_kinds.h); the one whose
// own reconstruction has the highest PSNR is kept (the first tried on a tie; an exact one ends the
// search), with the first run's measurement.
Status try_edge_treatments(const Image& image, const GenerateOptions& options, ErdRun run, GenerateResult* result) {
    const ErdStepStats measured = result->stats.erd;
    const int first = measured.hard_edges ? 1 : 0;
    double tried[3] = {0, 0, 0}, best = 0;
    if (Status st = choose_edge_kinds(image, &result->model, &tried[first], options.threads); !st) return st;
    best = tried[first];
    int choice = first;
    for (int k = 0; k < 3; ++k) {
        if (k == first || std::isinf(best)) continue;  // nothing beats an exact model
        GenerateOptions o = options;
        o.edges = k == 0 ? EdgeChoice::soft : EdgeChoice::hard;
        o.detect = k < 2 && options.detect;
        GenerateResult other;
        if (Status st = run_erd_method(image, o, run, &other); !st) return st;
        if (Status st = choose_edge_kinds(image, &other.model, &tried[k], options.threads); !st) return st;
        if (tried[k] > best) {
            best = tried[k];
            choice = k;
            *result = std::move(other);
        }
    }
    ErdStepStats& s = result->stats.erd;
    s.edges_measured = true;
    s.hard_steps = measured.hard_steps;
    s.soft_steps = measured.soft_steps;
    s.clean_steps = measured.clean_steps;
    s.all_steps = measured.all_steps;
    s.stepped = measured.stepped;
    s.tried = true;
    for (int k = 0; k < 3; ++k) s.tried_psnr[k] = tried[k];
    s.tried_choice = choice;
    s.hard_edges = result->model.edges == EdgeKind::hard;
    s.kind_exceptions = result->model.kind_exceptions.size();
    return Status::success();
}

}  // namespace

Status run_erd_method(const Image& image, const GenerateOptions& options, ErdRun run, GenerateResult* result) {
    result->stats.erd.plain_psnr = 0;
    Status st = run(image, options, true, result);
    if (st && result->model.edges == EdgeKind::hard) st = hard_second_run(image, options, run, result);
    const ErdStepStats& s = result->stats.erd;
    if (st && s.edges_measured && s.stepped) st = try_edge_treatments(image, options, run, result);
    return st;
}

}  // namespace erd
