#include "algorithms/methods/erded.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <numeric>
#include <string>

#include "algorithms/methods/erd_mesh.h"
#include "algorithms/model/erd_model.h"
#include "algorithms/methods/erdgpi.h"
#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/methods/gpi.h"
#include "algorithms/methods/methods.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/imaging/set_points.h"
#include "algorithms/methods/wedge_fit.h"

namespace erd {

namespace {

std::int64_t gcd64(std::int64_t a, std::int64_t b) {
    a = std::llabs(a);
    b = std::llabs(b);
    while (b != 0) {
        const std::int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

// splitmix64: a small fixed-seed generator, so -f 0 output is the same on every platform.
std::uint64_t next_random(std::uint64_t* state) {
    std::uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Chooses k usable pixels uniformly at random (partial Fisher-Yates), in row-major order.
std::vector<LatticePoint> random_points(const Grid<std::uint8_t>& occupied, std::size_t k, std::uint64_t seed) {
    std::vector<std::uint32_t> free;
    for (std::size_t i = 0; i < occupied.size(); ++i)
        if (!occupied.data[i]) free.push_back(std::uint32_t(i));
    k = std::min(k, free.size());
    std::uint64_t state = seed;
    for (std::size_t i = 0; i < k; ++i) {
        const std::size_t j = i + std::size_t(next_random(&state) % (free.size() - i));
        std::swap(free[i], free[j]);
    }
    free.resize(k);
    std::sort(free.begin(), free.end());
    std::vector<LatticePoint> pts;
    pts.reserve(k);
    const std::uint32_t w = std::uint32_t(occupied.width);
    for (std::uint32_t i : free) pts.push_back({std::int32_t(2 * (i % w)), std::int32_t(2 * (i / w))});
    return pts;
}

// Brings the diffusion's nearest pass to exactly k points: adds the densest unchosen usable
// pixels, or drops the least dense chosen ones (ties: row-major order). Returns the change.
std::size_t adjust_count(const Grid<double>& density, const Grid<std::uint8_t>& occupied, std::size_t k,
                         std::vector<LatticePoint>* pts) {
    const int w = density.width;
    auto index = [w](LatticePoint p) { return std::size_t(p.y / 2) * std::size_t(w) + std::size_t(p.x / 2); };
    std::size_t changed = 0;
    if (pts->size() > k) {
        std::vector<std::size_t> order(pts->size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return density.data[index((*pts)[a])] < density.data[index((*pts)[b])];
        });
        std::vector<std::uint8_t> drop(pts->size(), 0);
        changed = pts->size() - k;
        for (std::size_t i = 0; i < changed; ++i) drop[order[i]] = 1;
        std::vector<LatticePoint> kept;
        for (std::size_t i = 0; i < pts->size(); ++i)
            if (!drop[i]) kept.push_back((*pts)[i]);
        *pts = std::move(kept);
    } else if (pts->size() < k) {
        std::vector<std::uint8_t> taken(density.size(), 0);
        for (LatticePoint p : *pts) taken[index(p)] = 1;
        std::vector<std::uint32_t> cand;
        for (std::size_t i = 0; i < density.size(); ++i)
            if (!taken[i] && !occupied.data[i]) cand.push_back(std::uint32_t(i));
        const std::size_t need = std::min(k - pts->size(), cand.size());
        std::partial_sort(cand.begin(), cand.begin() + std::ptrdiff_t(need), cand.end(),
                          [&](std::uint32_t a, std::uint32_t b) {
                              return density.data[a] > density.data[b] || (density.data[a] == density.data[b] && a < b);
                          });
        for (std::size_t i = 0; i < need; ++i)
            pts->push_back({std::int32_t(2 * (cand[i] % std::uint32_t(w))), std::int32_t(2 * (cand[i] / std::uint32_t(w)))});
        changed = need;
    }
    return changed;
}

}  // namespace

Grid<std::uint8_t> edge_cells(const Grid<std::uint8_t>& edges, int width, int height) {
    Grid<std::uint8_t> out(width, height, 0);
    for_each_set(edges.data.data(), edges.data.size(), [&](std::size_t i) {
        const int X = int(i % std::size_t(edges.width)), Y = int(i / std::size_t(edges.width));
        // The half-pixel point lies in the cell of every pixel within half a pixel of it.
        for (int y = Y / 2; y <= (Y + 1) / 2 && y < height; ++y)
            for (int x = X / 2; x <= (X + 1) / 2 && x < width; ++x) out(x, y) = 1;
    });
    return out;
}

Grid<std::uint8_t> occupied_pixels(const Cdt& cdt, int width, int height) {
    Grid<std::uint8_t> occ(width, height, 0);
    for (LatticePoint p : cdt.points())
        if (p.x % 2 == 0 && p.y % 2 == 0) occ(p.x / 2, p.y / 2) = 1;
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    for (const auto& c : cons) {
        const LatticePoint a = cdt.point(c[0]), b = cdt.point(c[1]);
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y, g = gcd64(dx, dy);
        if (g == 0) continue;
        const std::int64_t sx = dx / g, sy = dy / g;
        for (std::int64_t i = 1; i < g; ++i) {
            const std::int64_t x = a.x + i * sx, y = a.y + i * sy;
            if (x % 2 == 0 && y % 2 == 0) occ(int(x / 2), int(y / 2)) = 1;
        }
    }
    return occ;
}

Status generate_erded(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    Cdt cdt;
    InitialMesh mesh;
    Status st = begin_erd_method(image, options, ErdMethod::erded, &cdt, &mesh, result);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);
    auto t0 = std::chrono::steady_clock::now();

    options.progress("sample selection", 0.0);
    const std::size_t k = cdt.vertex_count() < std::size_t(n) ? std::size_t(n) - cdt.vertex_count() : 0;
    const Grid<std::uint8_t> occupied = occupied_pixels(cdt, image.width, image.height);
    std::vector<LatticePoint> pts;
    std::size_t adjusted = 0;
    int passes = 0;
    const WedgeValueOptions wo = wedge_options(options);
    if (k > 0 && options.ed_select == 0) {
        pts = random_points(occupied, k, options.seed);
    } else if (k > 0) {
        // The MMSODD plane becomes the density in place; the wedge-value line search computes
        // its values where it needs them (the same values), so no second plane is kept.
        Grid<double> density = ed_density(mmsodd(image, 5), 0.5);
        const Grid<std::uint8_t> on_edge = edge_cells(mesh.edges, image.width, image.height);
        const int rad = std::max(0, options.edge_zero_radius);
        // Only the edge pixels are visited (the map is mostly empty); the zeros written do not
        // depend on the order.
        for_each_set(on_edge.data.data(), on_edge.data.size(), [&](std::size_t i) {
            const int x = int(i % std::size_t(image.width)), y = int(i / std::size_t(image.width));
            const int u0 = std::max(0, x - rad), u1 = std::min(image.width - 1, x + rad);
            for (int v = std::max(0, y - rad); v <= std::min(image.height - 1, y + rad); ++v)
                for (int u = u0; u <= u1; ++u) density(u, v) = 0.0;
        });
        DiffusionParams dp;
        dp.startup = options.startup == 1 ? Startup::force : options.startup == 2 ? Startup::none : Startup::mirror;
        dp.forbidden = &occupied;
        DiffusionResult dr;
        st = select_points(density, k, dp, &dr);
        if (!st) return st;
        passes = dr.passes;
        pts = std::move(dr.points);
        if (!dr.exact) adjusted = adjust_count(density, occupied, k, &pts);
    }
    result->stages.push_back({"sample selection", seconds_since(t0)});

    t0 = std::chrono::steady_clock::now();
    std::vector<VertInd> ids;
    st = cdt.insert_points(pts, &ids, false);  // no change report: nothing reads it
    if (!st) return st;
    ErdModel model(image, wo);
    model.assign_all(cdt);
    result->stages.push_back({"triangulation and wedge values", seconds_since(t0)});

    t0 = std::chrono::steady_clock::now();
    if (options.wedge_fit > 0) {
        WedgeFitStats fs;
        fit_wedge_values(cdt, image, options.wedge_fit, &model, &fs);
        result->stages.push_back({"wedge refit", seconds_since(t0)});
        t0 = std::chrono::steady_clock::now();
    }
    model.to_model(cdt, image.width, image.height, image.maxval, &result->model);
    result->achieved = result->model.size();
    add_param_notes(mesh, model, result);
    result->polylines = std::move(mesh.polylines);
    result->stages.push_back({"model", seconds_since(t0)});
    result->notes.push_back("error-diffusion passes: " + std::to_string(passes));
    result->notes.push_back("points added/removed to reach N exactly: " + std::to_string(adjusted));
    return Status::success();
}

}  // namespace erd
