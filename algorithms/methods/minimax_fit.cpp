#include "algorithms/methods/minimax_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "algorithms/methods/wedge_fit.h"
#include "kernel/raster.h"
#include "kernel/raster_rows.h"

namespace erd {

namespace {

// The smallest weight: a pixel far inside the bound still holds its face (without it the values
// no large error pins down drift, and the errors IRLS ignored become the largest).
constexpr double kFloor = 0.1;


// The face that owns each pixel (noFace outside every face): one scan of the mesh, which the
// passes below then read pixel by pixel instead of scanning every face again.
std::vector<FaceInd> owners_of(const Cdt& cdt, const Image& image) {
    const RasterDomain domain{cdt.max_x(), cdt.max_y()};
    const std::size_t W = std::size_t(image.width);
    std::vector<FaceInd> owner(W * std::size_t(image.height), noFace);
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        const EdgeInd e = 3 * f;
        const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
        for_each_owned_row(Lattice::pixels(), domain, p0, p1, p2, [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            std::fill(owner.begin() + std::ptrdiff_t(std::size_t(j) * W + std::size_t(lo)),
                      owner.begin() + std::ptrdiff_t(std::size_t(j) * W + std::size_t(hi) + 1), f);
        });
    }
    return owner;
}

// One pass over the valid pixels (each on the face that owns it: owner, pixel_owners'): the
// largest error of the current values, and (with systems) the face systems of the errors weighted
// by (|e| / e_norm)^(2^squarings), p = 2 + 2^squarings. Row by row, so each face's sums take its
// pixels in the order a scan of the face would.
double weighted_pass(const Cdt& cdt, const Image& image, const ErdModel& model, const std::vector<FaceInd>& owner,
                     int squarings, double e_norm, std::vector<FaceSystem>* systems) {
    const std::size_t W = std::size_t(image.width), H = std::size_t(image.height);
    const std::uint8_t* ok = image.valid.empty() ? nullptr : image.valid.data();
    const double inv = e_norm > 0 ? 1.0 / e_norm : 0.0;
    const std::size_t F = cdt.face_count();
    std::vector<SpanPlane> planes(F);
    for (FaceInd f = 0; f < F; ++f) planes[f] = model.face_plane(cdt, f);
    // The barycentric planes of the face of the current run of pixels (made per run, not kept
    // per face: 80 bytes a face of peak memory).
    SpanPlane l0, l1;
    FaceInd lf = noFace;
    double emax = 0;
    if (systems) systems->assign(F, FaceSystem());
    for (std::size_t j = 0; j < H; ++j) {
        const double Y = double(2 * j);
        for (std::size_t i = 0; i < W; ++i) {
            const std::size_t p = j * W + i;
            const FaceInd f = owner[p];
            if (f == noFace || (ok && !ok[p])) continue;
            const double X = double(2 * i), b = image.reals[p];
            const double err = b - planes[f].at(X, Y);
            emax = std::max(emax, std::fabs(err));
            if (!systems) continue;
            double w = std::fabs(err) * inv;
            for (int k = 0; k < squarings; ++k) w *= w;
            w = w > kFloor ? w : kFloor;
            if (f != lf) {
                const EdgeInd e = 3 * f;
                const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
                l0.set(p0, 1.0, p1, 0.0, p2, 0.0);
                l1.set(p0, 0.0, p1, 1.0, p2, 0.0);
                lf = f;
            }
            const double w0 = l0.at(X, Y), w1 = l1.at(X, Y), w2 = 1.0 - w0 - w1;
            FaceSystem& fs = (*systems)[f];
            fs.g[0] += w * w0 * w0;
            fs.g[1] += w * w0 * w1;
            fs.g[2] += w * w0 * w2;
            fs.g[3] += w * w1 * w1;
            fs.g[4] += w * w1 * w2;
            fs.g[5] += w * w2 * w2;
            fs.h[0] += w * b * w0;
            fs.h[1] += w * b * w1;
            fs.h[2] += w * b * w2;
            fs.bb += w * b * b;
            fs.owns = true;
        }
    }
    if (systems)
        for (FaceInd f = 0; f < F; ++f)
            for (int k = 0; k < 3; ++k) (*systems)[f].entry[k] = model.corner_entry(cdt, 3 * f + EdgeInd(k));
    return emax;
}

}  // namespace

std::vector<FaceInd> pixel_owners(const Cdt& cdt, const Image& image) { return owners_of(cdt, image); }

double fit_minimax(const Cdt& cdt, const Image& image, ErdModel* model, int rounds, ProgressHook progress,
                   const std::vector<FaceInd>* owners) {
    if (!image.real()) return -1.0;
    std::vector<double> kept(model->entry_count()), start(model->entry_count());
    for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = model->entry_value(i);
    MeshSystems systems;
    WedgeFitOptions fo;
    fo.iterations = 8;
    fo.prior_weight = kFloor;  // each value also drawn to where the round started
    fo.support_bounds = -1;
    // Each pass measures the values the round before left (the first: those given) and weighs by
    // them; a last pass without weights measures the last round's.
    double best = 0, last = 0;
    double e_norm = 0;
    std::vector<FaceInd> own;  // the mesh stays as it is: one map for every pass
    if (!owners) own = owners_of(cdt, image);
    const std::vector<FaceInd>& owner = owners ? *owners : own;
    for (int r = 0; r <= rounds; ++r) {
        progress("minimax fit", double(r) / double(rounds + 1));
        // The first pass has no weights yet: it measures only.
        const bool fit = r < rounds;
        last = weighted_pass(cdt, image, *model, owner, std::min(r + 1, 5), e_norm > 0 ? e_norm : 1.0, fit && r > 0 ? &systems.faces : nullptr);
        if (r == 0 && fit) {
            // The first round's weights need the first measure: one pass more.
            e_norm = last;
            last = weighted_pass(cdt, image, *model, owner, 1, e_norm, &systems.faces);
        }
        if (r == 0 || last < best) {
            best = last;
            if (r > 0)
                for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = model->entry_value(i);
        }
        if (!fit || best <= 0) break;
        e_norm = last;
        systems.stale.assign(systems.faces.size(), 0);
        for (std::size_t i = 0; i < start.size(); ++i) start[i] = model->entry_value(i);
        fit_wedge_values(cdt, image, fo, model, nullptr, &start, {}, &systems);
    }
    for (std::size_t i = 0; i < kept.size(); ++i) model->set_entry_value(i, kept[i]);
    progress("minimax fit", 1.0);
    return best;
}

double largest_error(const Cdt& cdt, const Image& image, const ErdModel& model, const std::vector<FaceInd>* owners) {
    if (!image.real()) return -1.0;
    return weighted_pass(cdt, image, model, owners ? *owners : owners_of(cdt, image), 0, 1.0, nullptr);
}

}  // namespace erd
