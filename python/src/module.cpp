// erd._erd: the compiled half of the erd package. Every call goes to the public C++ API
// (api/erd.h) or, for erd.edges and the files, to the library pieces the erd program uses
// (algorithms/imaging/polylines.h, algorithms/model/model_io.h, cli/fileio.h). Long calls run
// without the interpreter lock; erd.generate stops on Ctrl-C (python/src/interrupt.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/imaging/edge_polylines.h"
#include "algorithms/model/model_io.h"
#include "api/erd.h"
#include "cli/commands.h"
#include "cli/fileio.h"
#include "python/src/arrays.h"
#include "python/src/interrupt.h"
#include "python/src/mesh.h"
#include "python/src/options.h"

namespace erd::py {

namespace pyb = pybind11;

namespace {

pyb::object density_error;  // erd.DensityError, set at import

Mesh generate(pyb::handle image, const std::string& method, double density, pyb::handle points, const pyb::kwargs& kwargs) {
    api::Method m;
    Status st = api::method_from_name(method, &m);
    if (!st) raise_status(st);
    GenerateArgs args = generate_args(density, points, kwargs);
    const ImageArg img = image_arg(image, "image", args.maxval, args.nodata);
    Interrupt interrupt;
    args.options.generate.progress = interrupt.hook();
    Mesh mesh;
    api::GenerateInfo info;
    {
        pyb::gil_scoped_release unlocked;
        st = api::generate(m, img.view, args.options, &mesh.model, &info);
    }
    interrupt.rethrow();
    mesh.method = method;
    mesh.requested = info.requested;
    mesh.achieved = info.achieved;
    mesh.run = info.stats;
    mesh.stages = std::move(info.stages);
    if (st.code == Code::density) {
        pyb::object e = density_error(st.message);
        e.attr("mesh") = pyb::cast(std::move(mesh));
        PyErr_SetObject(density_error.ptr(), e.ptr());
        throw pyb::error_already_set();
    }
    if (!st) raise_status(st);
    if (!info.warning.empty())
        pyb::module_::import("warnings").attr("warn")(info.warning, pyb::module_::import("builtins").attr("RuntimeWarning"), 2);
    return mesh;
}

Mesh load(pyb::handle path) {
    pyb::module_ os = pyb::module_::import("os");
    const std::string name = os.attr("fsdecode")(os.attr("fspath")(path)).cast<std::string>();
    Mesh mesh;
    std::string text;
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        st = cli::read_file(name, &text);
    }
    if (!st) raise_status(st, true);
    const ModelFileKind kind = model_kind_from_name(name);
    if (kind == ModelFileKind::triangulation)
        raise_status(Status::bad_input(name + ": a -t triangulation has no values; erd.load reads .model and .erd files"));
    {
        pyb::gil_scoped_release unlocked;
        st = read_model(text, kind, &mesh.model);
    }
    if (!st) raise_status(Status::bad_input(name + ": " + st.message));
    mesh.requested = mesh.achieved = mesh.model.vertices.size();
    return mesh;
}

double psnr(pyb::handle a, pyb::handle b, std::optional<long long> maxval) {
    if (!maxval) maxval = dtype_maxval(a);
    const ImageArg x = image_arg(a, "a", maxval), y = image_arg(b, "b", maxval);
    double db = 0;
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        st = api::psnr(x.view, y.view, &db);
    }
    if (!st) raise_status(st);
    return db;
}

struct Edges {
    pyb::array map;
    std::vector<pyb::array> polylines;
    double tau_high = 0, tau_low = 0;
};

Edges edges(pyb::handle image, double beta, double ratio, double tolerance, int min_length, bool length_after,
            bool plain_canny, std::optional<long long> maxval) {
    const ImageArg img = image_arg(image, "image", maxval);
    if (img.view.channels != 1) throw pyb::value_error("erd.edges takes a gray image (H x W); pass one channel or the luma");
    EdgePolylineParams params;
    params.canny.beta = beta;
    params.canny.r = ratio;
    params.canny.modified = !plain_canny;
    params.epsilon = tolerance;
    params.min_length = min_length;
    if (length_after) params.length_rule = LengthRule::after_simplification;
    Image copy(img.view.width, img.view.height, img.view.maxval);
    EdgePolylineResult chain;
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        for (int y = 0; y < copy.height; ++y)
            for (int x = 0; x < copy.width; ++x) copy.at(x, y) = img.view.samples[std::size_t(y) * img.view.stride + std::size_t(x)];
        st = edge_polylines(copy, params, &chain);
    }
    if (!st) raise_status(st);
    Edges e;
    pyb::array_t<bool> m({std::size_t(chain.edges.height), std::size_t(chain.edges.width)});
    bool* dst = m.mutable_data();
    for (std::size_t i = 0; i < chain.edges.data.size(); ++i) dst[i] = chain.edges.data[i] != 0;
    e.map = m;
    for (const Polyline& l : chain.polylines)
        e.polylines.push_back(table<double>(l.size(), 2, [&](std::size_t i, std::size_t j) { return 0.5 * double(j ? l[i].y : l[i].x); }));
    e.tau_high = chain.stats.tau_high;
    e.tau_low = chain.stats.tau_low;
    return e;
}

