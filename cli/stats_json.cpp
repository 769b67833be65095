#include "cli/stats_json.h"

#include <sys/resource.h>

#include <cmath>

#include "algorithms/model/model_topology.h"
#include "cli/report.h"

namespace erd::cli {

GenerateStats collect_stats(const std::string& method, const Image& image, const GenerateResult& result) {
    GenerateStats s;
    const Model& m = result.model;
    s.method = method;
    s.width = image.width;
    s.height = image.height;
    s.maxval = image.maxval;
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
        s.dropped_constraints = rs.erd.dropped_crossing;
    }
    if (rs.has_greedy) s.stop = to_string(rs.greedy.stop);
    return s;
}

static std::string kv(const char* key, const std::string& value) { return std::string("\"") + key + "\":" + value; }
static std::string num(double v) { return json_number(v); }
static std::string num(std::size_t v) { return std::to_string(v); }

std::string stats_json(const GenerateStats& s) {
    std::string j = "{";
    j += kv("method", json_string(s.method)) + ",";
    j += kv("model", s.erd ? "\"erd\"" : "\"basic\"") + ",";
    j += kv("image", "{" + kv("width", std::to_string(s.width)) + "," + kv("height", std::to_string(s.height)) + "," +
                         kv("maxval", std::to_string(s.maxval)) + "}") + ",";
    j += kv("points", "{" + kv("requested", num(s.requested)) + "," + kv("achieved", num(s.achieved)) + "}") + ",";
    j += kv("vertices", num(s.vertices)) + ",";
    j += kv("faces", num(s.faces)) + ",";
    j += kv("constrained_vertices", num(s.constrained_vertices)) + ",";
    j += kv("constrained_edges", num(s.constrained_edges)) + ",";
    j += kv("dropped_constraints", num(s.dropped_constraints)) + ",";
    if (s.has_params)
        j += kv("parameters", "{" + kv("beta", num(s.beta)) + "," + kv("r", num(s.r)) + "," + kv("l", std::to_string(s.l)) +
                                  "," + kv("epsilon", num(s.epsilon)) + "," + kv("simple", s.simple ? "true" : "false") +
                                  "}") + ",";
    else
        j += kv("parameters", "null") + ",";
    j += kv("stop", s.stop.empty() ? "null" : json_string(s.stop)) + ",";
    j += "\"stages\":[";
    for (std::size_t i = 0; i < s.stages.size(); ++i) {
        if (i) j += ",";
        j += "{" + kv("name", json_string(s.stages[i].name)) + "," + kv("seconds", num(s.stages[i].seconds)) + "}";
    }
    j += "],";
    j += kv("total_seconds", num(s.total_seconds)) + ",";
    j += kv("peak_memory_bytes", std::to_string(s.peak_memory_bytes));
    if (s.has_psnr) j += "," + kv("psnr", num(s.psnr));
    j += "}\n";
    return j;
}

long long peak_memory_bytes() {
    struct rusage ru {};
    if (getrusage(RUSAGE_SELF, &ru) != 0) return 0;
    return static_cast<long long>(ru.ru_maxrss) * 1024;  // Linux: kilobytes
}

}  // namespace erd::cli
