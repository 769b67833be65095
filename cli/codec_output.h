// The .erdz flags shared by `erd generate` and `erd convert` (--step, --bpp, --step-psnr) and
// the writing of a model to the file name it goes to.
#pragma once
#include <string>

#include "algorithms/codec/erdz.h"
#include "algorithms/codec/erdz_rate.h"
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "cli/args.h"
#include "kernel/status.h"

namespace erd::cli {

struct CodecChoice {
    ErdzOptions erdz;
    RateTarget target;  // bpp or psnr > 0: the step is searched (erdz_rate.h)
    bool given = false; // any of the flags was given
    bool choose_density = false;  // --choose-density: the density is searched too (cli/rd_search.h)
};

// Parses --step Q, --bpp B, --step-psnr P (at most one); the first bad value sets *st.
void parse_codec_options(const Args& a, CodecChoice* c, Status* st);

// The bytes of m for `path`: .erdz by the choice (a target needs `original` for --step-psnr),
// else the text model, which refuses codec flags. *note gets "step S, B bits (X bpp)..." for
// an .erdz (empty otherwise).
Status model_bytes_for(const std::string& path, const Model& m, const Image* original, const CodecChoice& c,
                       std::string* bytes, std::string* note);

}  // namespace erd::cli
