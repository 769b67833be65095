#include "algorithms/methods/wedge_fit.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/raster.h"
#include "kernel/raster_rows.h"
#include "kernel/row_parallel.h"

namespace erd {

namespace {

// The systems of the triangle (p0, p1, p2) for each of the N images (one, or the channel planes
// of a colour image: the Gram matrix is the same, made once), over the pixels the triangle owns.
// The rows are the triangle's owned rows, top to bottom, walked directly (kernel/raster_rows.h):
// the rows and columns scan_triangle's spans hold, without the list in between. Real: the images'
// real planes, the pixels without data left out (issue 47).
template <int N, bool Real>
void accumulate(const Image* const* images, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2,
                FaceSystem* out) {
    SpanPlane l0, l1;  // the weights of corners 0 and 1 as planes
    l0.set(p0, 1.0, p1, 0.0, p2, 0.0);
    l1.set(p0, 0.0, p1, 1.0, p2, 0.0);
    // The weights are l.at(X, Y) = (z0 + gx (X - x0)) + gy (Y - y0) with z0 = 1 for l0 and 0
    // for l1, computed below with the same roundings in the same order: X - x0 is an exact
    // small integer stepped by 2, and dropping l1's "0 +" changes at most the sign of a zero
    // weight, which no sum below can see (the sums start at +0, and +0 + -0 = +0).
    const double gx0 = l0.gx, gx1 = l1.gx;
    double g00 = 0, g01 = 0, g02 = 0, g11 = 0, g12 = 0, g22 = 0, h0[N] = {}, h1[N] = {}, h2[N] = {};
    std::uint64_t bb[N] = {};  // sum b^2 in integers: exact, and what the double sum gave while exact
    double rbb[N] = {}, rlo[N], rhi[N];  // a real image's sum b^2 and range
    std::uint16_t lo[N], hi[N];
    for (int k = 0; k < N; ++k) lo[k] = 0xffff, hi[k] = 0, rlo[k] = HUGE_VAL, rhi[k] = -HUGE_VAL;
    const std::uint8_t* ok = Real && !images[0]->valid.empty() ? images[0]->valid.data() : nullptr;
    bool owns = false;
    for_each_owned_row(Lattice::pixels(), domain, p0, p1, p2, [&](std::int32_t j, std::int32_t first, std::int32_t last) {
        const double Y = double(2 * j);
        const double t0 = l0.gy * (Y - l0.y0), t1 = l1.gy * (Y - l1.y0);
        const std::size_t row = std::size_t(j) * std::size_t(images[0]->width);
        const std::uint16_t* px[N];
        const double* rx[N];
        for (int k = 0; k < N; ++k) {
            if constexpr (Real) rx[k] = &images[k]->reals[row];
            else px[k] = &images[k]->samples[row];
        }
        if constexpr (!Real) owns = true;
        double a = double(2 * first) - l0.x0;
        for (std::int32_t i = first; i <= last; ++i, a += 2.0) {
            if constexpr (Real) {
                if (ok && !ok[row + std::size_t(i)]) continue;
                owns = true;
            }
            const double w0 = (1.0 + gx0 * a) + t0, w1 = gx1 * a + t1;
            const double w2 = 1.0 - w0 - w1;
            g00 += w0 * w0;
            g01 += w0 * w1;
            g02 += w0 * w2;
            g11 += w1 * w1;
            g12 += w1 * w2;
            g22 += w2 * w2;
            for (int k = 0; k < N; ++k) {
                if constexpr (Real) {
                    const double b = rx[k][i];
                    h0[k] += b * w0;
                    h1[k] += b * w1;
                    h2[k] += b * w2;
                    rbb[k] += b * b;
                    rlo[k] = b < rlo[k] ? b : rlo[k];
                    rhi[k] = b > rhi[k] ? b : rhi[k];
                } else {
                    const std::uint16_t v = px[k][i];
                    const double b = double(v);
                    h0[k] += b * w0;
                    h1[k] += b * w1;
                    h2[k] += b * w2;
                    bb[k] += std::uint64_t(v) * v;
                    lo[k] = v < lo[k] ? v : lo[k];
                    hi[k] = v > hi[k] ? v : hi[k];
                }
            }
        }
    });
    if (!owns) return;
    for (int k = 0; k < N; ++k) {
        FaceSystem& fs = out[k];
        const double g[6] = {g00, g01, g02, g11, g12, g22};
        for (int j = 0; j < 6; ++j) fs.g[j] = g[j];
        fs.h[0] = h0[k];
        fs.h[1] = h1[k];
        fs.h[2] = h2[k];
        if constexpr (Real) {
            // The range as floats rounded outwards: it only bounds the refit's values.
            fs.bb = rbb[k];
            fs.lo = std::nextafter(float(rlo[k]), -HUGE_VALF);
            fs.hi = std::nextafter(float(rhi[k]), HUGE_VALF);
        } else {
            fs.bb = double(bb[k]);
            fs.lo = lo[k];
            fs.hi = hi[k];
        }
        fs.owns = true;
    }
}

template <int N>
void accumulate(const Image* const* images, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2,
                FaceSystem* out) {
    if (images[0]->real()) accumulate<N, true>(images, domain, p0, p1, p2, out);
    else accumulate<N, false>(images, domain, p0, p1, p2, out);
}

// A face system's terms of one more channel of a colour image: those that depend on the samples
// (the Gram matrix and the entries depend on the triangle alone, and are channel 0's).
struct ChannelTerms {
    double h[3];
    double bb;
    float lo, hi;
};

// Faces' pixel sums in parts of at least this many faces, one thread each (a face of a 1% mesh
// is tens of pixels: a part is a few tenths of a millisecond at least).
constexpr std::size_t kMinPartFaces = 4096;

// Assembles the face systems of every face that owns at least one pixel, for each of the N
// images: faces holds image 0's, more[k - 1] image k's own terms. Every face's sums go to its own
// slot on `threads` threads; the faces that own no pixel are then dropped in order.
template <int N>
void face_systems(const Cdt& cdt, const Image* const* images, const ErdModel& model, std::vector<FaceSystem>* faces,
                  std::vector<ChannelTerms>* more, int threads) {
    const RasterDomain domain{cdt.max_x(), cdt.max_y()};
    const std::size_t nf = cdt.face_count();
    faces->assign(nf, FaceSystem());
    for (int k = 1; k < N; ++k) more[k - 1].assign(nf, ChannelTerms());
    parallel_rows(0, nf, threads, kMinPartFaces, [&](std::size_t f0, std::size_t f1) {
        for (std::size_t f = f0; f < f1; ++f) {
            const EdgeInd e = 3 * EdgeInd(f);
            const LatticePoint p0 = cdt.point(cdt.org(e)), p1 = cdt.point(cdt.org(e + 1)), p2 = cdt.point(cdt.org(e + 2));
            FaceSystem fs[N];
            accumulate<N>(images, domain, p0, p1, p2, fs);
            if (!fs[0].owns) continue;
            for (int j = 0; j < 3; ++j) fs[0].entry[j] = model.corner_entry(cdt, e + EdgeInd(j));
            (*faces)[f] = fs[0];
            for (int k = 1; k < N; ++k)
                more[k - 1][f] = ChannelTerms{{fs[k].h[0], fs[k].h[1], fs[k].h[2]}, fs[k].bb, fs[k].lo, fs[k].hi};
        }
    });
    std::size_t n = 0;
    for (std::size_t f = 0; f < nf; ++f) {
        if (!(*faces)[f].owns) continue;
        (*faces)[n] = (*faces)[f];
        for (int k = 1; k < N; ++k) more[k - 1][n] = more[k - 1][f];
        ++n;
    }
    faces->resize(n);
    for (int k = 1; k < N; ++k) more[k - 1].resize(n);
}

// The systems solve() reads: faces, with the data terms of `terms` instead of their own when given
// (another channel of the same faces).
struct Systems {
    const std::vector<FaceSystem>& faces;
    const std::vector<ChannelTerms>* terms = nullptr;
    const double* h(std::size_t i) const { return terms ? (*terms)[i].h : faces[i].h; }
    double bb(std::size_t i) const { return terms ? (*terms)[i].bb : faces[i].bb; }
    float lo(std::size_t i) const { return terms ? (*terms)[i].lo : faces[i].lo; }
    float hi(std::size_t i) const { return terms ? (*terms)[i].hi : faces[i].hi; }
    // FaceSystem::sse with face i's Gram matrix and these terms.
    double sse(std::size_t i, double a, double b, double c) const {
        double gv[3];
        faces[i].gram_times(a, b, c, gv);
        const double* hh = h(i);
        return (a * gv[0] + b * gv[1] + c * gv[2]) - 2.0 * (a * hh[0] + b * hh[1] + c * hh[2]) + bb(i);
    }
};

double total_sse(const Systems& sys, const std::vector<double>& x) {
    double sse = 0;
    for (std::size_t i = 0; i < sys.faces.size(); ++i) {
        const FaceSystem& fs = sys.faces[i];
        if (fs.owns) sse += sys.sse(i, x[fs.entry[0]], x[fs.entry[1]], x[fs.entry[2]]);
    }
    return sse > 0 ? sse : 0.0;  // an exact fit can leave a rounding residue below zero
}

// The CGLS refit of model's values from its face systems (regularised as options says; prior as
// for fit_wedge_values).
void solve(const Systems& sys, const Image& image, const WedgeFitOptions& options, ErdModel* model,
           WedgeFitStats* stats, const std::vector<double>* prior, const ProgressHook& progress) {
    const std::vector<FaceSystem>& faces = sys.faces;
    const std::size_t n = model->entry_count();
    const double lambda = options.prior_weight > 0 ? options.prior_weight : 0.0;

    // out = (A^T A + lambda I) v, assembled from the face Gram matrices.
    auto normal_times = [&](const std::vector<double>& v, std::vector<double>* out) {
        std::fill(out->begin(), out->end(), 0.0);
        for (const FaceSystem& fs : faces) {
            if (!fs.owns) continue;
            double gv[3];
            fs.gram_times(v[fs.entry[0]], v[fs.entry[1]], v[fs.entry[2]], gv);
            for (int j = 0; j < 3; ++j) (*out)[fs.entry[j]] += gv[j];
        }
        if (lambda > 0)
            for (std::size_t i = 0; i < v.size(); ++i) (*out)[i] += lambda * v[i];
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double t = 0;
        for (std::size_t i = 0; i < a.size(); ++i) t += a[i] * b[i];
        return t;
    };

    // Jacobi preconditioning: solve for y with x = x0 + S y, S = diag(1 / |column of A|), so the
    // values of big and small faces converge at the same rate (10 steps then do what 30 did).
    std::vector<double> scale(n, lambda);
    for (const FaceSystem& fs : faces)
        if (fs.owns)
            for (int j = 0; j < 3; ++j) scale[fs.entry[j]] += fs.g[j == 0 ? 0 : j == 1 ? 3 : 5];
    for (double& c : scale) c = c > 1e-12 ? 1.0 / std::sqrt(c) : 0.0;

    std::vector<double> x(n), y(n, 0.0), s(n), p(n), ps(n), q(n), x0(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = model->entry_value(i);
    // The value each one is drawn towards and bounded around: its line-search value.
    for (std::size_t i = 0; i < n; ++i) x0[i] = prior && i < prior->size() ? (*prior)[i] : x[i];
    if (stats) stats->sse_before = total_sse(sys, x);
    // s = S (A^T b + lambda x0 - (A^T A + lambda I) x), the preconditioned residual at y = 0.
    normal_times(x, &q);
    std::fill(s.begin(), s.end(), 0.0);
    for (std::size_t f = 0; f < faces.size(); ++f)
        if (faces[f].owns)
            for (int j = 0; j < 3; ++j) s[faces[f].entry[j]] += sys.h(f)[j];
    for (std::size_t i = 0; i < n; ++i) s[i] = scale[i] * (s[i] + lambda * x0[i] - q[i]);
    p = s;
    double gamma = dot(s, s);
    int it = 0;
    for (; it < options.iterations && gamma > 1e-12; ++it) {
        progress("wedge refit", 0.5 + 0.5 * double(it) / double(options.iterations));
        for (std::size_t i = 0; i < n; ++i) ps[i] = scale[i] * p[i];
        normal_times(ps, &q);
        const double pq = dot(ps, q);  // |A S p|^2 (+ lambda |S p|^2)
        if (pq <= 0) break;
        const double alpha = gamma / pq;
        for (std::size_t i = 0; i < n; ++i) {
            y[i] += alpha * p[i];
            s[i] -= alpha * scale[i] * q[i];
        }
        const double g2 = dot(s, s);
        const double beta = g2 / gamma;
        gamma = g2;
        for (std::size_t i = 0; i < n; ++i) p[i] = s[i] + beta * p[i];
    }
    // Bounds: [0, maxval] (a real image: its range lo..hi), and with support_bounds the range of
    // the samples the value reaches (every pixel of the faces it is a corner of) widened to take in
    // its line-search value.
    std::vector<double> lo(n, image.real() ? image.lo : 0.0), hi(n, image.real() ? image.hi : double(image.maxval));
    if (options.support_bounds >= 0) {
        std::vector<double> a(n), b(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = b[i] = x0[i];
        for (std::size_t f = 0; f < faces.size(); ++f)
            for (int j = 0; j < 3 && faces[f].owns; ++j) {
                const std::uint32_t k = faces[f].entry[j];
                if (double(sys.lo(f)) < a[k]) a[k] = double(sys.lo(f));
                if (double(sys.hi(f)) > b[k]) b[k] = double(sys.hi(f));
            }
        for (std::size_t i = 0; i < n; ++i) {
            const double m = options.support_bounds * (b[i] - a[i]);
            lo[i] = std::max(lo[i], a[i] - m);
            hi[i] = std::min(hi[i], b[i] + m);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double v = x[i] + scale[i] * y[i];
        x[i] = v < lo[i] ? lo[i] : (v > hi[i] ? hi[i] : v);
        model->set_entry_value(i, x[i]);
    }
    if (stats) {
        stats->iterations = it;
        stats->sse_after = total_sse(sys, x);
    }
}

}  // namespace

FaceSystem face_system(const Image& image, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2) {
    FaceSystem fs;
    const Image* one = &image;
    accumulate<1>(&one, domain, p0, p1, p2, &fs);
    return fs;
}

void face_systems3(const Image* const* planes, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2,
                   FaceSystem* out) {
    // accumulate<3> sums each channel's terms as accumulate<1> does, the Gram matrix once.
    for (int k = 0; k < 3; ++k) out[k] = FaceSystem();
    accumulate<3>(planes, domain, p0, p1, p2, out);
}

bool ColourSystems::find(const Cdt& cdt, FaceInd f, FaceSystem* out) const {
    if (f >= faces.size() || !faces[f].made) return false;
    const Face& c = faces[f];
    for (int j = 0; j < 3; ++j) {
        const LatticePoint p = cdt.point(cdt.org(3 * f + EdgeInd(j)));
        if (p.x != c.p[j].x || p.y != c.p[j].y) return false;
    }
    for (int k = 0; k < 3; ++k) {
        FaceSystem& s = out[k];
        s = FaceSystem();
        for (int j = 0; j < 6; ++j) s.g[j] = c.g[j];
        for (int j = 0; j < 3; ++j) s.h[j] = c.t[k].h[j];
        s.bb = c.t[k].bb;
        s.lo = c.t[k].lo;
        s.hi = c.t[k].hi;
        s.owns = c.owns;
    }
    return true;
}

void ColourSystems::get(const Cdt& cdt, const Image* const* planes, FaceInd f, FaceSystem* out) {
    if (find(cdt, f, out)) return;
    if (faces.size() < cdt.face_count()) faces.resize(cdt.face_count());
    Face& c = faces[f];
    for (int j = 0; j < 3; ++j) c.p[j] = cdt.point(cdt.org(3 * f + EdgeInd(j)));
    face_systems3(planes, RasterDomain{cdt.max_x(), cdt.max_y()}, c.p[0], c.p[1], c.p[2], out);
    for (int j = 0; j < 6; ++j) c.g[j] = out[0].g[j];  // accumulate<3> gives every channel the same
    for (int k = 0; k < 3; ++k) c.t[k] = Terms{{out[k].h[0], out[k].h[1], out[k].h[2]}, out[k].bb, out[k].lo, out[k].hi};
    c.owns = out[0].owns;
    c.made = true;
}

const FaceSystem& MeshSystems::get(const Cdt& cdt, const Image& image, FaceInd f) {
    if (stale[f]) {
        const EdgeInd e = 3 * f;
        faces[f] = face_system(image, RasterDomain{cdt.max_x(), cdt.max_y()}, cdt.point(cdt.org(e)),
                               cdt.point(cdt.org(e + 1)), cdt.point(cdt.org(e + 2)));
        stale[f] = 0;
    }
    return faces[f];
}

void fit_wedge_values(const Cdt& cdt, const Image& image, int iterations, ErdModel* model, WedgeFitStats* stats,
                      ProgressHook progress) {
    WedgeFitOptions o;
    o.iterations = iterations;
    fit_wedge_values(cdt, image, o, model, stats, nullptr, progress);
}

void fit_wedge_values(const Cdt& cdt, const Image& image, const WedgeFitOptions& options, ErdModel* model,
                      WedgeFitStats* stats, const std::vector<double>* prior, ProgressHook progress,
                      MeshSystems* systems) {
    progress("wedge refit", 0.0);
    if (systems) {
        // The systems by face slot are solved in place (the faces that own no pixel are skipped
        // there): the same faces in the same order as the pass over the pixels lists, without a
        // second copy of them beside the mesh's.
        // Each face's system in its own slot, on the options' threads.
        if (!systems->matches(cdt)) {
            systems->faces.assign(cdt.face_count(), FaceSystem());
            systems->stale.assign(cdt.face_count(), 1);
        }
        parallel_rows(0, cdt.face_count(), options.threads, kMinPartFaces, [&](std::size_t f0, std::size_t f1) {
            for (std::size_t f = f0; f < f1; ++f) systems->get(cdt, image, FaceInd(f));
        });
        for (FaceInd f = 0; f < cdt.face_count(); ++f) {
            FaceSystem& fs = systems->faces[f];
            if (fs.owns)
                for (int j = 0; j < 3; ++j) fs.entry[j] = model->corner_entry(cdt, 3 * f + EdgeInd(j));
        }
        progress("wedge refit", 0.5);
        solve(Systems{systems->faces}, image, options, model, stats, prior, progress);
        return;
    }
    std::vector<FaceSystem> faces;
    const Image* one = &image;
    face_systems<1>(cdt, &one, *model, &faces, nullptr, options.threads);
    progress("wedge refit", 0.5);
    solve(Systems{faces}, image, options, model, stats, prior, progress);
}

void fit_wedge_values(const Cdt& cdt, const std::vector<const Image*>& planes, const WedgeFitOptions& options,
                      const std::vector<ErdModel*>& models, std::vector<WedgeFitStats>* stats,
                      const std::vector<const std::vector<double>*>* priors, ProgressHook progress,
                      ColourSystems* systems) {
    stats->assign(planes.size(), WedgeFitStats());
    auto prior = [&](std::size_t c) { return priors && c < priors->size() ? (*priors)[c] : nullptr; };
    if (planes.size() != 3 || models.size() != 3) {
        for (std::size_t c = 0; c < planes.size() && c < models.size(); ++c)
            fit_wedge_values(cdt, *planes[c], options, models[c], &(*stats)[c], prior(c),
                             c + 1 == planes.size() ? progress : ProgressHook());
        return;
    }
    progress("wedge refit", 0.0);
    // One list of systems (channel 0's) and the other channels' own terms beside it: the three
    // channels' wedges are the same, so are their entries and Gram matrices.
    std::vector<FaceSystem> faces;
    std::vector<ChannelTerms> more[2];
    if (systems) {  // as face_systems<3>, each face's systems kept or made again
        faces.reserve(cdt.face_count());
        for (auto& m : more) m.reserve(cdt.face_count());
        for (FaceInd f = 0; f < cdt.face_count(); ++f) {
            FaceSystem fs[3];
            systems->get(cdt, planes.data(), f, fs);
            if (!fs[0].owns) continue;
            faces.push_back(fs[0]);
            for (int j = 0; j < 3; ++j) faces.back().entry[j] = models[0]->corner_entry(cdt, 3 * f + EdgeInd(j));
            for (int k = 1; k < 3; ++k)
                more[k - 1].push_back(ChannelTerms{{fs[k].h[0], fs[k].h[1], fs[k].h[2]}, fs[k].bb, fs[k].lo, fs[k].hi});
        }
    } else {
        face_systems<3>(cdt, planes.data(), *models[0], &faces, more, options.threads);
    }
    progress("wedge refit", 0.5);
    // The progress of the last channel's iterations stands for all three (it must not go back).
    for (std::size_t c = 0; c < 3; ++c)
        solve(Systems{faces, c == 0 ? nullptr : &more[c - 1]}, *planes[c], options, models[c], &(*stats)[c], prior(c),
              c == 2 ? progress : ProgressHook());
}

}  // namespace erd
