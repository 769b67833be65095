#include "algorithms/model/erd_model.h"

#include <cmath>
#include <limits>

#include "algorithms/imaging/bilinear.h"
#include "algorithms/imaging/filters.h"
#include "algorithms/imaging/mmsodd.h"

namespace erd {

void wedge_bisector(LatticePoint u1, LatticePoint u2, double* dx, double* dy) {
    const double kTwoPi = 6.283185307179586476925286766559;
    const double t1 = std::atan2(double(u1.y), double(u1.x));
    const double t2 = std::atan2(double(u2.y), double(u2.x));
    // Positive rotation in the doubled frame is increasing atan2 (orient2d > 0 <=> cross > 0).
    double sweep = t2 - t1;
    if (sweep <= 0) sweep += kTwoPi;
    const double t = t1 + 0.5 * sweep;
    *dx = std::cos(t);
    *dy = std::sin(t);
}

ErdModel::ErdModel(const Image& image, const WedgeValueOptions& options) : phi_(image), options_(options) {}

double ErdModel::multi_wedge_value(const Cdt& cdt, VertInd v, const Wedge& w) {
    const LatticePoint p = cdt.point(v);
    EdgeInd last = w.first;
    for (std::uint32_t i = 1; i < w.count; ++i) last = cdt.rot_next(last);
    const LatticePoint a = cdt.point(cdt.dest(w.first));
    const LatticePoint b = cdt.point(cdt.org(prev_edge(last)));
    double dx = 0, dy = 0;
    wedge_bisector({a.x - p.x, a.y - p.y}, {b.x - p.x, b.y - p.y}, &dx, &dy);
    const double x = 0.5 * p.x, y = 0.5 * p.y;
    const double max_x = phi_.width - 1, max_y = phi_.height - 1;
    auto clamp = [](double t, double hi) { return t < 0 ? 0.0 : (t > hi ? hi : t); };
    ++stats_.multi_wedges;
    if (options_.rule == 0) {
        const double t = options_.fixed_distance;
        return bilinear(phi_, clamp(x + t * dx, max_x), clamp(y + t * dy, max_y));
    }
    const int steps = int(std::lround((options_.alpha_max - options_.alpha_min) / kWedgeAlphaStep));
    double best = -1, bx = x, by = y;
    int best_i = 0;
    for (int i = 0; i <= steps; ++i) {
        const double alpha = options_.alpha_min + kWedgeAlphaStep * i;
        const double qx = clamp(x + alpha * dx, max_x), qy = clamp(y + alpha * dy, max_y);
        const double f = mmsodd_near(qx, qy);
        if (f > best) {
            best = f;
            bx = qx;
            by = qy;
            best_i = i;
        }
    }
    if (best_i == 0) ++stats_.alpha_first;
    if (best_i == steps) ++stats_.alpha_last;
    return bilinear(phi_, bx, by);
}

void ErdModel::prepare_taps() {
    taps_b_ = binomial_taps(options_.smoothing_order);
    if (taps_b_.empty()) taps_b_ = {1.0};
    stencil_radius_ = int(taps_b_.size() / 2);
}

double ErdModel::smoothed_pixel(int u, int v) const {
    // S(u, v) of algorithms/mmsodd.h: the binomial in x, then in y, zero outside the image.
    if (u < 0 || v < 0 || u >= phi_.width || v >= phi_.height) return 0.0;
    const int c = stencil_radius_;
    double s = 0;
    for (int m = -c; m <= c; ++m) {
        const int y = v - m;
        if (y < 0 || y >= phi_.height) continue;  // a row of zeros
        const std::uint16_t* row = &phi_.samples[std::size_t(y) * std::size_t(phi_.width)];
        double r = 0;
        for (int n = -c; n <= c; ++n) {
            const int x = u - n;
            if (x >= 0 && x < phi_.width) r += taps_b_[std::size_t(n + c)] * double(row[x]);
        }
        s += taps_b_[std::size_t(m + c)] * r;
    }
    return s;
}

double ErdModel::mmsodd_pixel(int x, int y) {
    const std::size_t key = std::size_t(y) * std::size_t(phi_.width) + std::size_t(x);
    const auto found = local_.find(key);
    if (found != local_.end()) return found->second;
    if (stencil_radius_ < 0) prepare_taps();
    // The two passes of algorithms/imaging/mmsodd.h at one pixel: S on the 3 x 3 neighbourhood, then the
    // derivative taps, in the same expressions as the whole-grid sweep. Integer samples and dyadic
    // taps make every value exact, so the order of the additions does not matter: the values are
    // those of the grid bit for bit.
    double S[3][3];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) S[j][i] = smoothed_pixel(x + i - 1, y + j - 1);
    const double fxx = (S[1][2] + S[1][0]) - 2.0 * S[1][1];
    const double fyy = (S[2][1] + S[0][1]) - 2.0 * S[1][1];
    const double fxy = 0.25 * ((S[2][2] - S[2][0]) - (S[0][2] - S[0][0]));
    const double value = mmsodd_value(fxx, fyy, fxy);
    local_.emplace(key, value);
    return value;
}

