#include "algorithms/codec/erdz_rate.h"

#include <cmath>

#include "algorithms/model/metrics.h"
#include "algorithms/model/reconstruct.h"

namespace erd {
namespace {

constexpr int kFinest = -8, kCoarsest = 32;  // step = 2^(i/4)

double grid_step(int i) { return std::pow(2.0, double(i) / 4.0); }

}  // namespace

Status encode_erdz_for(const Model& m, const Image* original, const RateTarget& target, ErdzOptions options,
                       std::string* out, ErdzInfo* info, RateResult* result) {
    const bool by_psnr = target.psnr > 0.0;
    if (!by_psnr && !(target.bpp > 0.0)) return Status::bad_input("a rate target needs bpp > 0 or psnr > 0");
    if (by_psnr && (!original || original->width != m.width || original->height != m.height ||
                    original->channels != m.channels))
        return Status::bad_input("a PSNR target needs the original image, of the model's size and channels");
    const double pixels = double(m.width) * double(m.height);
    *result = RateResult();
    // ok(i): step i meets the target. Coarser steps meet a bpp target more easily, finer ones a
    // PSNR target: bisect for the boundary.
    std::string bytes;
    ErdzInfo inf;
    double db = 0.0;
    const auto evaluate = [&](int i, bool* ok) {
        options.step = grid_step(i);
        Status st = encode_erdz(m, options, &bytes, &inf);
        if (!st) return st;
        ++result->encodings;
        if (!by_psnr) {
            *ok = double(inf.total_bits) / pixels <= target.bpp;
            return st;
        }
        Model decoded;
        Image rec;
        if (!(st = decode_erdz(bytes, &decoded))) return st;
        if (!(st = reconstruct(decoded, supersampled(decoded), &rec))) return st;
        if (!(st = psnr(*original, rec, &db))) return st;
        *ok = db >= target.psnr;
        return st;
    };
    // The finest step for a PSNR target (the coarsest for a size) either meets it or nothing does.
    int lo = kFinest, hi = kCoarsest;
    bool ok_lo = false, ok_hi = false;
    Status st = evaluate(by_psnr ? lo : hi, by_psnr ? &ok_lo : &ok_hi);
    if (!st) return st;
    int best = by_psnr ? lo : hi;
    bool met = by_psnr ? ok_lo : ok_hi;
    if (met) {
        // PSNR: ok at lo, find the largest ok i. bpp: ok at hi, find the smallest ok i.
        while (hi - lo > 1) {
            const int mid = (lo + hi) / 2;
            bool ok = false;
            if (!(st = evaluate(mid, &ok))) return st;
            if (ok == by_psnr) lo = mid;
            else hi = mid;
        }
        best = by_psnr ? lo : hi;
    }
    options.step = grid_step(best);
    if (!(st = encode_erdz(m, options, out, &inf))) return st;
    if (info) *info = inf;
    result->step = inf.step;
    result->bpp = double(inf.total_bits) / pixels;
    result->met = met;
    if (original && original->width == m.width && original->height == m.height && original->channels == m.channels) {
        Model decoded;
        Image rec;
        if (!(st = decode_erdz(*out, &decoded))) return st;
        if (!(st = reconstruct(decoded, supersampled(decoded), &rec))) return st;
        if (!(st = psnr(*original, rec, &result->psnr))) return st;
    }
    return Status::success();
}

}  // namespace erd