int cli_main(const std::vector<std::string>& argv) {
    std::vector<std::string> args = argv;
    std::vector<char*> ptrs;
    for (std::string& s : args) ptrs.push_back(&s[0]);
    ptrs.push_back(nullptr);
    pyb::gil_scoped_release unlocked;
    const int status = cli::run(int(args.size()), ptrs.data());
    std::fflush(stdout);
    return status;
}

}  // namespace

}  // namespace erd::py

PYBIND11_MODULE(_erd, m) {
    namespace pyb = pybind11;
    using namespace erd::py;
    m.doc() = "erd: image -> triangle mesh with explicit edge discontinuities (the compiled part; use `import erd`).";
    // The docstrings carry the Python signatures (pybind11's own would show C++ types: handle, kwargs).
    pyb::options doc_options;
    doc_options.disable_function_signatures();
    bind_mesh(m);

    density_error = pyb::reinterpret_steal<pyb::object>(
        PyErr_NewExceptionWithDoc("erd.DensityError",
                                  "The method could not place exactly the requested number of vertices (exit_mode=0, "
                                  "the default; `erd generate` exits 3). The mesh it made is in .mesh.",
                                  PyExc_ValueError, nullptr));
    m.attr("DensityError") = density_error;

    m.def("generate", &generate, pyb::arg("image"), pyb::arg("method") = "erdgpi", pyb::arg("density") = 1.0,
          pyb::arg("points") = pyb::none(),
          ("generate(image, method='erdgpi', density=1.0, points=None, **options) -> Mesh\n\n"
           "Meshes a uint8 or uint16 array, H x W (gray) or H x W x 3 (RGB: a colour mesh), as `erd generate` does, or a\n"
           "real-valued one (float32, float64, int16, int32, uint32: elevation, scientific data) without quantising it;\n"
           "NaN and nodata= mark pixels without data (the mesh covers the rest). method: 'ed', 'gpi', 'gpr', 'gprfs',\n"
           "'id' (basic model), 'erded', 'erdgpi', 'erdgpr' (ERD model; erdgpr the best). density: vertices as a percentage of the pixels; points:\n"
           "an exact vertex count instead (wins over density). options: the `erd generate` flags by their long\n"
           "names with '_' for '-' (beta=0.05, thesis=True, max_error=2.0, ...), plus maxval= (default 255 for\n"
           "uint8, 65535 for uint16). Options: " + option_names() + ".\n\n"
           "Raises TypeError for unknown option names, ValueError for bad arrays or values (with the library's\n"
           "message), erd.DensityError when the vertex count is not met exactly and exit_mode=0 (exit_mode=1 warns,\n"
           "2 is silent), KeyboardInterrupt on Ctrl-C. Runs without the GIL.").c_str());
    m.def("load", &load, pyb::arg("path"),
          "load(path) -> Mesh\n\nReads a .model or .erd file (the kind from the name, else from the content).\n"
          "OSError when the file cannot be read, ValueError when it is not a valid model.");
    m.def("psnr", &psnr, pyb::arg("a"), pyb::arg("b"), pyb::arg("maxval") = pyb::none(),
          "psnr(a, b, maxval=None) -> float\n\nPSNR of approximation b against original a in dB, as `erd psnr`: peak 2^p - 1 for\n"
          "p the bits of maxval (default 255 for uint8 a, 65535 for uint16); inf when equal. Both arrays\n"
          "uint8/uint16 of one shape (H x W, or H x W x 3: the MSE over all channels).");
    pyb::class_<Edges>(m, "Edges", "What erd.edges finds: the half-pixel edge map and the simplified polylines.")
        .def_readonly("map", &Edges::map, "(2H-1) x (2W-1) bool: True at half-pixel lattice points on an edge.")
        .def_readonly("polylines", &Edges::polylines, "List of K x 2 float64 arrays of (x, y) in pixel units.")
        .def_readonly("tau_high", &Edges::tau_high, "The high hysteresis threshold used.")
        .def_readonly("tau_low", &Edges::tau_low, "The low hysteresis threshold used.")
        .def("__repr__", [](const Edges& e) {
            return "<erd.Edges " + std::to_string(e.polylines.size()) + " polylines, tau_high " + std::to_string(e.tau_high) + ">";
        });
    const erd::EdgePolylineParams defaults;  // the library's, as `erd edges` has them
    m.def("edges", &edges, pyb::arg("image"), pyb::kw_only(), pyb::arg("beta") = defaults.canny.beta,
          pyb::arg("ratio") = defaults.canny.r, pyb::arg("tolerance") = defaults.epsilon,
          pyb::arg("min_length") = defaults.min_length, pyb::arg("length_after") = false, pyb::arg("plain_canny") = false,
          pyb::arg("maxval") = pyb::none(),
          "edges(image, *, beta=0.055, ratio=0.4, tolerance=1.0, min_length=5, length_after=False, plain_canny=False,\n"
          "      maxval=None) -> Edges\n\n"
          "The first stage of ERDED and ERDGPI on its own, as `erd edges`: edges at half-pixel resolution\n"
          "(modified Canny), traced into polylines and simplified (Douglas-Peucker tolerance in pixels;\n"
          "min_length counted before simplification unless length_after). ValueError for parameters out of range.");
    m.def("_cli_main", &cli_main, pyb::arg("argv"),
          "_cli_main(argv) -> int: the erd program's main on argv (argv[0] = program name); returns the exit status.");
}
