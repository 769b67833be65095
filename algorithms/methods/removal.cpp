// Greedy point removal (removal.h): face errors, the hole's triangulation, the lazy heap.
#include "algorithms/methods/removal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "kernel/predicates.h"
#include "kernel/raster_rows.h"

namespace erd {

PointRemover::PointRemover(Cdt& cdt, const Image& image, RemovalModel& model, bool round_values,
                           const MeshSystems* systems)
    : cdt_(cdt), image_(image), model_(model), round_(round_values), channels_(image.channels) {
    domain_ = RasterDomain{cdt.max_x(), cdt.max_y()};
    face_err_.assign(cdt.face_count(), 0.0);
    const bool quadratic = systems && systems->matches(cdt) && !round_ && channels_ == 1;
    for (FaceInd f = 0; f < cdt.face_count(); ++f) {
        if (!cdt.face_live(f)) continue;
        if (quadratic && !systems->stale[f]) {
            LatticePoint p[3];
            double z[3];
            face_corners(f, p, z);
            total_ += face_err_[f] = std::max(0.0, systems->faces[f].sse(z[0], z[1], z[2]));
        } else {
            total_ += face_err_[f] = face_error_now(f);
        }
    }
}

void PointRemover::track_faces() {
    track_ = true;
    by_face_.reserve(cdt_.face_count());
    for (FaceInd f = 0; f < cdt_.face_count(); ++f)
        if (cdt_.face_live(f)) by_face_.set(f, face_err_[f], f);
    occupied_.assign(image_.pixels(), 0);
    for (VertInd v = 0; v < cdt_.vertex_count(); ++v) {
        const LatticePoint p = cdt_.point(v);
        if (cdt_.vertex_live(v) && !(p.x & 1) && !(p.y & 1)) occupied_[pixel_index(p)] = 1;
    }
}

bool PointRemover::worst_pixel(LatticePoint* out) {
    if (by_face_.empty()) return false;
    const FaceInd f = by_face_.top();
    LatticePoint p[3];
    double z[3 * 3];
    face_corners(f, p, z);
    SpanPlane planes[3];
    for (int c = 0; c < channels_; ++c) planes[c].set(p[0], z[c], p[1], z[channels_ + c], p[2], z[2 * channels_ + c]);
    const std::size_t width = std::size_t(image_.width), nc = std::size_t(channels_);
    double best = -1.0;
    for_each_owned_row(Lattice::pixels(), domain_, p[0], p[1], p[2], [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
        for (std::int32_t x = lo; x <= hi; ++x) {
            if (occupied_[std::size_t(j) * width + std::size_t(x)]) continue;
            double e2 = 0.0;
            for (int c = 0; c < channels_; ++c) {
                const double e = double(image_.samples[(std::size_t(j) * width + std::size_t(x)) * nc + std::size_t(c)]) -
                                 planes[c].at(double(2 * x), double(2 * j));
                e2 += e * e;
            }
            if (e2 > best) {
                best = e2;
                *out = LatticePoint{2 * x, 2 * j};
            }
        }
    });
    return best > 0.0;
}

double PointRemover::triangle_error(const LatticePoint* p, const double* z) const {
    const double maxval = double(image_.maxval);
    const std::size_t width = std::size_t(image_.width), nc = std::size_t(channels_);
    const std::uint16_t* samples = image_.samples.data();
    double total = 0.0;
    if (!round_ && channels_ > 1 && channels_ <= 3) {
        // The ERD model's colour errors: one pass over the face's pixels for all channels, each
        // channel's sum in the order the one-channel loop below takes (the same doubles).
        SpanPlane planes[3];
        double dv[3], sums[3] = {0.0, 0.0, 0.0};
        for (int c = 0; c < channels_; ++c) {
            planes[c].set(p[0], z[c], p[1], z[channels_ + c], p[2], z[2 * channels_ + c]);
            dv[c] = 2.0 * planes[c].gx;
        }
        for_each_owned_row(Lattice::pixels(), domain_, p[0], p[1], p[2], [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            const std::uint16_t* px = samples + (std::size_t(j) * width + std::size_t(lo)) * nc;
            if (nc == 3) {
                double v0 = planes[0].at(double(2 * lo), double(2 * j)), v1 = planes[1].at(double(2 * lo), double(2 * j)),
                       v2 = planes[2].at(double(2 * lo), double(2 * j));
                double s0 = sums[0], s1 = sums[1], s2 = sums[2];
                for (std::int32_t x = lo; x <= hi; ++x, px += 3, v0 += dv[0], v1 += dv[1], v2 += dv[2]) {
                    const double e0 = double(px[0]) - v0, e1 = double(px[1]) - v1, e2 = double(px[2]) - v2;
                    s0 += e0 * e0;
                    s1 += e1 * e1;
                    s2 += e2 * e2;
                }
                sums[0] = s0;
                sums[1] = s1;
                sums[2] = s2;
                return;
            }
            for (int c = 0; c < channels_; ++c) {
                double v = planes[c].at(double(2 * lo), double(2 * j)), sum = sums[c];
                const std::uint16_t* q = px + c;
                for (std::int32_t x = lo; x <= hi; ++x, v += dv[c], q += nc) {
                    const double e = double(*q) - v;
                    sum += e * e;
                }
                sums[c] = sum;
            }
        });
        for (int c = 0; c < channels_; ++c) total += sums[c];
        return total;
    }
    for (int c = 0; c < channels_; ++c) {
        const double z0 = z[c], z1 = z[channels_ + c], z2 = z[2 * channels_ + c];
        // Integer values (the basic model's samples) round exactly, as reconstruction does, so
        // a face's error does not depend on the order of its corners.
        RoundedPlane exact;
        const bool is_exact = round_ && z0 == std::floor(z0) && z1 == std::floor(z1) && z2 == std::floor(z2) &&
                              exact.set(p[0], std::int64_t(z0), p[1], std::int64_t(z1), p[2], std::int64_t(z2),
                                        std::int64_t(image_.maxval));
        SpanPlane plane;
        if (!is_exact) plane.set(p[0], z0, p[1], z1, p[2], z2);
        const double dv = 2.0 * plane.gx;
        double sum = 0.0;
        for_each_owned_row(Lattice::pixels(), domain_, p[0], p[1], p[2], [&](std::int32_t j, std::int32_t lo, std::int32_t hi) {
            const std::uint16_t* row = samples + std::size_t(j) * width * nc + std::size_t(c);
            if (is_exact) {
                exact.pieces(lo, hi, j, [&](std::int32_t first, std::int32_t last, double v) {
                    for (std::int32_t x = first; x <= last; ++x, v += exact.dp) {
                        const double e = double(row[std::size_t(x) * nc]) - double(std::int32_t(v));
                        sum += e * e;
                    }
                });
                return;
            }
            double v = plane.at(double(2 * lo), double(2 * j));
            if (!round_) {  // the ERD model's real-valued errors: the loop without the rounding test
                const std::uint16_t* px = row + std::size_t(lo) * nc;
                for (std::int32_t x = lo; x <= hi; ++x, v += dv, px += nc) {
                    const double e = double(*px) - v;
                    sum += e * e;
                }
                return;
            }
            for (std::int32_t x = lo; x <= hi; ++x, v += dv) {
                const double cl = v < maxval ? v : maxval;
                const std::int32_t r = std::int32_t(cl + 0.5);
                const double a = r < 0 ? 0.0 : double(r);
                const double e = double(row[std::size_t(x) * nc]) - a;
                sum += e * e;
            }
        });
        total += sum;
    }
    return total;
}

void PointRemover::face_corners(FaceInd f, LatticePoint* p, double* z) const {
    for (int i = 0; i < 3; ++i) {
        const EdgeInd e = 3 * f + EdgeInd(i);
        p[i] = cdt_.point(cdt_.org(e));
        model_.corner_values(cdt_, e, channels_, z + i * channels_);
    }
}

double PointRemover::face_error_now(FaceInd f) const {
    LatticePoint p[3];
    double z[3 * 3];
    face_corners(f, p, z);
    return triangle_error(p, z);
}

bool PointRemover::gather(VertInd v) {
    if (!cdt_.can_remove(v)) return false;
    cdt_.corners_around(v, &corners_);
    poly_.clear();
    polyz_.clear();
    star_.clear();
    // Corner e = v -> q_i stands for face (v, q_i, q_i+1); next(e) leaves q_i inside that face.
    for (EdgeInd e : corners_) {
        star_.push_back(face_of(e));
        const EdgeInd at_q = next_edge(e);
        poly_.push_back(cdt_.org(at_q));
        polyz_.resize(polyz_.size() + std::size_t(channels_));
        model_.corner_values(cdt_, at_q, channels_, polyz_.data() + polyz_.size() - std::size_t(channels_));
    }
    if (cdt_.on_boundary(v)) {  // open fan: the last neighbour closes it
        const EdgeInd at_q = prev_edge(corners_.back());
        poly_.push_back(cdt_.org(at_q));
        polyz_.resize(polyz_.size() + std::size_t(channels_));
        model_.corner_values(cdt_, at_q, channels_, polyz_.data() + polyz_.size() - std::size_t(channels_));
    }
    return true;
}

// The apex scan (kernel/cdt_remove.cpp): sub-polygon q_i .. q_j with base q_j -> q_i and the rest
// on its left; the apex is the vertex strictly left of the base whose circle with it holds no
// other such vertex, found in one pass of the kernel's perturbed in-circle test.
void PointRemover::triangulate_hole() {
    tris_.clear();
    stack_.clear();
    const std::uint32_t m = std::uint32_t(poly_.size());
    stack_.push_back(0);
    stack_.push_back(m - 1);
    while (!stack_.empty()) {
        const std::uint32_t j = stack_.back();
        stack_.pop_back();
        const std::uint32_t i = stack_.back();
        stack_.pop_back();
        if (j < i + 2) continue;
        const LatticePoint a = cdt_.point(poly_[j]), b = cdt_.point(poly_[i]);
        std::uint32_t k = noVertex;
        for (std::uint32_t l = i + 1; l < j; ++l) {
            const LatticePoint d = cdt_.point(poly_[l]);
            if (orient2d(a, b, d) <= 0) continue;
            if (k == noVertex || incircle_perturbed(a, b, cdt_.point(poly_[k]), d) > 0) k = l;
        }
        if (k == noVertex) continue;  // cannot happen for a star polygon
        tris_.push_back(j);
        tris_.push_back(i);
        tris_.push_back(k);
        stack_.push_back(i);
        stack_.push_back(k);
        stack_.push_back(k);
        stack_.push_back(j);
    }
}

void PointRemover::hole(VertInd v, std::vector<std::array<VertInd, 3>>* out) {
    out->clear();
    if (!gather(v)) return;
    triangulate_hole();
    for (std::size_t t = 0; t < tris_.size(); t += 3) out->push_back({poly_[tris_[t]], poly_[tris_[t + 1]], poly_[tris_[t + 2]]});
}

std::uint64_t PointRemover::cache_key(const VertInd* v, CacheSlot* key) {
    const int r = v[1] < v[0] ? (v[2] < v[1] ? 2 : 1) : (v[2] < v[0] ? 2 : 0);  // rotate the smallest first
    *key = CacheSlot{v[r], v[(r + 1) % 3], v[(r + 2) % 3], 0.0};
    return (std::uint64_t(key->a) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(key->b) * 0xC2B2AE3D27D4EB4Full) ^
           (std::uint64_t(key->c) * 0x165667B19E3779F9ull);
}

std::size_t PointRemover::cache_slot(const CacheSlot& key, std::uint64_t h) {
    const std::size_t mask = cache_.size() - 1;
    std::size_t i = std::size_t(h >> 20) & mask;
    for (; cache_[i].a != noVertex; i = (i + 1) & mask)
        if (cache_[i].a == key.a && cache_[i].b == key.b && cache_[i].c == key.c) break;
    return i;
}

double PointRemover::hole_triangle_error(std::size_t t, const CacheSlot& key_in, std::uint64_t hash) {
    CacheSlot key = key_in;
    const std::size_t i = cache_slot(key, hash);
    if (cache_[i].a != noVertex) return cache_[i].error;
    LatticePoint p[3];
    double z[3 * 3];
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t q = tris_[t + std::size_t(k)];
        p[k] = cdt_.point(poly_[q]);
        for (int c2 = 0; c2 < channels_; ++c2)
            z[k * channels_ + c2] = polyz_[q * std::size_t(channels_) + std::size_t(c2)];
    }
    const double e = triangle_error(p, z);
    if (2 * (cache_used_ + 1) > cache_.size()) {  // half full: start again, twice the size up to 2^22
        const std::size_t size = std::min<std::size_t>(cache_.size() * 2, std::size_t(1) << 22);
        cache_.assign(size, CacheSlot());
        cache_used_ = 0;
        return e;
    }
    key.error = e;
    cache_[i] = key;
    ++cache_used_;
    return e;
}

