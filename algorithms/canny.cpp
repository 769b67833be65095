#include "algorithms/canny.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
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
        w = width; h = height; pad = p; stride = width + 2 * p;
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

// Gradient of an extended plane f (frame >= binomial radius + 1): smooth with the binomial in x and
// y over the region the derivative needs (one point beyond the image), then central differences.
// This is exactly the composed filter (derivative * binomial) applied to the extended signal.
void gradient_padded(const Padded& f, const std::vector<double>& b, Grid<float>* gx, Grid<float>* gy) {
    const int w = f.w, h = f.h, c = int(b.size() / 2);
    std::vector<float> bt(b.begin(), b.end());
    // Row pass on rows -c-1 .. h+c, columns -1 .. w: tmp has width w+2, height h+2c+2.
    const int tw = w + 2, th = h + 2 * c + 2;
    std::vector<float> tmp(std::size_t(tw) * std::size_t(th));
    for (int y = 0; y < th; ++y) {
        const float* src = f.row(y - c - 1) - 1;  // column -1
        float* dst = tmp.data() + std::ptrdiff_t(y) * tw;
        for (int x = 0; x < tw; ++x) {
            float acc = 0.0f;
            for (int k = 0; k <= 2 * c; ++k) acc += bt[std::size_t(k)] * src[x + c - k];
            dst[x] = acc;
        }
    }
    // Column pass: s has rows -1 .. h, columns -1 .. w.
    const int sh = h + 2;
    std::vector<float> s(std::size_t(tw) * std::size_t(sh), 0.0f);
    for (int y = 0; y < sh; ++y) {
        float* dst = s.data() + std::ptrdiff_t(y) * tw;
        for (int k = 0; k <= 2 * c; ++k) {
            const float* src = tmp.data() + std::ptrdiff_t(y + 2 * c - k) * tw;
            const float t = bt[std::size_t(k)];
            for (int x = 0; x < tw; ++x) dst[x] += t * src[x];
        }
    }
    *gx = Grid<float>(w, h);
    *gy = Grid<float>(w, h);
    for (int y = 0; y < h; ++y) {
        const float* mid = s.data() + std::ptrdiff_t(y + 1) * tw + 1;
        const float* up = mid - tw;
        const float* down = mid + tw;
        float* ox = &(*gx)(0, y);
        float* oy = &(*gy)(0, y);
        for (int x = 0; x < w; ++x) {
            ox[x] = 0.5f * (mid[x + 1] - mid[x - 1]);
            oy[x] = 0.5f * (down[x] - up[x]);
        }
    }
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
    gradient_padded(p, b, gx, gy);
}

