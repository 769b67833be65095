#include "algorithms/methods/result.h"

#include <cstdio>

namespace erd {

namespace {

std::string real(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

}  // namespace

std::vector<std::string> result_lines(const RunStats& r) {
    std::vector<std::string> out;
    if (r.has_wedge_fit)
        out.push_back("wedge refit: " + std::to_string(r.wedge_fit.iterations) + " iterations, sse " +
                      real("%.6g", r.wedge_fit.sse_before) + " -> " + real("%.6g", r.wedge_fit.sse_after));
    if (r.has_erd) {
        const ErdStepStats& s = r.erd;
        const ErdParams& p = s.params;
        out.push_back("beta: " + real("%.6g", p.beta));
        out.push_back("r: " + real("%.6g", p.r));
        out.push_back("l: " + std::to_string(p.l));
        out.push_back("eps: " + real("%.6g", p.eps));
        out.push_back(std::string("simple: ") + (p.simple ? "yes" : "no"));
        out.push_back("parameter loop iterations: " + std::to_string(p.loop_iterations));
        out.push_back("polylines: " + std::to_string(s.polylines));
        out.push_back("initial mesh vertices: " + std::to_string(s.initial_vertices));
        out.push_back("dropped crossing constraints: " + std::to_string(s.dropped_crossing));
        if (s.dropped_polylines > 0)
            out.push_back("dropped polylines (N too small for them): " + std::to_string(s.dropped_polylines));
        out.push_back(std::string("edges: ") + (s.hard_edges ? "hard" : "soft") +
                      (s.edges_measured ? " (measured: " + std::to_string(s.hard_steps) + " hard and " + std::to_string(s.soft_steps) +
                                              " soft strong steps)"
                                        : " (asked for)"));
        if (s.edges_measured)
            out.push_back("clean steps: " + std::to_string(s.clean_steps) + " of " + std::to_string(s.all_steps) + " strong steps" +
                          (s.stepped ? " (stepped)" : ""));
        if (s.tried) {
            static const char* const kTried[3] = {"soft detection", "hard edges", "no edges"};
            std::string tried = "edge treatments tried (each edge's kind by fit):";
            for (int k = 0; k < 3; ++k) tried += std::string(k ? ", " : " ") + kTried[k] + " " + real("%.4f", s.tried_psnr[k]) + " dB";
            if (s.tried_choice >= 0) tried += std::string("; kept ") + kTried[s.tried_choice];
            out.push_back(tried);
        }
        if (s.kind_exceptions > 0)
            out.push_back("edges of the other kind: " + std::to_string(s.kind_exceptions) + " (" + (s.hard_edges ? "soft" : "hard") + ")");
        if (s.plain_psnr > 0 || s.exact_psnr > 0)
            out.push_back("hard curves: plain past the budget " + real("%.4f", s.plain_psnr) + " dB, side-keeping only " +
                          real("%.4f", s.exact_psnr) + " dB (the better kept)");
        out.push_back("multi-wedge values: " + std::to_string(s.multi_wedges) + " (line-search maximum at alpha_min: " +
                      std::to_string(s.alpha_first) + ", at alpha_max: " + std::to_string(s.alpha_last) + ")");
    }
    if (r.has_diffusion) {
        out.push_back("threshold rho " + real("%.6g", r.diffusion.rho) + " after " + std::to_string(r.diffusion.passes) +
                      " diffusion passes");
        out.push_back("points added/removed to reach N exactly: " + std::to_string(r.diffusion.adjusted));
    }
    if (r.has_greedy) {
        out.push_back(std::string("stop: ") + to_string(r.greedy.stop));
        out.push_back("insertions: " + std::to_string(r.greedy.insertions));
        out.push_back("max abs error: " + real("%.4g", r.greedy.max_error));
        out.push_back("psnr (point evaluation): " + real("%.4f", r.greedy.psnr));
    }
    if (r.has_removal) {
        out.push_back("point removal: " + std::to_string(r.removal.removed) + " of " + std::to_string(r.removal.start) +
                      " vertices removed, " + std::to_string(r.removal.evaluations) + " significances computed");
        if (r.removal.bpr_rounds > 0)
            out.push_back("bad-point replacement: " + std::to_string(r.removal.bpr_rounds) + " rounds, " +
                          std::to_string(r.removal.bpr_moves) + " of " + std::to_string(r.removal.bpr_tried) +
                          " exchanges kept");
    }
    if (r.has_raster) {
        const RasterStats& s = r.raster;
        if (s.outline_points || s.dropped_faces)
            out.push_back("nodata: outline of " + std::to_string(s.outline_points) + " points, " + std::to_string(s.dropped_faces) +
                          " faces and " + std::to_string(s.dropped_vertices) + " vertices over nodata dropped");
        if (s.max_error >= 0)
            out.push_back("max error over valid pixels: " + real("%.6g", s.max_error) + " (after " +
                          std::to_string(s.fixup_insertions) + " insertions of the last greedy pass)");
    }
    if (r.has_quality) {
        const QualitySearchStats& q = r.quality;
        out.push_back("quality search: " + std::to_string(q.points) + " points after " + std::to_string(q.runs) + " runs (" +
                      (q.exact ? std::string("the greedy loop's own stop")
                       : !q.reached ? std::string("the target not reached at N")
                       : q.runs == 1 ? std::string("one run, --count-search 0")
                       : q.below == 0 ? std::string("the fewest there are, 4, reach the target")
                                      : "the largest count short of the target: " + std::to_string(q.below)) +
                      "; psnr " + real("%.4f", q.psnr) + " dB, max error " + real("%.4g", q.max_error) + ")");
    }
    return out;
}

}  // namespace erd