bool PointRemover::significance_of(VertInd v, double* sig) {
    if (!gather(v)) return false;
    ++stats_.evaluations;
    double before = 0.0;
    for (FaceInd f : star_) before += face_err_[f];
    triangulate_hole();
    if (cache_.empty()) cache_.resize(std::size_t(1) << 16);
    keys_.resize(tris_.size() / 3);
    for (std::size_t t = 0; t < tris_.size(); t += 3) {
        const VertInd tv[3] = {poly_[tris_[t]], poly_[tris_[t + 1]], poly_[tris_[t + 2]]};
        auto& k = keys_[t / 3];
        k.second = cache_key(tv, &k.first);
        prefetch_slot(k.second);
    }
    double after = 0.0;
    for (std::size_t t = 0; t < tris_.size(); t += 3) after += hole_triangle_error(t, keys_[t / 3].first, keys_[t / 3].second);
    *sig = after - before;
    return true;
}

double PointRemover::significance(VertInd v) {
    double sig = 0.0;
    return significance_of(v, &sig) ? sig : 0.0;
}

void PointRemover::update(VertInd v) {
    if (v >= stale_.size()) stale_.resize(cdt_.vertex_count(), 0);
    stale_[v] = 0;
    double sig = 0.0;
    if (!cdt_.vertex_live(v) || !significance_of(v, &sig)) {
        heap_.remove(v);
        return;
    }
    heap_.set(v, -sig, tie_of(cdt_.point(v)));
}

