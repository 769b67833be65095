#include "algorithms/canny.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <vector>

#include "algorithms/bilinear.h"
#include "algorithms/thinning.h"

namespace erd {

namespace {

// A float plane with a frame of `pad` points on every side, so stencils need no bounds checks.
struct Padded {
    int w = 0, h = 0, pad = 0, stride = 0;
    std::vector<float> v;
    void reset(int width, int height, int p) {
        // Rows a multiple of 8 floats long with 8 spare, so the blocked loops below may run past
        // the frame without leaving the row.
        w = width; h = height; pad = p; stride = ((width + 2 * p + 7) / 8) * 8 + 8;
        v.assign(std::size_t(stride) * std::size_t(height + 2 * p), 0.0f);
    }
    float* row(int y) { return v.data() + std::ptrdiff_t(y + pad) * stride + pad; }
    const float* row(int y) const { return v.data() + std::ptrdiff_t(y + pad) * stride + pad; }
};

// Fills the frame of p by the extension rule (zero: already zero after reset).
void extend_frame(Padded* p, Border border) {
    if (border == Border::zero) return;
    for (int y = 0; y < p->h; ++y) {
        float* r = p->row(y);
        for (int i = 1; i <= p->pad; ++i) { r[-i] = r[0]; r[p->w - 1 + i] = r[p->w - 1]; }
    }
    const float* top = p->row(0) - p->pad;
    const float* bottom = p->row(p->h - 1) - p->pad;
    for (int i = 1; i <= p->pad; ++i) {
        std::copy(top, top + p->stride, p->row(-i) - p->pad);
        std::copy(bottom, bottom + p->stride, p->row(p->h - 1 + i) - p->pad);
    }
}

// dst[0..n) += t * src[0..n), n a multiple of 8: written in blocks of 8 so that -O2 vectorises it.
inline void axpy8(float* __restrict dst, const float* __restrict src, float t, int n) {
    for (int x = 0; x < n; x += 8)
        for (int j = 0; j < 8; ++j) dst[x + j] += t * src[x + j];
}

// Gradient of an extended plane f (frame >= binomial radius + 1): smooth with the binomial in y
// then x over the region the derivative needs (one point beyond the image), then central
// differences. This is exactly the composed filter (derivative * binomial) applied to the
// extended signal. mag (same geometry as f, frame 1 or more) receives sqrt(gx^2 + gy^2).
void gradient_padded(const Padded& f, const std::vector<double>& b, Grid<float>* gx, Grid<float>* gy, Padded* mag) {
    const int w = f.w, h = f.h, c = int(b.size() / 2), m = 2 * c + 1;
    std::vector<float> bt(b.begin(), b.end());
    // Streaming, one row at a time: column pass of row y into t (whole extended row), row pass
    // into s(., y) for x = -1 .. w, kept in a ring of three rows for the central differences.
    const int rs = f.stride;
    const int n8 = ((w + 2 + 7) / 8) * 8;
    const int ss = n8 + 8;
    std::vector<float> t(std::size_t(rs), 0.0f), ring(std::size_t(ss) * 3, 0.0f);
    auto smooth_row = [&](int y, float* dst) {
        const float* __restrict first = f.row(y + c) - f.pad;
        for (int x = 0; x < rs; ++x) t[std::size_t(x)] = bt[0] * first[x];
        for (int k = 1; k < m; ++k) axpy8(t.data(), f.row(y + c - k) - f.pad, bt[std::size_t(k)], rs);
        const float* src = t.data() + f.pad - 1;  // column -1
        for (int x = 0; x < n8; ++x) dst[x] = bt[0] * src[x + c];
        for (int k = 1; k < m; ++k) axpy8(dst, src + c - k, bt[std::size_t(k)], n8);
    };
    auto ring_row = [&](int y) { return ring.data() + std::ptrdiff_t((y + 3) % 3) * ss; };
    smooth_row(-1, ring_row(-1));
    smooth_row(0, ring_row(0));
    *gx = Grid<float>(w, h);
    *gy = Grid<float>(w, h);
    for (int y = 0; y < h; ++y) {
        smooth_row(y + 1, ring_row(y + 1));
        const float* mid = ring_row(y) + 1;
        const float* up = ring_row(y - 1) + 1;
        const float* down = ring_row(y + 1) + 1;
        float* __restrict ox = &(*gx)(0, y);
        float* __restrict oy = &(*gy)(0, y);
        float* __restrict om = mag->row(y);
        for (int x = 0; x < w; ++x) {
            const float ax = 0.5f * (mid[x + 1] - mid[x - 1]), ay = 0.5f * (down[x] - up[x]);
            ox[x] = ax;
            oy[x] = ay;
            om[x] = std::sqrt(ax * ax + ay * ay);
        }
    }
}

// Monotone bins from the bit pattern of a non-negative float (sign, exponent and 3 mantissa bits:
// 4096 bins, each 1/8 of an octave wide), so a histogram needs no prior pass for the maximum.
inline std::uint32_t float_bin(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u >> 20;
}
constexpr std::uint32_t kFloatBins = 4096;

// k-th largest of n values given their histogram: finds the bin, then selects inside it. *at_or_above
// receives the number of values >= the result.
template <class Visit>
float kth_largest(const std::vector<std::size_t>& hist, std::size_t k, Visit visit_all, std::size_t* at_or_above) {
    std::size_t above = 0;
    std::uint32_t bin = kFloatBins - 1;
    for (; bin > 0; --bin) {
        if (above + hist[bin] >= k) break;
        above += hist[bin];
    }
    std::vector<float> in_bin;
    in_bin.reserve(hist[bin]);
    visit_all([&](float v) { if (float_bin(v) == bin) in_bin.push_back(v); });
    if (in_bin.empty()) { *at_or_above = above; return 0.0f; }
    const std::size_t r = std::min(k - above, in_bin.size()) - 1;  // rank from the top inside the bin
    std::nth_element(in_bin.begin(), in_bin.begin() + std::ptrdiff_t(r), in_bin.end(), std::greater<float>());
    const float q = in_bin[r];
    std::size_t n = above;
    for (float v : in_bin) n += v >= q;
    *at_or_above = n;
    return q;
}

// 8-neighbour offsets in a plane of the given stride.
void neighbour_offsets(int stride, std::ptrdiff_t off[8]) {
    const int dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    const int dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    for (int i = 0; i < 8; ++i) off[i] = std::ptrdiff_t(dy[i]) * stride + dx[i];
}

enum : std::uint8_t { kNone = 0, kCandidate = 1, kMain = 2, kSecondary = 4 };

}  // namespace

void canny_gradient(const Grid<double>& f, int smoothing_order, Border border, Grid<float>* gx, Grid<float>* gy) {
    std::vector<double> b = binomial_taps(smoothing_order);
    if (b.empty()) b = {1.0};
    Padded p;
    p.reset(f.width, f.height, int(b.size() / 2) + 1);
    if (f.width <= 0 || f.height <= 0) { *gx = Grid<float>(); *gy = Grid<float>(); return; }
    for (int y = 0; y < f.height; ++y) {
        float* r = p.row(y);
        for (int x = 0; x < f.width; ++x) r[x] = float(f(x, y));
    }
    extend_frame(&p, border);
    Padded mag;
    mag.reset(f.width, f.height, 1);
    gradient_padded(p, b, gx, gy, &mag);
}

double beta_quantile(const float* values, std::size_t n, double beta) {
    if (n == 0) return 0.0;
    const double kd = std::nearbyint(beta * double(n));
    const std::size_t k = kd < 1.0 ? 1 : (kd > double(n) ? n : std::size_t(kd));
    std::vector<std::size_t> hist(kFloatBins, 0);
    for (std::size_t i = 0; i < n; ++i) ++hist[float_bin(values[i])];
    std::size_t count = 0;
    return double(kth_largest(hist, k, [&](auto&& f) { for (std::size_t i = 0; i < n; ++i) f(values[i]); }, &count));
}

Status detect_edges(const Image& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    return detect_edges(to_grid(im), params, edges, stats);
}

Status detect_edges(const Grid<double>& im, const CannyParams& params, Grid<std::uint8_t>* edges, CannyStats* stats) {
    if (im.width <= 0 || im.height <= 0) return Status::bad_input("edge detection: empty image");
    if (!(params.beta > 0.0 && params.beta <= 1.0)) return Status::bad_input("edge detection: beta must lie in (0, 1]");
    if (!(params.r >= 0.0 && params.r <= 1.0)) return Status::bad_input("edge detection: r must lie in [0, 1]");
    if (params.smoothing_order < 1 || params.smoothing_order % 2 == 0 || params.smoothing_order > 51)
        return Status::bad_input("edge detection: smoothing order must be odd, 1 to 51");
    if (params.max_link < 0 || params.max_link > 250) return Status::bad_input("edge detection: max_link must lie in [0, 250]");

    const std::vector<double> b = binomial_taps(params.smoothing_order);
    const int W = 2 * im.width - 1, H = 2 * im.height - 1;

    // 1. phi_bar on the half-pixel grid, extended, and its gradient.
    Padded f;
    f.reset(W, H, int(b.size() / 2) + 1);
    for (int Y = 0; Y < H; ++Y) {
        float* r = f.row(Y);
        const int y0 = Y >> 1, y1 = (Y & 1) ? y0 + 1 : y0;
        for (int x = 0; x < im.width; ++x) {
            const float top = float(im(x, y0)), bottom = float(im(x, y1));
            r[2 * x] = (Y & 1) ? 0.5f * (top + bottom) : top;
        }
        for (int X = 1; X < W; X += 2) r[X] = 0.5f * (r[X - 1] + r[X + 1]);
    }
    extend_frame(&f, params.border);
    Grid<float> gx, gy;
    Padded g;  // magnitude, with a one-point replicated frame for the 3x3 stencils below
    g.reset(W, H, 1);
    gradient_padded(f, b, &gx, &gy, &g);
    f = Padded();

    // 2. Thresholds.
    std::vector<std::size_t> hist(kFloatBins, 0);
    for (int Y = 0; Y < H; ++Y) {
        const float* r = g.row(Y);
        for (int X = 0; X < W; ++X) ++hist[float_bin(r[X])];
    }
    const std::size_t M = std::size_t(W) * std::size_t(H);
    const double kd = std::nearbyint(params.beta * double(M));
    const std::size_t k_high = kd < 1.0 ? 1 : (kd > double(M) ? M : std::size_t(kd));
    std::size_t above_high = 0;
    const double tau_high = kth_largest(
        hist, k_high,
        [&](auto&& fn) {
            for (int Y = 0; Y < H; ++Y) {
                const float* r = g.row(Y);
                for (int X = 0; X < W; ++X) fn(r[X]);
            }
        },
        &above_high);
    const double tau_low = params.r * tau_high;
    extend_frame(&g, Border::replicate);

    // 3. Non-maxima suppression (and the secondary maxima of step 5), over points >= tau_low only.
    // A point with g == 0 is never an edge (flat images give no edges whatever beta is).
    const float th = float(tau_high), tl = float(tau_low);
    const int stride = g.stride;
    std::vector<std::uint8_t> flag(g.v.size(), kNone);  // same frame as g, frame stays kNone
    auto at = [&](int X, int Y) { return std::ptrdiff_t(Y + 1) * stride + X + 1; };
    std::vector<std::ptrdiff_t> seeds;
    for (int Y = 0; Y < H; ++Y) {
        const float* ax = &gx(0, Y);
        const float* ay = &gy(0, Y);
        for (int X = 0; X < W; ++X) {
            const std::ptrdiff_t i = at(X, Y);
            const float m = g.v[std::size_t(i)];
            if (m < tl || m <= 0.0f) continue;
            const float* p = g.v.data() + i;
            const float ux = ax[X], uy = ay[X];
            const float aux = std::fabs(ux), auy = std::fabs(uy);
            std::ptrdiff_t major, minor;
            float w;
            if (aux >= auy) {
                major = ux > 0 ? 1 : -1;
                minor = (uy > 0 ? 1 : -1) * std::ptrdiff_t(stride);
                w = auy / aux;
            } else {
                major = (uy > 0 ? 1 : -1) * std::ptrdiff_t(stride);
                minor = ux > 0 ? 1 : -1;
                w = aux / auy;
            }
            const float ahead = (1.0f - w) * p[major] + w * p[major + minor];
            const float behind = (1.0f - w) * p[-major] + w * p[-major - minor];
            std::uint8_t fl = kNone;
            if (m > ahead && m >= behind) {
                fl = kCandidate;
                if (m >= th) seeds.push_back(i);
            }
            if (params.modified) {
                if ((m > p[-1] && m > p[1]) || (m > p[-stride] && m > p[stride]) ||
                    (m > p[-stride - 1] && m > p[stride + 1]) || (m > p[-stride + 1] && m > p[stride - 1]))
                    fl = std::uint8_t(fl | kSecondary);
            }
            flag[std::size_t(i)] = fl;
        }
    }
    gx = Grid<float>();
    gy = Grid<float>();

    // 4. Hysteresis: grow from the seeds through 8-connected candidates.
    std::ptrdiff_t off[8];
    neighbour_offsets(stride, off);
    std::vector<std::ptrdiff_t> stack;
    std::vector<std::ptrdiff_t> mains;  // every point marked kMain, in the order marked
    for (std::ptrdiff_t s : seeds) {
        if (flag[std::size_t(s)] & kMain) continue;
        flag[std::size_t(s)] |= kMain;
        stack.push_back(s);
        while (!stack.empty()) {
            const std::ptrdiff_t i = stack.back();
            stack.pop_back();
            mains.push_back(i);
            for (std::ptrdiff_t o : off) {
                const std::size_t j = std::size_t(i + o);
                if ((flag[j] & (kCandidate | kMain)) == kCandidate) { flag[j] |= kMain; stack.push_back(i + o); }
            }
        }
    }
    const std::size_t main_points = mains.size();

    // 5. Ding-Goshtasby: join different main components through short secondary paths. A
    // multi-source breadth-first search from every main point over secondary-only points labels
    // each reached point with its nearest main component; where two labels meet, the two parent
    // chains back to their sources are the shortest secondary link between those components.
    std::size_t added = 0;
    if (params.modified && params.max_link > 0) {
        std::vector<std::uint32_t> label(flag.size(), 0);  // main component + 1, 0 = unreached
        std::vector<std::uint8_t> dist(flag.size(), 0);
        std::vector<std::ptrdiff_t> queue;
        std::vector<std::int32_t> from(flag.size(), -1);
        std::uint32_t components = 0;
        for (const std::ptrdiff_t s : mains) {
            if (label[std::size_t(s)]) continue;
            ++components;
            label[std::size_t(s)] = components;
            stack.push_back(s);
            while (!stack.empty()) {
                const std::ptrdiff_t i = stack.back();
                stack.pop_back();
                queue.push_back(i);
                for (std::ptrdiff_t o : off) {
                    const std::size_t j = std::size_t(i + o);
                    if ((flag[j] & kMain) && !label[j]) { label[j] = components; stack.push_back(i + o); }
                }
            }
        }
        struct Meeting { std::uint64_t key; std::ptrdiff_t p, q; };
        std::vector<Meeting> meetings;
        const std::uint8_t limit = std::uint8_t(params.max_link);
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::ptrdiff_t i = queue[head];
            const std::uint32_t li = label[std::size_t(i)];
            const std::uint8_t di = dist[std::size_t(i)];
            for (std::ptrdiff_t o : off) {
                const std::size_t j = std::size_t(i + o);
                const std::uint32_t lj = label[j];
                if (lj == 0) {
                    if (di < limit && (flag[j] & (kSecondary | kMain)) == kSecondary) {
                        label[j] = li;
                        dist[j] = std::uint8_t(di + 1);
                        from[j] = std::int32_t(i);
                        queue.push_back(i + o);
                    }
                } else if (lj != li && li < lj && std::uint32_t(di) + dist[j] <= limit) {
                    meetings.push_back({(std::uint64_t(li) << 32) | lj, i, i + o});
                } else if (lj != li && li > lj && std::uint32_t(di) + dist[j] <= limit) {
                    meetings.push_back({(std::uint64_t(lj) << 32) | li, i + o, i});
                }
            }
        }
        // One link per pair of components: the first found, i.e. (nearly) the shortest.
        std::stable_sort(meetings.begin(), meetings.end(), [](const Meeting& a, const Meeting& c) { return a.key < c.key; });
        for (std::size_t k = 0; k < meetings.size(); ++k) {
            if (k > 0 && meetings[k].key == meetings[k - 1].key) continue;
            for (std::ptrdiff_t i : {meetings[k].p, meetings[k].q})
                for (; i >= 0 && !(flag[std::size_t(i)] & kMain); i = from[std::size_t(i)]) {
                    flag[std::size_t(i)] |= kMain;
                    mains.push_back(i);
                    ++added;
                }
        }

        // Where an edge runs into a stronger one (the stem of a T), the last points before the
        // junction lie on the flank of the stronger edge and are maxima in no direction, so no
        // secondary path exists. From each end of a main curve, climb the magnitude (strictly
        // increasing, >= tau_low, at most max_link points) and keep the climb if it arrives next
        // to a different main component.
        std::vector<std::ptrdiff_t> path;
        for (std::size_t qi = 0; qi < queue.size(); ++qi) {
            const std::ptrdiff_t end = queue[qi];
            if (dist[std::size_t(end)] != 0 || !(flag[std::size_t(end)] & kMain)) continue;
            int n = 0;
            for (std::ptrdiff_t o : off) n += (flag[std::size_t(end + o)] & kMain) != 0;
            if (n != 1) continue;
            const std::uint32_t own = label[std::size_t(end)];
            path.clear();
            std::ptrdiff_t cur = end;
            bool joined = false;
            for (int step = 0; step <= params.max_link && !joined; ++step) {
                for (std::ptrdiff_t o : off) {
                    const std::size_t j = std::size_t(cur + o);
                    if ((flag[j] & kMain) && label[j] != own && label[j] != 0) joined = true;
                }
                if (joined || step == params.max_link) break;
                std::ptrdiff_t best = -1;
                float bg = g.v[std::size_t(cur)];
                for (std::ptrdiff_t o : off) {
                    const std::size_t j = std::size_t(cur + o);
                    // Stay inside the image: the frame of g replicates the border values and
                    // may be larger than the point it is next to.
                    const std::size_t jx = j % std::size_t(stride), jy = j / std::size_t(stride);
                    if (jx < 1 || jx > std::size_t(W) || jy < 1 || jy > std::size_t(H)) continue;
                    if (flag[j] & kMain) continue;
                    if (g.v[j] > bg && g.v[j] >= tl) { bg = g.v[j]; best = cur + o; }
                }
                if (best < 0) break;
                path.push_back(best);
                cur = best;
            }
            if (!joined || path.empty()) continue;
            for (std::ptrdiff_t i : path) {
                flag[std::size_t(i)] |= kMain;
                label[std::size_t(i)] = own;
                mains.push_back(i);
                ++added;
            }
        }
    }

    // 6. Output and thinning.
    *edges = Grid<std::uint8_t>(W, H, 0);
    for (const std::ptrdiff_t i : mains) (*edges)(int(i % stride) - 1, int(i / stride) - 1) = 1;
    const std::size_t edge_points = params.thin ? thin_edges(edges) : mains.size();
    if (stats) {
        stats->tau_high = tau_high;
        stats->tau_low = tau_low;
        stats->above_high = above_high;
        stats->main_points = main_points;
        stats->added_points = added;
        stats->edge_points = edge_points;
    }
    return Status::success();
}

}  // namespace erd