double ErdModel::mmsodd_near(double x, double y) {
    // f is the MMSODD of phi, defined on the pixel lattice (thesis 3.2.1, eq. 3.1); a point of
    // the line search reads it at the nearest pixel (halves up: x, y >= 0).
    const int px = int(x + 0.5), py = int(y + 0.5);
    if (have_mmsodd_) return mmsodd_(px, py);
    return mmsodd_pixel(px, py);
}

void ErdModel::assign_vertex(const Cdt& cdt, VertInd v) {
    if (slots_.size() <= v) slots_.resize(std::size_t(v) + 1);
    slots_[v].first = std::uint32_t(entries_.size());
    if (cdt.wedge_count(v) <= 1) {
        const LatticePoint p = cdt.point(v);
        entries_.push_back({kOnlyWedge, bilinear_doubled(phi_, p.x, p.y)});
        entry_vertex_.push_back(v);
        slots_[v].count = 1;
        slots_[v].value = entries_.back().value;
        return;
    }
    cdt.wedges(v, &scratch_);
    for (const Wedge& w : scratch_) {
        entries_.push_back({w.id, multi_wedge_value(cdt, v, w)});
        entry_vertex_.push_back(v);
    }
    slots_[v].count = std::uint32_t(scratch_.size());
    if (phi_.real()) pin_pixel(cdt, v);
}

void ErdModel::pin_pixel(const Cdt& cdt, VertInd v, double bound) {
    const LatticePoint p = cdt.point(v);
    if ((p.x & 1) || (p.y & 1) || v >= slots_.size() || slots_[v].count == 0) return;
    const std::size_t px = std::size_t(p.y / 2) * std::size_t(phi_.width) + std::size_t(p.x / 2);
    if (!phi_.valid.empty() && !phi_.valid[px]) return;
    const double z = phi_.reals[px];
    if (slots_[v].count == 1) {
        if (bound < 0 || std::fabs(entries_[slots_[v].first].value - z) > bound) set_entry_value(slots_[v].first, z);
        return;
    }
    // The wedge of the face that owns the vertex's pixel (kernel/raster.h).
    const RasterDomain dom{cdt.max_x(), cdt.max_y()};
    cdt.corners_around(v, &star_);
    for (const EdgeInd e : star_) {
        const EdgeInd k = 3 * face_of(e);
        if (!triangle_owns(Lattice::pixels(), dom, cdt.point(cdt.org(k)), cdt.point(cdt.org(k + 1)), cdt.point(cdt.org(k + 2)),
                           p.x / 2, p.y / 2))
            continue;
        const std::uint32_t i = multi_wedge_entry(cdt, v, e);
        if (i != kNoEntry && (bound < 0 || std::fabs(entries_[i].value - z) > bound)) entries_[i].value = z;
        return;
    }
}

void ErdModel::pin_pixel_vertices(const Cdt& cdt) {
    if (!phi_.real()) return;
    for (VertInd v = 0; v < slots_.size(); ++v) pin_pixel(cdt, v);
}

void ErdModel::pin_pixel_vertices(const Cdt& cdt, double bound) {
    if (!phi_.real()) return;
    for (VertInd v = 0; v < slots_.size(); ++v) pin_pixel(cdt, v, bound);
}

void ErdModel::assign_all(const Cdt& cdt) {
    const std::size_t n = cdt.vertex_count();
    slots_.assign(n, Slot());
    entries_.clear();
    entries_.reserve(n + n / 4);
    entry_vertex_.clear();
    entry_vertex_.reserve(n + n / 4);
    for (std::size_t v = 0; v < n; ++v) assign_vertex(cdt, VertInd(v));
}

double ErdModel::wedge_value(VertInd v, WedgeId id) const {
    if (v >= slots_.size() || slots_[v].count == 0) return std::numeric_limits<double>::quiet_NaN();
    const Entry* e = &entries_[slots_[v].first];
    if (slots_[v].count == 1) return e->value;
    for (std::uint32_t i = 0; i < slots_[v].count; ++i)
        if (e[i].id == id) return e[i].value;
    return std::numeric_limits<double>::quiet_NaN();
}

