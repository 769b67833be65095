#include "cli/stats_json.h"

#include <sys/resource.h>

#include <cmath>

#include "algorithms/model/model_topology.h"
#include "cli/json.h"

namespace erd::cli {

GenerateStats collect_stats(const std::string& method, const Image& image, const GenerateResult& result) {
    GenerateStats s;
    const Model& m = result.model;
    s.method = method;
    s.width = image.width;
    s.height = image.height;
    s.maxval = image.maxval;
    s.channels = m.channels;
    s.erd = m.kind == ModelKind::erd;
    s.requested = result.requested;
    s.achieved = result.achieved;
    s.vertices = m.vertices.size();
    s.faces = m.faces.size();
    s.stages = result.stages;
    ModelTopology topo;
    if (build_topology(m, &topo).ok()) {
        std::vector<bool> touched(m.vertices.size(), false);
        for (const ModelEdge& e : model_edges(m, topo)) {
            if (!e.constrained) continue;
            ++s.constrained_edges;
            touched[e.a] = touched[e.b] = true;
        }
        for (bool t : touched) s.constrained_vertices += t ? 1 : 0;
    }
    const RunStats& rs = result.stats;
    if (rs.has_erd) {
        const ErdParams& p = rs.erd.params;
        s.has_params = true;
        s.beta = p.beta;
        s.r = p.r;
        s.l = p.l;
        s.epsilon = p.eps;
        s.simple = p.simple;
        s.hard_edges = rs.erd.hard_edges;
        s.dropped_constraints = rs.erd.dropped_crossing;
        s.other_kind_edges = result.model.kind_exceptions.size();
    }
    if (rs.has_greedy) s.stop = to_string(rs.greedy.stop);
    s.has_quality = rs.has_quality;
    s.quality = rs.quality;
    return s;
}

std::string stats_json(const GenerateStats& s) {
    JsonObject j;
    j.str("method", s.method).str("model", s.erd ? "erd" : "basic");
    j.object("image", JsonObject().integer("width", s.width).integer("height", s.height).integer("maxval", s.maxval).integer("channels", s.channels));
    j.object("points", JsonObject().integer("requested", (long long)s.requested).integer("achieved", (long long)s.achieved));
    j.integer("vertices", (long long)s.vertices).integer("faces", (long long)s.faces);
    j.integer("constrained_vertices", (long long)s.constrained_vertices);
    j.integer("constrained_edges", (long long)s.constrained_edges);
    j.integer("dropped_constraints", (long long)s.dropped_constraints);
    if (s.erd) j.integer("other_kind_edges", (long long)s.other_kind_edges);
    if (s.has_params)
        j.object("parameters", JsonObject().num("beta", s.beta).num("r", s.r).integer("l", s.l).num("epsilon", s.epsilon).boolean("simple", s.simple)
                                   .str("edges", s.hard_edges ? "hard" : "soft"));
    else
        j.null("parameters");
    if (s.stop.empty()) j.null("stop");
    else j.str("stop", s.stop);
    std::string stages = "[";
    for (std::size_t i = 0; i < s.stages.size(); ++i)
        stages += (i ? "," : "") + JsonObject().str("name", s.stages[i].name).num("seconds", s.stages[i].seconds).text();
    j.raw("stages", stages + "]");
    j.num("total_seconds", s.total_seconds).integer("peak_memory_bytes", s.peak_memory_bytes);
    j.integer("memory_estimate_bytes", s.memory_estimate_bytes);
    if (s.has_psnr) j.num("psnr", s.psnr);
    if (s.has_quality) {
        const QualitySearchStats& q = s.quality;
        j.object("quality_search", JsonObject().integer("runs", q.runs).integer("points", (long long)q.points)
                                       .integer("below", (long long)q.below).boolean("reached", q.reached)
                                       .boolean("exact", q.exact).num("psnr", q.psnr).num("max_error", q.max_error));
    }
    return j.text() + "\n";
}

long long peak_memory_bytes() {
    struct rusage ru {};
    if (getrusage(RUSAGE_SELF, &ru) != 0) return 0;
    return static_cast<long long>(ru.ru_maxrss) * 1024;  // Linux: kilobytes
}

}  // namespace erd::cli