void PointRemover::start() {
    started_ = true;
    stale_.assign(cdt_.vertex_count(), 0);
    heap_.reserve(cdt_.vertex_count());
    double sig = 0.0;
    for (VertInd v = 0; v < cdt_.vertex_count(); ++v)
        if (cdt_.vertex_live(v) && significance_of(v, &sig)) heap_.set(v, -sig, tie_of(cdt_.point(v)));
}

void PointRemover::rescan_created(bool cached) {
    if (face_err_.size() < cdt_.face_count()) face_err_.resize(cdt_.face_count(), 0.0);
    for (FaceInd f : cdt_.changes().destroyed) {
        total_ -= face_err_[f];
        face_err_[f] = 0.0;
        if (track_) by_face_.remove(f);
    }
    const std::vector<FaceInd>& created = cdt_.changes().created;
    if (cached) {
        if (cache_.empty()) cache_.resize(std::size_t(1) << 16);
        keys_.resize(created.size());
        for (std::size_t n = 0; n < created.size(); ++n) {
            const FaceInd f = created[n];
            const VertInd v[3] = {cdt_.face_vertex(f, 0), cdt_.face_vertex(f, 1), cdt_.face_vertex(f, 2)};
            keys_[n].second = cache_key(v, &keys_[n].first);
            prefetch_slot(keys_[n].second);
        }
    }
    for (std::size_t n = 0; n < created.size(); ++n) {
        const FaceInd f = created[n];
        // After a removal the created faces are the hole's triangles, whose errors significance()
        // mostly cached (the same pixels and values: hole_triangle_error).
        const std::size_t i = cached ? cache_slot(keys_[n].first, keys_[n].second) : 0;
        total_ += face_err_[f] = cached && cache_[i].a != noVertex ? cache_[i].error : face_error_now(f);
        if (track_) by_face_.set(f, face_err_[f], f);
    }
}

