// The ERD model (thesis 3.3) on top of the kernel's constrained Delaunay triangulation: one value
// per wedge of every vertex, the approximating function those values define, and conversion to
// erd::Model for the .erd writer.
//
// Wedges are the kernel's (Cdt::wedges, Cdt::wedge_id): a vertex with 0 or 1 incident interior
// constrained edges has one wedge, otherwise one per run of faces between constrained (or hull)
// edges. A wedge id is the direction of the wedge's negative-side bounding edge, so it survives
// insertions elsewhere and the split of that edge; the values are stored keyed by it.
//
// Wedge values (step 2 of the framework, 3.4.1):
//   one wedge   z = phi_bar(v);
//   several     line search along the unit bisector d of the wedge: v' = v + alpha d with alpha in
//               [alpha_min, alpha_max] pixels (default [0.75, 1]; the thesis's [1, 1.5] with
//               --thesis) in steps of kWedgeAlphaStep, maximising the MMSODD (defined on the
//               pixels: read at the pixel nearest v') at v' clamped into Gamma; z = phi_bar(v').
//               First maximum wins.
//   rule 0      ("fixed distance", -w 0): z = phi_bar(v + d).
// For a boundary wedge of an open fan the bounding edges are the hull edge and the constrained
// edge, so its bisector points into the image as well.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "kernel/cdt.h"
#include "kernel/raster.h"

namespace erd {

// Step of the wedge-value line search in pixels (alpha = alpha_min, alpha_min + 0.05, ..., alpha_max).
constexpr double kWedgeAlphaStep = 0.05;

struct WedgeValueOptions {
    int rule = 1;             // 1: MMSODD line search; 0: fixed distance (thesis -w)
    int smoothing_order = 5;  // binomial order of the MMSODD used by the line search (thesis -s)
    double alpha_min = 0.75;   // line-search range along the bisector, in pixels
    double alpha_max = 1.0;
    double fixed_distance = 1.0;  // rule 0: distance along the bisector, in pixels
};

// Wedge values of every vertex of one triangulation. The triangulation itself stays outside
// (the caller owns and mutates the Cdt); after each insertion call assign_vertex for the new
// vertex. Values of existing vertices never change: insertions only split constrained edges,
// which keeps every existing wedge id.
class ErdModel {
public:
    // image: the samples phi (W x H), kept by reference for the model's lifetime and read as
    // integers (no W x H double copy: bit for bit the same values). Without set_mmsodd the line
    // search computes the MMSODD at the pixels it reads (see local_).
    ErdModel(const Image& image, const WedgeValueOptions& options);

    // Supplies the MMSODD grid of the line search (it must be mmsodd(phi, smoothing_order) with
    // zero borders), so a caller that computed it already (ERDED's density) does not pay twice.
    void set_mmsodd(Grid<double> grid) {
        mmsodd_ = std::move(grid);
        have_mmsodd_ = true;
    }

    // Takes over `old`'s MMSODD (its grid or the pixels its line searches computed; a model of the
    // same image and options), so a fresh model of a changed mesh does not compute them again.
    void take_mmsodd(ErdModel& old) {
        if (old.have_mmsodd_) set_mmsodd(std::move(old.mmsodd_));
        old.have_mmsodd_ = false;
        local_ = std::move(old.local_);
        old.local_.clear();
    }

    // Computes and stores the wedge values of v from the current triangulation.
    void assign_vertex(const Cdt& cdt, VertInd v);
    // assign_vertex for every vertex.
    void assign_all(const Cdt& cdt);

    // A real image (issue 47): a real model is evaluated at each pixel on the face that owns it,
    // so at a vertex on a pixel the wedge of the owning face takes the pixel's value (its other
    // wedges keep theirs), and the vertex's own pixel has no error. assign_vertex does this for
    // every vertex it assigns; this does it again for all (after a refit moved the values). Does
    // nothing for an integer image.
    void pin_pixel_vertices(const Cdt& cdt);
    // The same for the vertices whose own pixel is more than `bound` off (the others keep their
    // fitted values; fit_minimax moves them off the samples on purpose).
    void pin_pixel_vertices(const Cdt& cdt, double bound);

    // Number of stored wedges of v (0 when never assigned).
    std::uint32_t wedge_count(VertInd v) const { return v < slots_.size() ? slots_[v].count : 0; }
    // The value of the wedge with id `id` of v, or of its only wedge. NaN when v has no such wedge.
    double wedge_value(VertInd v, WedgeId id) const;
    // The wedge value at corner e (a half-edge leaving v): the value of the wedge face e/3 lies in.
    double corner_value(const Cdt& cdt, EdgeInd e) const;
    // Mean of v's wedge values: the approximating function at v (thesis 3.3, case 2).
    double vertex_value(VertInd v) const;
    // The plane of face f through its three corner values (doubled coordinates).
    SpanPlane face_plane(const Cdt& cdt, FaceInd f) const;

