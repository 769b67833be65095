#include "python/src/options.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace erd::py {

namespace pyb = pybind11;

namespace {

enum class Kind { integer, real, flag };

// One keyword: its name, type, accepted range and where it goes. `odd`: wedge_order.
struct Spec {
    const char* name;
    Kind kind;
    double lo, hi;
    void (*set)(GenerateArgs*, double);
};

const double kBig = 1e300;

// The order is the CLI's; thesis is applied before the others so an explicit value still wins.
const std::vector<Spec>& specs() {
    static const std::vector<Spec> s = {
        {"exit_mode", Kind::integer, 0, 2, [](GenerateArgs* a, double v) { a->options.exact = api::ExactMode(int(v)); }},
        {"max_error", Kind::real, 0, kBig, [](GenerateArgs* a, double v) { a->options.generate.max_error = v; }},
        {"psnr", Kind::real, 1e-300, kBig, [](GenerateArgs* a, double v) { a->options.generate.psnr = v; }},
        {"triangles", Kind::integer, 1, 9e18, [](GenerateArgs* a, double v) { a->options.generate.triangles = std::int64_t(v); }},
        {"min_length", Kind::integer, 1, 1 << 20, [](GenerateArgs* a, double v) { a->options.generate.min_length = int(v); }},
        {"beta", Kind::real, 1e-9, 1.0, [](GenerateArgs* a, double v) { a->options.generate.beta = v; }},
        {"ratio", Kind::real, 1e-9, 1.0, [](GenerateArgs* a, double v) { a->options.generate.ratio = v; }},
        {"epsilon", Kind::real, 0, kBig, [](GenerateArgs* a, double v) { a->options.generate.epsilon = v; }},
        {"select", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.ed_select = int(v); }},
        {"wedge_rule", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.wedge_rule = int(v); }},
        {"wedge_order", Kind::integer, 1, 31, [](GenerateArgs* a, double v) { a->options.generate.wedge_order = int(v); }},
        {"startup", Kind::integer, 0, 2, [](GenerateArgs* a, double v) { a->options.generate.startup = int(v); }},
        {"simple", Kind::integer, 0, 1 << 30, [](GenerateArgs* a, double v) { a->options.generate.simple = int(v); }},
        {"lower_beta", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.lower_beta = v == 1; }},
        {"seed", Kind::integer, 0, double(1LL << 62), [](GenerateArgs* a, double v) { a->options.generate.seed = std::uint64_t(v); }},
        {"wedge_fit", Kind::integer, 0, 1000, [](GenerateArgs* a, double v) { a->options.generate.wedge_fit = int(v); }},
        {"alpha_min", Kind::real, 0, 64, [](GenerateArgs* a, double v) { a->options.generate.alpha_min = v; }},
        {"alpha_max", Kind::real, 0, 64, [](GenerateArgs* a, double v) { a->options.generate.alpha_max = v; }},
        {"edge_zero_radius", Kind::integer, 0, 64, [](GenerateArgs* a, double v) { a->options.generate.edge_zero_radius = int(v); }},
        {"flips", Kind::integer, 0, 64, [](GenerateArgs* a, double v) {
             a->options.generate.flips = int(v);
             a->options.generate.ending_given = true;
         }},
        {"moves", Kind::integer, 0, 64, [](GenerateArgs* a, double v) {
             a->options.generate.moves = int(v);
             a->options.generate.ending_given = true;
         }},
        {"oversample", Kind::real, 1, 64, [](GenerateArgs* a, double v) { a->options.generate.oversample = v; }},
        {"lazy", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.removal_lazy = v == 1; }},
        {"bpr", Kind::integer, 0, 1000, [](GenerateArgs* a, double v) { a->options.generate.bpr = int(v); }},
        {"id_cycles", Kind::integer, 0, 1000, [](GenerateArgs* a, double v) { a->options.generate.id_cycles = int(v); }},
        {"id_share", Kind::real, 0, 4, [](GenerateArgs* a, double v) { a->options.generate.id_share = v; }},
        {"removal_refit", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.removal_refit = int(v); }},
        {"removal_stages", Kind::integer, 1, 16, [](GenerateArgs* a, double v) { a->options.generate.removal_stages = int(v); }},
        {"removal_cycles", Kind::integer, 0, 16, [](GenerateArgs* a, double v) { a->options.generate.removal_cycles = int(v); }},
        {"aa_errors", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.supersampled_errors = v == 1; }},
        {"count_search", Kind::integer, 0, 1, [](GenerateArgs* a, double v) { a->options.generate.count_search = v == 1; }},
        {"maxval", Kind::integer, 1, 65535, [](GenerateArgs* a, double v) { a->maxval = (long long)v; }},
        {"nodata", Kind::real, -kBig, kBig, [](GenerateArgs* a, double v) { a->nodata = v; }},
        {"max_slack", Kind::real, 1.0, 16.0, [](GenerateArgs* a, double v) { a->options.generate.max_slack = v; }},
        {"minimax", Kind::integer, 0, 64, [](GenerateArgs* a, double v) { a->options.generate.minimax_rounds = int(v); }},
        {"min_step", Kind::real, 0, 1e6, [](GenerateArgs* a, double v) { a->options.generate.min_step_factor = v; }},
        {"max_memory", Kind::integer, 0, 9e18, [](GenerateArgs* a, double v) { a->options.max_memory = std::size_t(v); }},
        {"threads", Kind::integer, 0, 256, [](GenerateArgs* a, double v) { a->options.generate.threads = int(v); }},
    };
    return s;
}

