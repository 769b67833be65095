// Least-squares refit of all wedge values of an ERD model (ours, beyond the thesis).
//
// The thesis fixes each wedge value from the image near its vertex (3.4.1 step 2). Once the mesh
// is final, the approximating function is linear in the wedge values, so the values that minimise
// the squared error at the pixels can be found directly: conjugate gradients on the normal
// equations, starting from the thesis's values. A face's pixels enter those equations only
// through a 3x3 Gram matrix and a 3-vector, so one pass over the pixels assembles them and the
// iterations cost O(faces). Each pixel is evaluated with the plane of the face that owns it
// (kernel/raster.h ownership), as during ERDGPI refinement.
// A value no pixel depends on keeps its thesis value. Results are clamped to [0, maxval] (a real
// image: to its range; its pixels without data take no part).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/model/erd_model.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/result.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"
#include "kernel/raster.h"

namespace erd {

// One face's share of the refit's normal equations. With w = (w0, w1, w2) the weights of the
// face's corners at a pixel (w2 = 1 - w0 - w1) and b the pixel's sample, summed over the face's
// pixels: g = sum w w^T (symmetric: g00 g01 g02 g11 g12 g22), h = sum b w, bb = sum b^2. They
// depend on the face's corners and the image only, not on the values.
struct FaceSystem {
    std::uint32_t entry[3] = {0, 0, 0};  // the model's entries of the corners (set by the refit)
    double g[6] = {0, 0, 0, 0, 0, 0};
    double h[3] = {0, 0, 0};
    double bb = 0;
    float lo = 65535, hi = 0;  // smallest and largest sample among the face's pixels (a real image's
                               // rounded outwards)
    bool owns = false;                  // false: the face owns no pixel (the rest is zero)

    // (G v)_i for the face's values v = (a, b, c).
    void gram_times(double a, double b, double c, double out[3]) const {
        out[0] = g[0] * a + g[1] * b + g[2] * c;
        out[1] = g[1] * a + g[3] * b + g[4] * c;
        out[2] = g[2] * a + g[4] * b + g[5] * c;
    }
    // sum over the face's pixels of (approximation - b)^2 = v^T G v - 2 h.v + bb.
    double sse(double a, double b, double c) const {
        double gv[3];
        gram_times(a, b, c, gv);
        return (a * gv[0] + b * gv[1] + c * gv[2]) - 2.0 * (a * h[0] + b * h[1] + c * h[2]) + bb;
    }
};

// The system of the triangle with corners p0, p1, p2 in that order (the order of a face's
// corners 0, 1, 2) over the pixels it owns. Bit for bit what the refit's own pass over the
// pixels makes for such a face.
FaceSystem face_system(const Image& image, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2);
// The same for three planes of one size (a colour image's channels) in one pass over the pixels:
// out[k] is bit for bit face_system(*planes[k], ...).
void face_systems3(const Image* const* planes, RasterDomain domain, LatticePoint p0, LatticePoint p1, LatticePoint p2,
                   FaceSystem* out);

// The systems of a mesh's faces by face slot, kept in step with the mesh: the refit fills them
// when they are missing, and the flips (flips.h) rewrite those of the faces they flip, so the
// refits after the flips need no pass over the pixels.
// A changed face is only marked stale and made again when it is next needed (a face can change
// many times between refits).
struct MeshSystems {
    std::vector<FaceSystem> faces;
    std::vector<std::uint8_t> stale;  // by face slot: 1 = faces[f] is out of date

    bool matches(const Cdt& cdt) const { return faces.size() == cdt.face_count(); }
    void mark(FaceInd f) { stale[f] = 1; }
    // The system of face f, made again first when stale.
    const FaceSystem& get(const Cdt& cdt, const Image& image, FaceInd f);
};

// The three channels' face systems of a colour mesh by face slot, each with the corners it was made
// for: a face whose corners are still those points in that order has bit for bit the same systems,
// so the ending's refits and moves pass over the pixels of the faces flips and moves changed only.
struct ColourSystems {
    struct Terms {  // one channel's own terms (FaceSystem's h, bb, lo, hi)
        double h[3], bb;
        float lo, hi;
    };
    struct Face {  // the Gram matrix and `owns` are the same in every channel
        LatticePoint p[3];
        double g[6];
        Terms t[3];
        bool owns = false, made = false;
    };
    std::vector<Face> faces;
    // Face f's systems into out[0..3) (planes: the three channels), made again unless its corners
    // are the same.
    void get(const Cdt& cdt, const Image* const* planes, FaceInd f, FaceSystem* out);
    // Face f's systems into out[0..3) when they are those of its current corners; else false.
    bool find(const Cdt& cdt, FaceInd f, FaceSystem* out) const;
};

// Refits every wedge value of model on cdt against image by at most `iterations` CGLS steps.
// progress: "wedge refit", half for the pass over the pixels, half for the iterations.
void fit_wedge_values(const Cdt& cdt, const Image& image, int iterations, ErdModel* model, WedgeFitStats* stats,
                      ProgressHook progress = {});

// The refit's regularisation (docs/DECISIONS.md "Wedge refit bounds"). It minimises
//   sum over pixels (approximation - sample)^2 + prior_weight * sum over values (z - z_ls)^2
// where z_ls is the value's line-search value (the thesis's): a value with little pixel support
// stays near z_ls. With support_bounds each result is then clamped into the range of the samples
// of the pixels it reaches (every pixel of the faces it is a corner of), widened to hold z_ls:
// no value ends further from z_ls than the data it is fitted to.
struct WedgeFitOptions {
    int iterations = 6;         // CGLS steps
    double prior_weight = 0.0;  // lambda, in pixel observations; 0: plain least squares
    double support_bounds = -1.0;  // margin (fraction of the range) of the bounds; < 0: off
    // The faces' pixel sums on this many threads (kernel/row_parallel.h; 0: one per processor):
    // each face's system is its own, so the values are the same for any count.
    int threads = 1;
};

// As above with options. `prior`, when given, holds z_ls for the first prior->size() entries
// (the values start from the model's current ones); other entries use their current value.
// systems, when given: used when they match cdt, else made (and kept there) by the pass over the
// pixels.
void fit_wedge_values(const Cdt& cdt, const Image& image, const WedgeFitOptions& options, ErdModel* model,
                      WedgeFitStats* stats, const std::vector<double>* prior = nullptr, ProgressHook progress = {},
                      MeshSystems* systems = nullptr);

// The same for the channels of a colour image on one triangulation (models[c] on planes[c], all
// with the same wedges): each channel's refit as above with the same options, the pixel pass
// shared; (*priors)[c], when given, is channel c's `prior`.
// systems (optional, three channels): the face systems kept from the refits and moves before.
void fit_wedge_values(const Cdt& cdt, const std::vector<const Image*>& planes, const WedgeFitOptions& options,
                      const std::vector<ErdModel*>& models, std::vector<WedgeFitStats>* stats,
                      const std::vector<const std::vector<double>*>* priors = nullptr, ProgressHook progress = {},
                      ColourSystems* systems = nullptr);

}  // namespace erd
