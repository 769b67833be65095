// erd psnr ORIGINAL APPROX [--json]: the thesis's Cal_PSNR.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/model/metrics.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/image_io.h"
#include "cli/json.h"

namespace erd::cli {

const CommandLine kPsnr = {
    "psnr",
    "erd psnr ORIGINAL APPROX [--json]",
    "Prints the PSNR of APPROX against ORIGINAL in dB with 4 decimals (\"inf\" when they are\n"
    "identical). Peak = 2^p - 1 with p = ceil(log2(maxval + 1)) of the original; PSNR =\n"
    "10 log10(peak^2 / MSE). Both images must have the same size and maxval.",
    {
        {0, "json", nullptr, "{\"mse\":..,\"peak\":..,\"psnr\":..} on stdout (psnr null when identical)"},
    },
    "no warnings", 2, 2, "expected ORIGINAL and APPROX",
};

static int run_psnr(const Args& args, const Reporter& rep) {
    const std::string& a = args.positional()[0];
    const std::string& b = args.positional()[1];
    if (a == "-" && b == "-") return rep.usage("only one of the images can be stdin");

    Image orig, approx;
    std::string warning;
    Status st;
    if (!(st = read_image(a, &orig, &warning))) return rep.fail(st);
    rep.warn(warning);
    if (!(st = read_image(b, &approx, &warning))) return rep.fail(st);
    rep.warn(warning);

    double e = 0, p = 0;
    if (!(st = mse(orig, approx, &e)) || !(st = psnr(orig, approx, &p)))
        return rep.fail(Status::bad_input(a + " and " + b + ": " + st.message));
    const double peak = psnr_peak(orig.maxval);
    if (args.has("json")) {
        std::printf("%s\n", JsonObject().num("mse", e).num("peak", peak).num("psnr", p).text().c_str());
    } else if (std::isinf(p)) {
        std::printf("inf\n");
    } else {
        std::printf("%.4f\n", p);
    }
    return 0;
}

int cmd_psnr(int argc, char** argv) { return run_command(kPsnr, argc, argv, run_psnr); }

}  // namespace erd::cli