std::string real_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The value of keyword `name` as a double, after its type check.
double number(const std::string& name, Kind kind, pyb::handle v) {
    const bool is_bool = pyb::isinstance<pyb::bool_>(v);
    const bool is_int = !is_bool && PyLong_Check(v.ptr());
    if (kind == Kind::integer && !is_int)
        throw pyb::type_error(name + " must be an int, got " + std::string(pyb::str(pyb::type::handle_of(v).attr("__name__"))));
    if (kind == Kind::real && (is_bool || !(is_int || PyFloat_Check(v.ptr()))))
        throw pyb::type_error(name + " must be a number, got " + std::string(pyb::str(pyb::type::handle_of(v).attr("__name__"))));
    if (is_int) {
        // Range-check big integers before they turn into doubles.
        const long long x = PyLong_AsLongLong(v.ptr());
        if (x == -1 && PyErr_Occurred()) {
            PyErr_Clear();
            throw pyb::value_error(name + ": " + std::string(pyb::str(v)) + " is out of range");
        }
        return double(x);
    }
    return v.cast<double>();
}

void unknown(const std::vector<std::string>& names) {
    std::vector<std::string> known;
    for (const Spec& s : specs()) known.push_back(s.name);
    known.push_back("thesis");
    known.push_back("edges");
    pyb::object close = pyb::module_::import("difflib").attr("get_close_matches");
    std::string msg = "generate() got unexpected keyword argument" + std::string(names.size() > 1 ? "s " : " ");
    for (std::size_t i = 0; i < names.size(); ++i) {
        msg += (i ? ", '" : "'") + names[i] + "'";
        pyb::list guess = close(names[i], pyb::cast(known), 1);
        if (!guess.empty()) msg += " (did you mean '" + guess[0].cast<std::string>() + "'?)";
    }
    throw pyb::type_error(msg + "; options: " + option_names());
}

}  // namespace

std::string option_names() {
    std::vector<std::string> names = {"thesis", "edges"};
    for (const Spec& s : specs()) names.push_back(s.name);
    std::sort(names.begin(), names.end());
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
    return out;
}

GenerateArgs generate_args(double density, pyb::handle points, const pyb::kwargs& kwargs) {
    GenerateArgs a;
    std::vector<std::string> bad;
    for (auto item : kwargs) {
        const std::string name = item.first.cast<std::string>();
        bool found = name == "thesis" || name == "edges";
        for (const Spec& s : specs()) found = found || name == s.name;
        if (!found) bad.push_back(name);
    }
    if (!bad.empty()) unknown(bad);

    GenerateOptions& g = a.options.generate;
    if (points.is_none()) {
        if (!(density > 0.0) || !std::isfinite(density))
            throw pyb::value_error("density " + real_text(density) + " is not a positive percentage");
        g.density = density;
        g.density_given = true;
    } else {
        const double n = number("points", Kind::integer, points);
        if (n < 1 || n > double(1LL << 40)) throw pyb::value_error("points " + std::string(pyb::str(points)) + " is out of range");
        g.points = std::int64_t(n);
    }
    if (kwargs.contains("thesis")) {
        pyb::handle t = kwargs["thesis"];
        if (!pyb::isinstance<pyb::bool_>(t)) throw pyb::type_error("thesis must be True or False");
        if (t.cast<bool>()) set_thesis_preset(&g);
    }
    // `erd generate --edges KIND`; like the other explicit keywords it beats thesis=True's soft.
    if (kwargs.contains("edges")) {
        pyb::handle e = kwargs["edges"];
        if (!pyb::isinstance<pyb::str>(e)) throw pyb::type_error("edges must be 'hard', 'soft' or 'auto'");
        const std::string k = e.cast<std::string>();
        if (k == "hard") g.edges = EdgeChoice::hard;
        else if (k == "soft") g.edges = EdgeChoice::soft;
        else if (k == "auto") g.edges = EdgeChoice::automatic;
        else throw pyb::value_error("edges: '" + k + "' is not 'hard', 'soft' or 'auto'");
    }
    for (const Spec& s : specs()) {
        if (!kwargs.contains(s.name)) continue;
        const double v = number(s.name, s.kind, kwargs[s.name]);
        if (!(v >= s.lo && v <= s.hi) && !(std::isnan(v) && std::string(s.name) == "nodata"))
            throw pyb::value_error(std::string(s.name) + ": " + std::string(pyb::str(kwargs[s.name])) + " is outside " +
                                   real_text(s.lo) + ".." + real_text(s.hi));
        s.set(&a, v);
    }
    if (g.wedge_order % 2 == 0) throw pyb::value_error("wedge_order: " + std::to_string(g.wedge_order) + " is not an odd filter order");
    if (g.alpha_max < g.alpha_min)
        throw pyb::value_error("alpha_max " + real_text(g.alpha_max) + " is below alpha_min " + real_text(g.alpha_min));
    return a;
}

}  // namespace erd::py
