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
#include "kernel/predicates.h"

namespace {

void check_refusal(const erd::Status& s) {
    if (s.code != erd::Code::input || s.message.empty() || s.message.find('\n') != std::string::npos) std::abort();
}

void check_model(const erd::Model& m) {
    if (m.channels != 1 && m.channels != 3) std::abort();
    const std::size_t C = std::size_t(m.channels);
    if (m.width < 1 || m.height < 1 || m.values.size() != m.vertices.size() * C) std::abort();
    if (m.kind == erd::ModelKind::erd && m.corner_values.size() != m.faces.size() * C) std::abort();
    for (const auto& f : m.faces) {
        for (std::uint32_t v : f)
            if (v >= m.vertices.size()) std::abort();
        if (erd::orient2d(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) <= 0) std::abort();
    }
    for (const auto& p : m.vertices)
        if (p.x < 0 || p.y < 0 || p.x > 2 * m.width - 2 || p.y > 2 * m.height - 2) std::abort();
}

void run(const std::string& text, erd::ModelFileKind kind) {
    erd::Model m;
    erd::Status s = erd::read_model(text, kind, &m);
    if (!s.ok()) {
        check_refusal(s);
        return;
    }
    check_model(m);
    if (std::int64_t(m.width) * m.height > (std::int64_t(1) << 16)) return;  // keep runs fast
    erd::Image a[2];
    for (int ss = 0; ss < 2; ++ss) {
        s = erd::reconstruct(m, ss == 1, &a[ss]);
        if (!s.ok()) {
            check_refusal(s);
            return;
        }
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