    // The approximating function at lattice point p (doubled coordinates) inside the domain:
    // the face's plane inside a face or on an unconstrained edge; the mean of the two sides on a
    // constrained edge; the mean of the wedge values at a vertex.
    double evaluate(const Cdt& cdt, LatticePoint p) const;

    // The flat index of the stored wedge value that corner e uses (for fitting all values at once),
    // and the values themselves in that indexing.
    std::uint32_t corner_entry(const Cdt& cdt, EdgeInd e) const;
    // corner_value in two steps, the lookup once for models of the same wedges (ErdChannels'
    // channels): the entry corner e reads (kNoValue: none, the NaN), then that entry's value.
    static constexpr std::uint32_t kNoValue = 0xffffffffu;
    std::uint32_t corner_lookup(const Cdt& cdt, EdgeInd e) const;
    double looked_up_value(VertInd v, std::uint32_t i) const {
        if (i == kNoValue) return std::numeric_limits<double>::quiet_NaN();
        return slots_[v].count == 1 ? slots_[v].value : entries_[i].value;
    }
    std::size_t entry_count() const { return entries_.size(); }
    double entry_value(std::size_t i) const { return entries_[i].value; }
    void set_entry_value(std::size_t i, double z) {
        entries_[i].value = z;
        Slot& s = slots_[entry_vertex_[i]];
        if (s.count == 1 && s.first == i) s.value = z;  // a vertex's only value, kept in its slot too
    }

    // The line search's MMSODD at pixel (x, y) inside the image when no grid was supplied: the
    // filters of mmsodd(phi, smoothing_order) with zero borders at that pixel, computed on first
    // use and cached. Public for tests.
    double mmsodd_pixel(int x, int y);

    // Wedge-value search statistics: how many multi-wedge values were computed, and how many of
    // those had their maximum at the first / last alpha.
    struct Stats {
        std::size_t multi_wedges = 0;
        std::size_t alpha_first = 0;
        std::size_t alpha_last = 0;
    };
    const Stats& stats() const { return stats_; }

    // The ERD model of the current triangulation: vertices, per-vertex mean values, faces with
    // positive orientation, their corner (wedge) values, and the constrained edges.
    void to_model(const Cdt& cdt, int width, int height, std::uint32_t maxval, Model* out) const;

private:
    struct Entry {
        WedgeId id;
        double value;
    };
    static constexpr std::uint32_t kNoEntry = 0xffffffffu;
    // The entry of the wedge of multi-wedge vertex v that corner e lies in (kNoEntry if none):
    // the one wedge_value(v, cdt.wedge_id(e)) finds, without wedge_id's count and gcd.
    std::uint32_t multi_wedge_entry(const Cdt& cdt, VertInd v, EdgeInd e) const;
    double multi_wedge_value(const Cdt& cdt, VertInd v, const Wedge& w);
    void pin_pixel(const Cdt& cdt, VertInd v, double bound = -1.0);
    double mmsodd_near(double x, double y);  // MMSODD at the pixel nearest (x, y), grid or local

    const Image& phi_;
    WedgeValueOptions options_;
    Grid<double> mmsodd_;
    bool have_mmsodd_ = false;
    // Without a full grid the line search computes the MMSODD only at the pixels it touches
    // (ERDGPI reads well under 1% of them): the same filters, cached by pixel index in a map
    // rather than a whole W x H grid (8 bytes per pixel that were mostly never read).
    std::unordered_map<std::size_t, double> local_;
    void prepare_taps();
    double smoothed_pixel(int u, int v) const;  // S of algorithms/mmsodd.h at pixel (u, v)
    int stencil_radius_ = -1;  // radius of taps_b_ (the binomial); < 0 until the first use
    std::vector<double> taps_b_;
    // Per vertex: the index of its first entry, the number of its entries (wedges) and, for a
    // vertex of one wedge, a copy of its value: a corner's value then reads the slot alone (one
    // cache line; the entry's load missed the cache on 1-2 pixel faces: docs/log/dem-speed.md).
    struct Slot {
        std::uint32_t first = 0;
        std::uint32_t count = 0;
        double value = 0;
    };
    std::vector<Slot> slots_;
    std::vector<Entry> entries_;
    std::vector<VertInd> entry_vertex_;  // per entry: its vertex (set_entry_value's slot copy)
    std::vector<Wedge> scratch_;
    std::vector<EdgeInd> star_;
    Stats stats_;
};

// The unit bisector (in pixel units, x right, y down) of the wedge spanning positively from the
// ray along u1 to the ray along u2 (doubled-coordinate direction vectors, nonzero). Exposed for
// tests.
void wedge_bisector(LatticePoint u1, LatticePoint u2, double* dx, double* dy);

}  // namespace erd