void PointRemover::touch_neighbours(const std::vector<VertInd>& around) {
    if (!started_) return;  // no significances yet (growth before start())
    if (stale_.size() < cdt_.vertex_count()) stale_.resize(cdt_.vertex_count(), 0);
    for (VertInd q : around) {
        if (!lazy) update(q);
        else if (heap_.contains(q) || cdt_.can_remove(q)) {
            stale_[q] = 1;
            if (!heap_.contains(q)) update(q);
        }
    }
}

Status PointRemover::remove(VertInd v) {
    if (!gather(v)) return Status::failure("point removal: vertex not removable");
    around_ = poly_;
    const LatticePoint pv = cdt_.point(v);
    Status st = cdt_.remove_vertex(v);
    if (!st) return st;
    if (track_ && !(pv.x & 1) && !(pv.y & 1)) occupied_[pixel_index(pv)] = 0;
    heap_.remove(v);
    rescan_created(true);
    ++stats_.removed;
    touch_neighbours(around_);
    return Status::success();
}

Status PointRemover::insert(LatticePoint p, VertInd* v, const std::vector<double>* values) {
    const Location loc = cdt_.locate(p);
    Status st = cdt_.insert_point(p, v, loc.face);
    if (!st) return st;
    model_.on_vertex_inserted(cdt_, *v);
    if (values) model_.restore_values(cdt_, *v, *values);
    if (track_) occupied_[pixel_index(p)] = 1;
    rescan_created(false);
    around_.clear();
    for (FaceInd f : cdt_.changes().created)
        for (int i = 0; i < 3; ++i) around_.push_back(cdt_.face_vertex(f, i));
    std::sort(around_.begin(), around_.end());
    around_.erase(std::unique(around_.begin(), around_.end()), around_.end());
    touch_neighbours(around_);
    return Status::success();
}