double beta_quantile(const float* values, std::size_t n, double beta) {
    if (n == 0) return 0.0;
    double kd = std::nearbyint(beta * double(n));
    std::size_t k = kd < 1.0 ? 1 : (kd > double(n) ? n : std::size_t(kd));
    float top = 0.0f;
    for (std::size_t i = 0; i < n; ++i) top = std::max(top, values[i]);
    if (top <= 0.0f) return 0.0;
    // Histogram on a monotone bin map, so every value in a higher bin is >= every value in a lower
    // one; the k-th largest is then selected exactly inside its bin.
    constexpr int kBins = 4096;
    const float scale = float(kBins) / top;
    auto bin_of = [&](float v) { int b = int(v * scale); return b >= kBins ? kBins - 1 : (b < 0 ? 0 : b); };
    std::vector<std::size_t> hist(kBins, 0);
    for (std::size_t i = 0; i < n; ++i) ++hist[std::size_t(bin_of(values[i]))];
    std::size_t above = 0;
    int bin = kBins - 1;
    for (; bin > 0; --bin) {
        if (above + hist[std::size_t(bin)] >= k) break;
        above += hist[std::size_t(bin)];
    }
    std::vector<float> in_bin;
    in_bin.reserve(hist[std::size_t(bin)]);
    for (std::size_t i = 0; i < n; ++i)
        if (bin_of(values[i]) == bin) in_bin.push_back(values[i]);
    const std::size_t r = k - above - 1;  // rank from the top inside the bin
    std::nth_element(in_bin.begin(), in_bin.begin() + std::ptrdiff_t(r), in_bin.end(), std::greater<float>());
    return double(in_bin[r]);
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
    if (params.max_link < 0) return Status::bad_input("edge detection: max_link must be >= 0");

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
    gradient_padded(f, b, &gx, &gy);

    // Magnitude, with a one-point replicated frame for the 3x3 stencils below.
    Padded g;
    g.reset(W, H, 1);
    for (int Y = 0; Y < H; ++Y) {
        float* r = g.row(Y);
        const float* ax = &gx(0, Y);
        const float* ay = &gy(0, Y);
        for (int X = 0; X < W; ++X) r[X] = std::sqrt(ax[X] * ax[X] + ay[X] * ay[X]);
    }

    // 2. Thresholds.
    std::vector<float> mags(std::size_t(W) * std::size_t(H));
    for (int Y = 0; Y < H; ++Y) std::copy(g.row(Y), g.row(Y) + W, mags.begin() + std::ptrdiff_t(Y) * W);
    const double tau_high = beta_quantile(mags.data(), mags.size(), params.beta);
    const double tau_low = params.r * tau_high;
    std::size_t above_high = 0;
    for (float m : mags) above_high += m >= float(tau_high);
    mags = std::vector<float>();
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
    std::size_t main_points = 0;
    for (std::ptrdiff_t s : seeds) {
        if (flag[std::size_t(s)] & kMain) continue;
        flag[std::size_t(s)] |= kMain;
        stack.push_back(s);
        while (!stack.empty()) {
            const std::ptrdiff_t i = stack.back();
            stack.pop_back();
            ++main_points;
            for (std::ptrdiff_t o : off) {
                const std::size_t j = std::size_t(i + o);
                if ((flag[j] & (kCandidate | kMain)) == kCandidate) { flag[j] |= kMain; stack.push_back(i + o); }
            }
        }
    }

    // 5. Ding-Goshtasby: join different main components through short secondary paths. A
    // multi-source breadth-first search from every main point over secondary-only points labels
    // each reached point with its nearest main component; where two labels meet, the two parent
    // chains back to their sources are the shortest secondary link between those components.
    std::size_t added = 0;
    if (params.modified && params.max_link > 0) {
        std::vector<std::uint32_t> label(flag.size(), 0);  // main component + 1, 0 = unreached
        std::vector<std::uint16_t> dist(flag.size(), 0);
        std::vector<std::ptrdiff_t> queue;
        std::vector<std::ptrdiff_t> from(flag.size(), -1);
        std::uint32_t components = 0;
        for (int Y = 0; Y < H; ++Y)
            for (int X = 0; X < W; ++X) {
                const std::ptrdiff_t s = at(X, Y);
                if (!(flag[std::size_t(s)] & kMain) || label[std::size_t(s)]) continue;
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
        const std::uint16_t limit = std::uint16_t(std::min(params.max_link, 60000));
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::ptrdiff_t i = queue[head];
            const std::uint32_t li = label[std::size_t(i)];
            const std::uint16_t di = dist[std::size_t(i)];
            for (std::ptrdiff_t o : off) {
                const std::size_t j = std::size_t(i + o);
                const std::uint32_t lj = label[j];
                if (lj == 0) {
                    if (di < limit && (flag[j] & (kSecondary | kMain)) == kSecondary) {
                        label[j] = li;
                        dist[j] = std::uint16_t(di + 1);
                        from[j] = i;
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
                ++added;
            }
        }
    }

    // 6. Output and thinning.
    *edges = Grid<std::uint8_t>(W, H, 0);
    for (int Y = 0; Y < H; ++Y)
        for (int X = 0; X < W; ++X) (*edges)(X, Y) = (flag[std::size_t(at(X, Y))] & kMain) ? 1 : 0;
    if (params.thin) thin_edges(edges);
    if (stats) {
        stats->tau_high = tau_high;
        stats->tau_low = tau_low;
        stats->above_high = above_high;
        stats->main_points = main_points;
        stats->added_points = added;
        std::size_t n = 0;
        for (std::uint8_t e : edges->data) n += e != 0;
        stats->edge_points = n;
    }
    return Status::success();
}

}  // namespace erd
