#include "algorithms/methods/erded.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "algorithms/imaging/colour.h"
#include "algorithms/imaging/error_diffusion.h"
#include "algorithms/imaging/mmsodd.h"
#include "algorithms/imaging/set_points.h"
#include "algorithms/methods/erd_mesh.h"
#include "algorithms/methods/exact_count.h"
#include "algorithms/methods/scaffold.h"
#include "algorithms/model/erd_model.h"

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

namespace {

Status erded_once(const Image& image, const GenerateOptions& options, bool hard_fallback, GenerateResult* result) {
    Cdt cdt;
    InitialMesh mesh;
    Status st = begin_erd_method(image, options, ErdMethod::erded, &cdt, &mesh, result, hard_fallback);
    if (!st) return st;
    const std::int64_t n = std::int64_t(result->requested);
    StageTimer timer(result);

    if (options.progress.report_cancelled("sample selection", 0.0)) return Status::failure(kCancelled);
    const std::size_t k = cdt.vertex_count() < std::size_t(n) ? std::size_t(n) - cdt.vertex_count() : 0;
    Grid<std::uint8_t> occupied = occupied_pixels(cdt, image.width, image.height);
    if (image.has_holes())  // nodata pixels are never chosen
        for (std::size_t i = 0; i < occupied.size(); ++i) occupied.data[i] |= std::uint8_t(image.valid[i] == 0);
    std::vector<LatticePoint> pts;
    const WedgeValueOptions wo = wedge_options(options);
    if (k > 0 && options.ed_select == 0) {
        pts = random_points(occupied, k, options.seed);
    } else if (k > 0) {
        // The pixels of the half-pixel edge map, which is freed before the density plane exists
        // (the two were the run's peak on photos).
        const Grid<std::uint8_t> on_edge = edge_cells(mesh.edges, image.width, image.height);
        mesh.edges = Grid<std::uint8_t>();
        // The MMSODD plane becomes the density in place; the wedge-value line search computes
        // its values where it needs them (the same values), so no second plane is kept.
        Grid<double> density = ed_density(colour_mmsodd(image, 5, options.colour.density, options.threads), 0.5, options.threads);
        options.progress("sample selection", 0.3);
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
        dp.threads = options.threads;
        DiffusionResult dr;
        st = select_points(density, k, dp, &dr);
        if (!st) return st;
        pts = std::move(dr.points);
        result->stats.has_diffusion = true;
        result->stats.diffusion.rho = dr.rho;
        result->stats.diffusion.passes = dr.passes;
        if (!dr.exact) result->stats.diffusion.adjusted = adjust_to_exact(density, occupied, k, &pts);
    }
    timer.lap("sample selection");
    options.progress("triangulation and wedge values", 0.0);

    std::vector<VertInd> ids;
    st = cdt.insert_points(pts, &ids, false);  // no change report: nothing reads it
    if (!st) return st;
    if (image.channels > 1) {
        ErdChannels model(image, wo, options.colour.shared_wedge_position, options.colour.density);
        model.assign_all(cdt);
        timer.lap("triangulation and wedge values");
        return finish_erd_method(cdt, image, options, &mesh, &model, &timer, result);
    }
    ErdModel model(image, wo);
    model.assign_all(cdt);
    timer.lap("triangulation and wedge values");
    return finish_erd_method(cdt, image, options, &mesh, &model, &timer, result);
}

}  // namespace

Status generate_erded(const Image& image, const GenerateOptions& options, GenerateResult* result) {
    return run_erd_method(image, options, erded_once, result);
}

}  // namespace erd