Status PointRemover::run_to(std::size_t target, const ProgressHook& progress) {
    const std::size_t first = cdt_.live_vertex_count();
    std::size_t next_report = 0;
    while (cdt_.live_vertex_count() > target && !heap_.empty()) {
        const VertInd v = heap_.top();
        if (v < stale_.size() && stale_[v]) {
            ++stats_.stale_pops;
            update(v);
            continue;
        }
        Status st = remove(v);
        if (!st) return st;
        if (progress && stats_.removed >= next_report) {
            const double done = first > target ? double(first - cdt_.live_vertex_count()) / double(first - target) : 1.0;
            if (progress.report_cancelled("point removal", done)) return Status::failure(kCancelled);
            next_report = stats_.removed + std::max<std::size_t>(1, (first - target) / 100);
        }
    }
    return Status::success();
}

void PointRemover::least_significant(std::size_t count, std::vector<VertInd>* out) {
    out->clear();
    std::vector<std::pair<VertInd, double>> taken;
    while (out->size() < count && !heap_.empty()) {
        const VertInd v = heap_.top();
        if (v < stale_.size() && stale_[v]) {
            ++stats_.stale_pops;
            update(v);
            continue;
        }
        taken.push_back({v, heap_.top_key()});
        out->push_back(v);
        heap_.remove(v);
    }
    for (const auto& t : taken) heap_.set(t.first, t.second, tie_of(cdt_.point(t.first)));
}

Status removal_accepts(const Image& image, const char* method) {
    if (!image.real()) return Status::success();
    return Status::bad_input(std::string(method) + ": real-valued rasters are not supported by the removal methods (use gpi or erdgpi)");
}

std::vector<LatticePoint> live_points(const Cdt& cdt) {
    std::vector<LatticePoint> pts;
    for (VertInd v = 4; v < cdt.vertex_count(); ++v)
        if (cdt.vertex_live(v)) pts.push_back(cdt.point(v));
    return pts;
}

Status compact_cdt(const Cdt& cdt, Cdt* out, std::vector<VertInd>* to_out) {
    Status st = out->reset(cdt.max_x(), cdt.max_y());
    if (!st) return st;
    const std::vector<LatticePoint> pts = live_points(cdt);
    out->reserve(pts.size() + 4);
    std::vector<VertInd> ids;
    st = out->insert_points(pts, &ids, false);
    if (!st) return st;
    // Old vertex -> new vertex, for the constrained edges.
    std::vector<VertInd> to(cdt.vertex_count(), noVertex);
    for (VertInd v = 0; v < 4; ++v) to[v] = v;
    std::size_t k = 0;
    for (VertInd v = 4; v < cdt.vertex_count(); ++v)
        if (cdt.vertex_live(v)) to[v] = ids[k++];
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    for (const auto& c : cons) {
        st = out->insert_constraint(to[c[0]], to[c[1]]);
        if (!st) return st;
    }
    if (to_out) *to_out = std::move(to);
    return Status::success();
}

}  // namespace erd
