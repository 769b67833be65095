// Greedy point removal (Demaret and Iske's adaptive thinning; Adams's GPR): ONE removal loop for
// GPR, GPRFS (basic model), the ERD model's refinement by removal and bad-point replacement
// (bpr.h). The model says which value a vertex takes on a face (RemovalModel below).
//
// Significance of a removable vertex v (Cdt::can_remove: not a corner, on no constrained edge):
// the squared error over the pixels of v's star after v is removed and the hole retriangulated as
// the kernel will (the Delaunay triangulation of the star polygon, ties as the kernel breaks
// them: the apex scan of kernel/cdt_remove.cpp, computed here without touching the mesh), minus
// the squared error over the same pixels now. Faces keep their squared error (pixel ownership of
// kernel/raster.h, so the sums are additive); a vertex's significance is a sum over its star.
// The loop removes the vertex of least significance (ties: the first in (y, x) order), and after
// a removal only the hole's polygon vertices have stale significances: recomputed at once
// (eager) or when they reach the top of the heap (lazy, the default; docs/DECISIONS.md "Point
// removal" has the measurement).
//
// Errors: each channel's plane through the corner values by point evaluation at the pixels a
// face owns, rounded half up and clamped to [0, maxval] (round_values, the basic model's
// reconstruction) or real-valued (the ERD model, whose reconstruction is supersampled).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/imaging/image.h"
#include "algorithms/methods/heap.h"
#include "algorithms/methods/wedge_fit.h"
#include "kernel/cdt.h"
#include "kernel/progress.h"
#include "kernel/raster.h"
#include "kernel/status.h"

namespace erd {

// What removal needs from a mesh model: the value channel c of the approximation takes at
// corner e (a half-edge leaving org(e)) on the faces of that corner's wedge. Must not change while
// removal runs except through the vertices it removes.
class RemovalModel {
public:
    virtual ~RemovalModel() = default;
    virtual double corner_value(const Cdt& cdt, EdgeInd e, int c) const = 0;
    // Every channel's value at corner e into z[0 .. channels).
    virtual void corner_values(const Cdt& cdt, EdgeInd e, int channels, double* z) const {
        for (int c = 0; c < channels; ++c) z[c] = corner_value(cdt, e, c);
    }
    // Called after PointRemover::insert created vertex v: assign its values.
    virtual void on_vertex_inserted(const Cdt& cdt, VertInd v) {
        (void)cdt;
        (void)v;
    }
    // The values of a removable vertex v (one wedge), one per channel, and setting them again on a
    // vertex inserted at its place (bad-point replacement's undo). The basic model's values are
    // the samples: nothing to keep.
    virtual void save_values(const Cdt& cdt, VertInd v, std::vector<double>* out) const {
        (void)cdt;
        (void)v;
        out->clear();
    }
    virtual void restore_values(const Cdt& cdt, VertInd v, const std::vector<double>& values) {
        (void)cdt;
        (void)v;
        (void)values;
    }
};

// The basic model: a vertex's value is the image sample at its pixel (vertices must be pixels).
class SampleRemovalModel : public RemovalModel {
public:
    explicit SampleRemovalModel(const Image& image) : image_(image) {}
    double corner_value(const Cdt& cdt, EdgeInd e, int c) const override {
        const LatticePoint p = cdt.point(cdt.org(e));
        return double(image_.at(p.x / 2, p.y / 2, c));
    }

private:
    const Image& image_;
};

struct RemovalStats {
    std::size_t removed = 0;      // vertices removed
    std::size_t evaluations = 0;  // significances computed (the start's included)
    std::size_t stale_pops = 0;   // lazy: stale vertices found at the top and recomputed
};

class PointRemover {
public:
    // cdt: the mesh (any CDT; its constrained and corner vertices are never removed). Scans every
    // face once; significances are computed by start(). systems (optional; gray, real-valued
    // errors): the refit's face systems of cdt (wedge_fit.h), whose quadratic forms give the face
    // errors without that scan.
    PointRemover(Cdt& cdt, const Image& image, RemovalModel& model, bool round_values,
                 const MeshSystems* systems = nullptr);

    // Computes the significance of every removable vertex (in vertex order) and fills the heap.
    // Before it, insert() keeps only the face errors (growth by worst_pixel, as GPI grows).
    void start();
    // The significance of removable vertex v in the current mesh (not cached).
    double significance(VertInd v);
    // The triangles that will fill v's hole (positive order), as the kernel will make them; for tests.
    void hole(VertInd v, std::vector<std::array<VertInd, 3>>* out);
    // Removes v (must be removable) and updates the face errors; its polygon's vertices are
    // recomputed (eager) or marked stale (lazy).
    Status remove(VertInd v);
    // Removes vertices by least significance until the mesh has `target` live vertices or none
    // is removable. Cancelled through progress: kCancelled.
    Status run_to(std::size_t target, const ProgressHook& progress);
    // Inserts pixel point p (not a vertex) and updates face errors and the significances of the
    // vertices whose stars changed (bad-point replacement). *v receives the vertex; `values`
    // (optional) are set on it (RemovalModel::restore_values) before its faces are scanned.
    Status insert(LatticePoint p, VertInd* v, const std::vector<double>* values = nullptr);