std::uint32_t ErdModel::multi_wedge_entry(const Cdt& cdt, VertInd v, EdgeInd e) const {
    // Cdt::wedge_id's walk: rotate negatively from the corner to the bounding constrained (or
    // hull) edge. Its direction names the wedge; instead of reducing it by the gcd as wedge_id
    // does (and counting v's wedges first), it is compared with each stored id's reduced
    // direction: the same ray exactly when the cross product is 0 and the dot product positive.
    EdgeInd b = e;
    while (cdt.twin(b) != noEdge && !cdt.constrained(b)) b = cdt.rot_prev(b);
    const LatticePoint p = cdt.point(v), q = cdt.point(cdt.dest(b));
    const std::int64_t dx = std::int64_t(q.x) - p.x, dy = std::int64_t(q.y) - p.y;
    for (std::uint32_t i = slots_[v].first; i < slots_[v].first + slots_[v].count; ++i) {
        const WedgeId id = entries_[i].id;
        const std::int64_t ex = std::int32_t(std::uint32_t(id >> 32)), ey = std::int32_t(std::uint32_t(id));
        if (ex * dy - ey * dx == 0 && ex * dx + ey * dy > 0) return i;
    }
    return kNoEntry;
}

double ErdModel::corner_value(const Cdt& cdt, EdgeInd e) const {
    const VertInd v = cdt.org(e);
    if (v >= slots_.size() || slots_[v].count == 0) return std::numeric_limits<double>::quiet_NaN();
    if (slots_[v].count == 1) return slots_[v].value;
    const std::uint32_t i = multi_wedge_entry(cdt, v, e);
    return i == kNoEntry ? std::numeric_limits<double>::quiet_NaN() : entries_[i].value;
}

std::uint32_t ErdModel::corner_lookup(const Cdt& cdt, EdgeInd e) const {
    const VertInd v = cdt.org(e);
    if (v >= slots_.size() || slots_[v].count == 0) return kNoValue;
    if (slots_[v].count == 1) return slots_[v].first;
    static_assert(kNoEntry == kNoValue, "corner_lookup returns multi_wedge_entry's none");
    return multi_wedge_entry(cdt, v, e);
}

std::uint32_t ErdModel::corner_entry(const Cdt& cdt, EdgeInd e) const {
    const VertInd v = cdt.org(e);
    if (slots_[v].count == 1) return slots_[v].first;
    const std::uint32_t i = multi_wedge_entry(cdt, v, e);
    return i == kNoEntry ? slots_[v].first : i;
}

double ErdModel::vertex_value(VertInd v) const {
    if (v >= slots_.size() || slots_[v].count == 0) return std::numeric_limits<double>::quiet_NaN();
    double s = 0;
    for (std::uint32_t i = 0; i < slots_[v].count; ++i) s += entries_[slots_[v].first + i].value;
    return s / slots_[v].count;
}

SpanPlane ErdModel::face_plane(const Cdt& cdt, FaceInd f) const {
    const EdgeInd e = 3 * f;
    SpanPlane plane;
    plane.set(cdt.point(cdt.org(e)), corner_value(cdt, e), cdt.point(cdt.org(e + 1)), corner_value(cdt, e + 1),
              cdt.point(cdt.org(e + 2)), corner_value(cdt, e + 2));
    return plane;
}

double ErdModel::evaluate(const Cdt& cdt, LatticePoint p) const {
    const Location loc = cdt.locate(p);
    switch (loc.kind) {
        case Location::Kind::on_vertex: return vertex_value(loc.vertex);
        case Location::Kind::on_edge: {
            const double z = face_plane(cdt, face_of(loc.edge)).at(p.x, p.y);
            const EdgeInd t = cdt.twin(loc.edge);
            if (!cdt.constrained(loc.edge) || t == noEdge) return z;
            return 0.5 * (z + face_plane(cdt, face_of(t)).at(p.x, p.y));
        }
        case Location::Kind::in_face: return face_plane(cdt, loc.face).at(p.x, p.y);
        case Location::Kind::outside: break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

void ErdModel::to_model(const Cdt& cdt, int width, int height, std::uint32_t maxval, Model* out) const {
    out->kind = ModelKind::erd;
    out->width = width;
    out->height = height;
    out->maxval = maxval;
    const std::size_t nv = cdt.vertex_count(), nf = cdt.face_count();
    out->vertices.assign(cdt.points().begin(), cdt.points().end());
    out->values.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) out->values[v] = vertex_value(VertInd(v));
    out->faces.resize(nf);
    out->corner_values.resize(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        for (int i = 0; i < 3; ++i) {
            const EdgeInd e = EdgeInd(3 * f + std::size_t(i));
            out->faces[f][std::size_t(i)] = cdt.org(e);
            out->corner_values[f][std::size_t(i)] = corner_value(cdt, e);
        }
    }
    std::vector<std::array<VertInd, 2>> cons;
    cdt.export_constraints(&cons);
    out->constraints.resize(cons.size());
    for (std::size_t i = 0; i < cons.size(); ++i) out->constraints[i] = {cons[i][0], cons[i][1]};
}

}  // namespace erd
