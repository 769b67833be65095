#include "cli/codec_output.h"

#include <cstdio>

#include "cli/model_file.h"
#include "cli/report.h"

namespace erd::cli {

void parse_codec_options(const Args& a, CodecChoice* c, Status* st) {
    const int targets = int(a.has("step")) + int(a.has("bpp")) + int(a.has("step-psnr"));
    c->given = targets > 0;
    if (targets > 1 && st->ok()) *st = Status::bad_input("--step, --bpp and --step-psnr exclude each other");
    if (a.has("step")) c->erdz.step = a.real("step", 1.0, 1.0 / 256.0, 1e6, st);
    if (a.has("bpp")) c->target.bpp = a.real("bpp", 0.0, 0.0, 1e6, st, true);
    if (a.has("step-psnr")) c->target.psnr = a.real("step-psnr", 0.0, 0.0, 1000.0, st, true);
    c->choose_density = a.has("choose-density");
    if (c->choose_density && !a.has("bpp") && !a.has("step-psnr") && st->ok())
        *st = Status::bad_input("--choose-density needs a target: --bpp B or --step-psnr P");
}

Status model_bytes_for(const std::string& path, const Model& m, const Image* original, const CodecChoice& c,
                       std::string* bytes, std::string* note) {
    note->clear();
    if (!erdz_name(path)) {
        if (c.given) return Status::bad_input(escape_name(path) + ": --step, --bpp and --step-psnr apply to .erdz outputs only");
        return encode_model_file(path, m, c.erdz, bytes);
    }
    ErdzInfo info;
    char buf[256];
    if (c.target.bpp > 0.0 || c.target.psnr > 0.0) {
        RateResult rr;
        Status st = encode_erdz_for(m, original, c.target, c.erdz, bytes, &info, &rr);
        if (!st) return Status::error(st.code, escape_name(path) + ": " + st.message);
        std::snprintf(buf, sizeof buf, "step %g from %d encodings: %.4f bpp", rr.step, rr.encodings, rr.bpp);
        *note = buf;
        // The file's PSNR, which erdz_rate.h measures whenever the original (of the model's size) is given.
        if (original && original->width == m.width && original->height == m.height && original->channels == m.channels) {
            std::snprintf(buf, sizeof buf, ", %.4f dB", rr.psnr);
            *note += buf;
        }
        if (!rr.met) *note += c.target.psnr > 0.0 ? " (target not met: the finest step)" : " (target not met: the coarsest step)";
        return st;
    }
    Status st = encode_model_file(path, m, c.erdz, bytes, &info);
    if (!st) return st;
    std::snprintf(buf, sizeof buf, "step %g: %zu bits, %.4f bpp", info.step, info.total_bits,
                  double(info.total_bits) / (double(m.width) * double(m.height)));
    *note = buf;
    return st;
}

}  // namespace erd::cli
