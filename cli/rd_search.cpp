#include "cli/rd_search.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace erd::cli {
namespace {

// Better for the target: a size target maximises the PSNR, a quality target minimises the bpp.
bool better(const RateResult& a, const RateResult& b, bool by_psnr) {
    if (a.met != b.met) return a.met;
    if (!a.met) return false;
    return by_psnr ? a.bpp < b.bpp : a.psnr > b.psnr;
}

}  // namespace

Status choose_density(const MethodInfo& method, const Image& image, GenerateOptions options, const CodecChoice& codec,
                      GenerateResult* result, std::string* bytes, DensityChoice* choice) {
    const bool by_psnr = codec.target.psnr > 0.0;
    if (!by_psnr && !(codec.target.bpp > 0.0)) return Status::bad_input("--choose-density needs --bpp or --step-psnr");
    *choice = DensityChoice();
    const double pixels = double(image.width) * double(image.height);
    bool have = false;
    // One density: a run of the method, then the step search for the target (its result is
    // choice->trials.back()).
    const auto trial = [&](double d) -> Status {
        options.density = d;
        options.density_given = true;
        options.progress = {};
        GenerateResult r;
        Status st = method.run(image, options, &r);
        if (!st) return st;
        std::string b;
        ErdzOptions eo = codec.erdz;
        eo.method = method.name;
        RateResult rr;
        if (!(st = encode_erdz_for(r.model, &image, codec.target, eo, &b, nullptr, &rr))) return st;
        choice->trials.push_back({d, rr});
        if (!have || better(rr, choice->rate, by_psnr)) {
            have = true;
            choice->density = d;
            choice->rate = rr;
            *result = std::move(r);
            *bytes = std::move(b);
        }
        return Status::success();
    };
    int worse = 0;
    for (int k = -8; k <= 6; ++k) {
        const double d = std::pow(2.0, double(k) / 2.0);
        if (d / 100.0 * pixels < 8.0) continue;  // too few points to mesh
        const RateResult best_before = choice->rate;
        const bool had = have && choice->rate.met;
        Status st = trial(d);
        if (!st) return st;
        // Denser files only grow: past the first density whose coarsest step is too big, stop.
        if (!by_psnr && !choice->trials.back().rate.met) break;
        if (had) worse = better(choice->rate, best_before, by_psnr) ? 0 : worse + 1;
        if (worse == 2) break;
    }
    if (choice->rate.met) {
        const double best = choice->density;
        for (double f : {std::pow(2.0, -0.25), std::pow(2.0, 0.25)}) {
            const double d = best * f;
            if (d / 100.0 * pixels < 8.0 || d > kChoiceMaxDensity) continue;
            if (Status st = trial(d); !st) return st;
        }
    }
    if (!have) return Status::bad_input("--choose-density: the image is too small to mesh at any density tried");
    if (!choice->rate.met) {
        char buf[160];
        if (by_psnr)
            std::snprintf(buf, sizeof buf, "--choose-density: no density up to %g%% reaches %g dB", kChoiceMaxDensity,
                          codec.target.psnr);
        else
            std::snprintf(buf, sizeof buf, "--choose-density: no density from %g%% fits %g bpp", kChoiceMinDensity,
                          codec.target.bpp);
        return Status::bad_input(buf);
    }
    return Status::success();
}

}  // namespace erd::cli
