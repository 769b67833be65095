#include "algorithms/methods/methods.h"

#include "algorithms/methods/ed.h"
#include "algorithms/methods/erded.h"
#include "algorithms/methods/erdgpi.h"
#include "algorithms/methods/gpi.h"

namespace erd {

namespace {

// Memory factors: peak heap bytes measured (operator new high-water mark around generate(), the
// view's copy included) on the seven test images at 0.5% and 3%: ED 66 B/pixel whatever N; GPI
// 4 B/pixel + 186 B/vertex; ERDED and ERDGPI 108-116 B/pixel + 170-225 B/vertex (the edge
// detector's half-pixel planes dominate). The factors keep >= 20% headroom over every
// measurement (docs/DECISIONS.md, Packaging).
const MethodInfo kMethods[] = {
    {"ed", "error diffusion on the MMSODD (thesis 3.2.1, ywb), basic model", ModelKind::basic, "ywb", "idnotpx", 32, 64,
     generate_ed},
    {"gpi", "greedy point insertion (thesis 3.2.2, gpi), basic model", ModelKind::basic, "gpi", "idnotpx", 8, 256,
     generate_gpi},
    {"erded", "ERD model, error-diffusion refinement (thesis 3.4.2, erd_ed)", ModelKind::erd, "erd_ed",
     "idnotpxlbrefwsBS", 88, 320, generate_erded},
    {"erdgpi", "ERD model, greedy point insertion (thesis 3.4.3, erd_gpi)", ModelKind::erd, "erd_gpi",
     "idnotpxlbrewsS", 88, 320, generate_erdgpi},
};

}  // namespace

const MethodInfo* methods(std::size_t* count) {
    *count = sizeof kMethods / sizeof kMethods[0];
    return kMethods;
}

const MethodInfo* find_method(const std::string& name) {
    for (const MethodInfo& m : kMethods)
        if (name == m.name) return &m;
    return nullptr;
}

std::string method_names() {
    std::string out;
    for (const MethodInfo& m : kMethods) out += (out.empty() ? "" : ", ") + std::string(m.name);
    return out;
}

}  // namespace erd
