// Least-squares refit of all wedge values of an ERD model (ours, beyond the thesis).
//
// The thesis fixes each wedge value from the image near its vertex (3.4.1 step 2). Once the mesh
// is final, the approximating function is linear in the wedge values, so the values that minimise
// the squared error at the pixels can be found directly: conjugate gradients on the normal
// equations, starting from the thesis's values. A face's pixels enter those equations only
// through a 3x3 Gram matrix and a 3-vector, so one pass over the pixels assembles them and the
// iterations cost O(faces). Each pixel is evaluated with the plane of the face that owns it
// (kernel/raster.h ownership), as during ERDGPI refinement.
// A value no pixel depends on keeps its thesis value. Results are clamped to [0, maxval].
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "algorithms/model/erd_model.h"
#include "algorithms/imaging/image.h"
#include "algorithms/methods/result.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"

namespace erd {

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
};

// The pixel pass of a refit, kept for the next refit of the same image: a face whose three
// corners are where they were (in the same order) has the same pixels and the same sums, so the
// refit after the flips rescans only the faces the flips made. The values it gives are the
// ones a fresh pass gives, bit for bit.
class WedgeFitCache {
public:
    WedgeFitCache();
    ~WedgeFitCache();
    WedgeFitCache(const WedgeFitCache&) = delete;
    WedgeFitCache& operator=(const WedgeFitCache&) = delete;

    struct Faces;
    std::unique_ptr<Faces> faces;
};

// As above with options. `prior`, when given, holds z_ls for the first prior->size() entries
// (the values start from the model's current ones); other entries use their current value.
// `cache`, when given, is read and updated (it must have seen only this image).
void fit_wedge_values(const Cdt& cdt, const Image& image, const WedgeFitOptions& options, ErdModel* model,
                      WedgeFitStats* stats, const std::vector<double>* prior = nullptr, ProgressHook progress = {},
                      WedgeFitCache* cache = nullptr);

// The same for the channels of a colour image on one triangulation (models[c] on planes[c], all
// with the same wedges): each channel's refit as above with the same options, the pixel pass
// shared; (*priors)[c], when given, is channel c's `prior`.
void fit_wedge_values(const Cdt& cdt, const std::vector<const Image*>& planes, const WedgeFitOptions& options,
                      const std::vector<ErdModel*>& models, std::vector<WedgeFitStats>* stats,
                      const std::vector<const std::vector<double>*>* priors = nullptr, ProgressHook progress = {});

}  // namespace erd
