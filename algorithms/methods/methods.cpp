#include "algorithms/methods/methods.h"

#include "algorithms/methods/ed.h"
#include "algorithms/methods/erded.h"
#include "algorithms/methods/erdgpi.h"
#include "algorithms/methods/gpi.h"
#include "algorithms/methods/gpr.h"

namespace erd {

namespace {

// Memory factors of the size bound (memory_estimate.h memory_bound): the peak resident memory of
// `erd generate` (/usr/bin/time, max RSS) on bull, lena, bull at 2x, a synth image of 1024x768
// and 2048x2048 and white noise at 0.5% and 3%, less the 2 MiB of the process itself, fitted as
// bytes per pixel + bytes per vertex: ED 11 + 185, GPI 3 + 184; ERDED and ERDGPI 90 + 900 on the
// edge-rich images (synth, noise). A bound whatever the content, so 3-4 times the peak of a
// photo with an ERD method; the cap uses the estimate from the image (docs/DECISIONS.md, Memory).
// The removal methods (issue 45) come after the thesis's four, so api::Method keeps its values;
// their factors are bounds from the peaks of make eval's runs (GPR: the whole pixel lattice as a
// mesh, about 180 bytes a pixel; GPRFS and ERDGPR: their K*N-point start).
const MethodInfo kMethods[] = {
    {"ed", "error diffusion on the MMSODD (thesis 3.2.1, ywb), basic model", ModelKind::basic, "ywb", "idnotpx", 12, 200,
     generate_ed},
    {"gpi", "greedy point insertion (thesis 3.2.2, gpi), basic model", ModelKind::basic, "gpi", "idnotpx", 3, 210,
     generate_gpi},
    {"erded", "ERD model, error-diffusion refinement (thesis 3.4.2, erd_ed)", ModelKind::erd, "erd_ed",
     "idnotpxlbrefwsBS", 96, 960, generate_erded},
    {"erdgpi", "ERD model, greedy point insertion (thesis 3.4.3, erd_gpi)", ModelKind::erd, "erd_gpi",
     "idnotpxlbrewsS", 96, 960, generate_erdgpi},
    {"gpr", "greedy point removal from all pixels (Adams; Demaret-Iske thinning), basic model", ModelKind::basic,
     nullptr, nullptr, 400, 210, generate_gpr},
    {"gprfs", "GPRFS-ED: ED start at K*N points, then greedy point removal (Adams), basic model", ModelKind::basic,
     nullptr, nullptr, 60, 900, generate_gprfs},
    {"id", "incremental/decremental cycles: GPI's growth, then insert and remove A*N points C times (Adams), basic model",
     ModelKind::basic, nullptr, nullptr, 12, 900, generate_id},
    {"erdgpr", "ERD model, ERDGPI to K*N points then greedy point removal to N (ours, issue 45)", ModelKind::erd,
     nullptr, nullptr, 96, 1900, generate_erdgpr},
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