    // Bad-point replacement's bookkeeping (bpr.h): faces in a heap by squared error, and which
    // pixels are vertices. Call before start().
    void track_faces();
    // The pixel (even doubled coordinates) of largest absolute error that is not a vertex, in the
    // face of largest squared error; false when there is none.
    bool worst_pixel(LatticePoint* p);
    // Marks pixel p as not a candidate of worst_pixel.
    void ban(LatticePoint p) { occupied_[pixel_index(p)] = 1; }

    bool lazy = true;
    const RemovalStats& stats() const { return stats_; }
    // Whole-image squared error (sum over the channels) of the current mesh.
    double total_error() const { return total_; }
    // Squared error of live face f (cached).
    double face_error(FaceInd f) const { return face_err_[f]; }
    // The least significant removable vertices first: the heap's current order is not kept, so
    // this recomputes the stale ones. Fills *out with up to `count` vertices.
    void least_significant(std::size_t count, std::vector<VertInd>* out);

private:
    double triangle_error(const LatticePoint* p, const double* z) const;  // z: 3 x channels_
    // The error of hole triangle t (tris_ indices into poly_), from the cache when it was scanned
    // before. A triangle's pixels and values depend only on its three vertices (their values never
    // change while they live, and a wedge of a polygon vertex is fixed by the triangle), and
    // vertex indices are never reused, so the cache is keyed by the vertex triple; the stars of
    // neighbouring vertices share most of their hole triangles.
    // key, hash: its cache key and hash (cache_key).
    struct CacheSlot {
        VertInd a = noVertex, b = noVertex, c = noVertex;
        double error = 0.0;
    };
    double hole_triangle_error(std::size_t t, const CacheSlot& key, std::uint64_t hash);
    // Triangle v[0..2] (positive order, any rotation) as the cache keys it: *key gets the triple
    // in the cache's rotation; returns its hash.
    static std::uint64_t cache_key(const VertInd* v, CacheSlot* key);
    // The cache slot of key: its entry, or the empty slot where it goes.
    std::size_t cache_slot(const CacheSlot& key, std::uint64_t hash);
    // The probes of a hole's (or the created faces') triangles are independent: their slots are
    // asked for ahead (the table is larger than the caches), their keys kept here.
    std::vector<std::pair<CacheSlot, std::uint64_t>> keys_;
    void prefetch_slot(std::uint64_t hash) const {
        __builtin_prefetch(&cache_[std::size_t(hash >> 20) & (cache_.size() - 1)]);
    }
    double face_error_now(FaceInd f) const;
    void face_corners(FaceInd f, LatticePoint* p, double* z) const;  // points, 3 x channels_ values
    // The errors of the faces the last kernel change created; after a removal (cached) from the
    // hole-triangle cache where it holds them.
    void rescan_created(bool cached);
    bool significance_of(VertInd v, double* sig);  // false (nothing computed) when v is not removable
    void update(VertInd v);  // recompute v's significance into the heap (or drop it)
    void touch_neighbours(const std::vector<VertInd>& around);
    // The star polygon of v into poly_ (positive order) and each vertex's value on the hole into
    // polyz_; the star's faces into star_. False when v is not removable.
    bool gather(VertInd v);
    void triangulate_hole();  // apex scan of poly_ into tris_ (index triples)

    static std::uint64_t tie_of(LatticePoint p) {
        return (std::uint64_t(std::uint32_t(p.y)) << 32) | std::uint32_t(p.x);
    }

    Cdt& cdt_;
    const Image& image_;
    RemovalModel& model_;
    bool round_ = true;
    int channels_ = 1;
    RasterDomain domain_;
    std::size_t pixel_index(LatticePoint p) const {
        return std::size_t(p.y / 2) * std::size_t(image_.width) + std::size_t(p.x / 2);
    }
    std::vector<double> face_err_;
    double total_ = 0.0;
    bool track_ = false;
    bool started_ = false;  // start() ran: significances are kept
    IndexedMaxHeap by_face_;              // track_: faces keyed on squared error
    std::vector<std::uint8_t> occupied_;  // track_: per pixel, a vertex (or banned)
    std::vector<std::uint8_t> stale_;
    IndexedMaxHeap heap_;  // removable vertices keyed on -significance
    RemovalStats stats_;
    std::vector<VertInd> poly_;
    std::vector<double> polyz_;
    std::vector<FaceInd> star_;
    std::vector<std::uint32_t> tris_;
    std::vector<std::uint32_t> stack_;
    std::vector<EdgeInd> corners_;
    std::vector<VertInd> around_;
    std::vector<CacheSlot> cache_;  // open addressing, linear probing; emptied when half full
    std::size_t cache_used_ = 0;
};

// The removal methods (GPR, GPRFS, ID, ERDGPR) work on integer samples: a real-valued raster
// (issue 47) is refused with Code::input naming the method and the ones that take it.
Status removal_accepts(const Image& image, const char* method);

// Live points of cdt other than the four corners, in vertex order.
std::vector<LatticePoint> live_points(const Cdt& cdt);

// A fresh CDT of the live vertices and constrained edges of cdt: the same triangulation (the CDT
// is unique) with vertex indices and face slots compact again, as the model writers need.
// *to (optional): old vertex -> new vertex, noVertex for the dead.
Status compact_cdt(const Cdt& cdt, Cdt* out, std::vector<VertInd>* to = nullptr);

}  // namespace erd
