// Greedy point insertion (thesis 3.2.2 and 3.4.3): ONE refinement loop for GPI (basic model)
// and ERDGPI (ERD model). The loop owns the priority queue, the insertion and the stop rules;
// the model says how a face is approximated (GreedyModel below).
//
// The loop, in the thesis's words: every face f keeps cand(f), the lattice point of Lambda it
// owns with the largest absolute error, and the sum of squared errors over the points it owns;
// faces sit in an indexed max-heap keyed on that sum. Each step pops the face with the largest
// sum, inserts its candidate into the triangulation (that face as the location hint), lets the
// model assign values to the new vertex, and re-scans only the faces the kernel reports as
// created (plus any the model marks dirty); destroyed faces leave the heap. Every pixel is scanned
// by exactly one face (kernel/raster.h ownership rule), so the face sums add up to the
// whole-image squared error, which the loop keeps incrementally for the PSNR stop rule.
//
// Errors are measured at the pixel lattice Lambda (even doubled coordinates) by point evaluation
// of the face's plane (../shared/spec/NOTES.md: refinement may use point evaluation), or against
// the supersampled reconstruction (GreedyOptions::supersampled, the thesis's ERDGPI).
//
// Candidates: a lattice point that is already a vertex is never a candidate (inserting it would
// change nothing), nor is a point the model has refused (GreedyModel::admissible). Among equal
// errors the first point in scan order (top row first, then leftmost) wins. A face whose owned
// points all have error 0, or that has no admissible point, leaves the heap. When the heap is
// empty the loop stops early (e.g. a constant or planar image): GreedyStop::exhausted.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "kernel/progress.h"
#include "algorithms/methods/result.h"
#include "kernel/cdt.h"
#include "kernel/raster.h"
#include "kernel/status.h"

namespace erd {

// What the greedy loop needs from a mesh model. One instance lives for one refinement run; it may
// keep its own per-vertex or per-wedge state (values, wedge values) keyed by kernel indices.
//
//   GPI (algorithms/methods/gpi.cpp, BasicGreedyModel): the plane through the image samples at the
//       face's three vertices; on_vertex_inserted does nothing (the value of a vertex is the
//       sample at its pixel, read again in face_plane).
//   ERDGPI (erdmodel helper): the plane through the face's three wedge values (the wedge of each
//       corner in which the face lies, via cdt.wedge_id). When the inserted point lies on a
//       constrained edge the kernel split that edge; on_vertex_inserted computes the new vertex's
//       wedge values (two wedges) and may list faces whose planes changed although the kernel
//       did not recreate them.
class GreedyModel {
public:
    virtual ~GreedyModel() = default;

    // The approximating plane on face f of the current triangulation (kernel/raster.h SpanPlane,
    // the type reconstruction evaluates too, so both compute the same values). Called when a face
    // is scanned (every face when the loop starts, then each face to re-scan after an insertion,
    // always after on_vertex_inserted for that insertion) unless integer_values() answered.
    // Must be deterministic.
    virtual SpanPlane face_plane(const Cdt& cdt, FaceInd f) const = 0;

    // Called once after each insertion that created the new vertex v (cdt.changes() describes
    // the insertion and is still valid). Assign the vertex's value(s) here. Append to *dirty any
    // face, not among cdt.changes() created faces, whose plane changed (may be left empty; the
    // loop tolerates duplicates). An error status stops refinement and is returned by
    // greedy_refine.
    virtual Status on_vertex_inserted(const Cdt& cdt, VertInd v, std::vector<FaceInd>* dirty) = 0;

    // Face f's corner values (in the order of cdt.face_vertex(f, 0..2)) when they are integers,
    // as the basic model's image samples are: true and *z filled. Rounded scans
    // (GreedyOptions::round_values) then round the plane exactly (kernel/raster.h RoundedPlane),
    // as reconstruction does for such a model; otherwise (default) they step the face_plane()
    // value along each span and round that, as reconstruction does for other values. Must agree
    // with face_plane().
    virtual bool integer_values(const Cdt& cdt, FaceInd f, std::int64_t z[3]) const {
        (void)cdt;
        (void)f;
        (void)z;
        return false;
    }

    // Colour (issue 17): the number of channels the model approximates (the image's), and the
    // plane of channel c on face f. With channels() > 1 the loop calls channel_face_plane for
    // every channel instead of face_plane (and never integer_values).
    virtual int channels() const { return 1; }
    virtual SpanPlane channel_face_plane(const Cdt& cdt, FaceInd f, int c) const {
        (void)c;
        return face_plane(cdt, f);
    }

