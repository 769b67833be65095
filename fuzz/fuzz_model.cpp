// libFuzzer target for the model-file readers (algorithms/model/model_io.h: .model and .erd) and
// reconstruction of whatever they accept.
//
// Checks beyond "no crash": a refusal is one non-empty line with Code::input; an accepted model
// keeps the reader's promises (indices in range, positive faces, finite values, the corners as
// vertices); reconstruct() either refuses it with Code::input or returns a W x H image with
// samples <= maxval; and an accepted model that reconstructs survives write -> read with the same
// images (both modes). Each input is read as unknown (content decides), .model and .erd.
// Replay without libFuzzer: fuzz/replay.cpp.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "fuzz/fuzz_checks.h"

namespace {

using fuzz_checks::check_model;

void run(const std::string& text, erd::ModelFileKind kind) {
    erd::Model m;
    erd::Status s = erd::read_model(text, kind, &m);
    if (!fuzz_checks::accepted(s)) return;
    check_model(m);
    if (std::int64_t(m.width) * m.height > (std::int64_t(1) << 16)) return;  // keep runs fast
    erd::Image a[2];
    for (int ss = 0; ss < 2; ++ss) {
        s = erd::reconstruct(m, ss == 1, &a[ss]);
        if (!fuzz_checks::accepted(s)) return;
        if (a[ss].width != m.width || a[ss].height != m.height || a[ss].channels != m.channels ||
            a[ss].samples.size() != std::size_t(m.width) * std::size_t(m.height) * std::size_t(m.channels))
            std::abort();
        for (std::uint16_t v : a[ss].samples)
            if (v > m.maxval) std::abort();
    }
    std::string out;
    if (!erd::write_model(m, &out).ok()) std::abort();
    erd::Model r;
    if (!erd::read_model(out, m.kind == erd::ModelKind::erd ? erd::ModelFileKind::erd : erd::ModelFileKind::basic, &r).ok())
        std::abort();
    if (r.vertices != m.vertices || r.faces != m.faces || r.corner_values != m.corner_values || r.maxval != m.maxval ||
        r.channels != m.channels || r.edges != m.edges || r.kind_exceptions != m.kind_exceptions)
        std::abort();
    std::string again;
    if (!erd::write_model(r, &again).ok() || again != out) std::abort();
    for (int ss = 0; ss < 2; ++ss) {
        erd::Image b;
        if (!erd::reconstruct(r, ss == 1, &b).ok() || b.samples != a[ss].samples) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 1 << 16) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    run(text, erd::ModelFileKind::unknown);
    run(text, erd::ModelFileKind::basic);
    run(text, erd::ModelFileKind::erd);
    return 0;
}