    // May the candidate point p (a pixel, even coordinates) be inserted? Asked when a face's
    // candidate reaches the top of the heap. On false the loop bans p for the rest of the run
    // (it is never a candidate again), re-scans that face and carries on. Default: always.
    virtual bool admissible(const Cdt& cdt, LatticePoint p) const {
        (void)cdt;
        (void)p;
        return true;
    }
};

// The image size from which greedy refinement re-scans on two threads when given them
// (GreedyOptions::threads): below it the hand-over costs more than it saves (docs/DECISIONS.md "Threads").
constexpr std::size_t kTwoThreadPixels = std::size_t(1) << 19;

struct GreedyOptions {
    std::size_t target_vertices = 0;  // stop when the triangulation has this many vertices
    double max_error = -1.0;          // stop when max abs error <= max_error; negative: rule off
    double psnr = 0.0;                // stop when PSNR >= psnr dB; <= 0: rule off
    // Stop when the triangulation has at least this many triangles (an insertion adds two, so it
    // ends with T or T + 1); 0: rule off.
    std::size_t max_triangles = 0;
    // Errors against the approximation rounded to the nearest integer and clamped to
    // [0, maxval] (what imgsyn reconstructs; squared errors are integers and the running total
    // exact) instead of the real-valued plane. The default is GenerateOptions::round_values's
    // (docs/DECISIONS.md "Greedy point insertion" has the numbers that chose it); ERDGPI turns it off.
    bool round_values = true;
    // Errors against the 4x4-supersampled approximation, rounded and clamped as reconstruction
    // writes it (imgsyn_aa; sub-samples outside the domain clamped onto its border), instead of
    // point evaluation: the thesis's ERDGPI "maintains the image approximation" of its model,
    // which 3.3 rasterises by supersampling (docs/DECISIONS.md "ERD reproduction"). A pixel's
    // value then depends on the faces within 3/8 pixel of it, so after an insertion the faces
    // owning the pixels the new faces reach are re-scanned too. Overrides round_values. Costs
    // 16 floats per pixel. Sub-samples on a constrained edge take the owning face's plane (the
    // reconstruction takes the mean of both sides there; they are a few per edge).
    bool supersampled = false;
    // Colour images: the candidate is the pixel with the largest single channel error instead
    // of the largest sum of squared channel errors (ColourChoices::max_channel_error).
    bool max_channel_error = false;
    // With max_error: each step takes the face of the largest error (the candidate's), not of the
    // largest sum (the rule of hmm and Garland-Heckbert's max-error greedy): fewer points for the
    // same bound. The methods set it for real images (docs/DECISIONS.md "Rasters").
    bool max_error_first = false;
    // A tile (GenerateOptions::lock_border): the pixels on the rectangle's sides are never
    // candidates (their vertices were decided before the run).
    bool ban_border = false;
    // Threads for the re-scans (resolve_threads: 0 = the machine's); the result is the same bits
    // for any count. Two are used on images of at least kTwoThreadPixels without supersampling.
    int threads = 1;
    // Optional: called as progress("greedy insertion", vertices / target) about every 1%.
    ProgressHook progress;
    // Optional, a real gray image: the face that owns each pixel in the mesh given (pixel_owners,
    // minimax_fit.h). The first scan of all faces reads it (one sweep of the rows, the same sums
    // and candidates as scanning each face), and every re-scan keeps it, so it holds the final
    // mesh's owners at the end.
    std::vector<FaceInd>* owners = nullptr;
};

// Refines `cdt` (already holding the initial mesh: the four corners for GPI; corners, polyline
// points and constraints for ERDGPI) by greedy point insertion until a stop rule holds.
// `image` must match the triangulation's domain: cdt covers [0, 2W-2] x [0, 2H-2].
// Colour images (model.channels() == image.channels > 1): errors by point evaluation of each
// channel's plane (rounded and clamped when round_values; supersampled is ignored), a pixel's
// error the sum of its squared channel errors, the PSNR that of their mean over the channels.
// Fails with Code::runtime if the kernel or the model fails; the triangulation is then valid
// but partly refined.
Status greedy_refine(Cdt& cdt, const Image& image, GreedyModel& model, const GreedyOptions& options,
                     GreedyStats* stats);

}  // namespace erd
