#include "python/src/mesh.h"

#include <pybind11/numpy.h>

#include <cctype>
#include <utility>

#include "algorithms/model/model_io.h"
#include "algorithms/model/model_topology.h"
#include "algorithms/output/export.h"
#include "api/erd.h"
#include "cli/fileio.h"
#include "cli/stats_json.h"
#include "python/src/arrays.h"

namespace erd::py {

namespace pyb = pybind11;

void raise_status(const Status& st, bool os_error) {
    if (os_error) {
        PyErr_SetString(PyExc_OSError, st.message.c_str());
        throw pyb::error_already_set();
    }
    if (st.code == Code::runtime) throw std::runtime_error(st.message);
    throw pyb::value_error(st.message);
}

pyb::dict mesh_stats(const Mesh& mesh) {
    // The CLI's own collector, so the counts mean what --stats's do.
    GenerateResult r;
    r.model = mesh.model;
    r.requested = mesh.requested;
    r.achieved = mesh.achieved;
    r.stats = mesh.run;
    r.stages = mesh.stages;
    Image shape;
    shape.width = mesh.model.width;
    shape.height = mesh.model.height;
    shape.maxval = mesh.model.maxval;
    const cli::GenerateStats s = cli::collect_stats(mesh.method, shape, r);
    const pyb::object none = pyb::none();
    pyb::dict d;
    d["method"] = mesh.method.empty() ? none : pyb::str(mesh.method);
    d["model"] = s.erd ? "erd" : "basic";
    d["image"] = pyb::dict(pyb::arg("width") = s.width, pyb::arg("height") = s.height, pyb::arg("maxval") = s.maxval,
                            pyb::arg("channels") = s.channels);
    d["points"] = pyb::dict(pyb::arg("requested") = s.requested, pyb::arg("achieved") = s.achieved);
    d["vertices"] = s.vertices;
    d["faces"] = s.faces;
    d["constrained_vertices"] = s.constrained_vertices;
    d["constrained_edges"] = s.constrained_edges;
    d["dropped_constraints"] = s.dropped_constraints;
    if (s.erd) d["other_kind_edges"] = s.other_kind_edges;
    d["parameters"] = s.has_params ? pyb::object(pyb::dict(pyb::arg("beta") = s.beta, pyb::arg("r") = s.r, pyb::arg("l") = s.l,
                                                           pyb::arg("epsilon") = s.epsilon, pyb::arg("simple") = s.simple,
                                                           pyb::arg("edges") = s.hard_edges ? "hard" : "soft"))
                                   : none;
    d["stop"] = s.stop.empty() ? none : pyb::str(s.stop);
    pyb::list stages;
    for (const StageTime& t : s.stages) stages.append(pyb::dict(pyb::arg("name") = t.name, pyb::arg("seconds") = t.seconds));
    d["stages"] = stages;
    return d;
}

namespace {

std::string path_text(pyb::handle path) {
    pyb::module_ os = pyb::module_::import("os");
    return os.attr("fsdecode")(os.attr("fspath")(path)).cast<std::string>();
}

pyb::array reconstruct(const Mesh& m, pyb::object supersample) {
    // None: the model's own evaluation (its kind, and its edges of the other kind), as `erd
    // reconstruct` does; True or False: that evaluation at every pixel.
    const bool own = supersample.is_none();
    const bool aa = own ? supersampled(m.model) : supersample.cast<bool>();
    Image out;
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        if (own || m.model.kind_exceptions.empty()) {
            st = api::reconstruct(m.model, aa, &out);
        } else {
            Model every = m.model;
            every.kind_exceptions.clear();
            st = api::reconstruct(every, aa, &out);
        }
    }
    if (!st) raise_status(st);
    return image_array(out);
}

void save(const Mesh& m, pyb::handle path) {
    const std::string name = path_text(path);
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        std::string bytes;
        st = write_model(m.model, &bytes);
        if (st) st = cli::write_file_atomic(name, bytes);
        else st = Status::bad_input(name + ": " + st.message);
    }
    if (!st) raise_status(st, st.code == Code::runtime);
}

// The mesh as `erd export` writes it: the format from the name (.obj, .ply, .stl, .glb) or `format`.
std::string export_bytes(const Mesh& m, const std::string& format, pyb::object zscale) {
    ExportOptions o;
    if (format == "obj") o.format = MeshFormat::obj;
    else if (format == "ply") o.format = MeshFormat::ply;
    else if (format == "stl") o.format = MeshFormat::stl;
    else if (format == "glb") o.format = MeshFormat::glb;
    else throw pyb::value_error("format '" + format + "' is not obj, ply, stl or glb");
    if (!zscale.is_none()) {
        o.zscale = zscale.cast<double>();
        if (!(o.zscale > 0)) throw pyb::value_error("zscale must be greater than 0");
    }
    std::string out;
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        st = export_mesh(m.model, o, &out);
    }
    if (!st) raise_status(st);
    return out;
}

void export_file(const Mesh& m, pyb::handle path, pyb::object format, pyb::object zscale) {
    const std::string name = path_text(path);
    std::string f = format.is_none() ? std::string() : format.cast<std::string>();
    if (f.empty()) {
        const auto dot = name.find_last_of('.');
        f = dot == std::string::npos ? std::string() : name.substr(dot + 1);
        for (char& c : f) c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    const std::string bytes = export_bytes(m, f, zscale);
    Status st;
    {
        pyb::gil_scoped_release unlocked;
        st = cli::write_file_atomic(name, bytes);
    }
    if (!st) raise_status(st, true);
}

}  // namespace

void bind_mesh(pyb::module_& m) {
    pyb::class_<Mesh>(m, "Mesh",
                      "A triangle mesh of an image, as erd.generate or erd.load makes it.\n\n"
                      "Basic model (methods ed, gpi; .model files): one value per vertex, continuous.\n"
                      "ERD model (erded, erdgpi; .erd files): vertices on the half-pixel lattice, one value per\n"
                      "face corner (wedge values), discontinuous across the constrained edges.\n"
                      "Every array property returns a new array.")
        .def_property_readonly("kind", [](const Mesh& s) { return s.model.kind == ModelKind::erd ? "erd" : "basic"; },
                               "'basic' or 'erd'.")
        .def_property_readonly("method", [](const Mesh& s) { return s.method.empty() ? pyb::object(pyb::none()) : pyb::object(pyb::str(s.method)); },
                               "The method that made the mesh ('ed', 'gpi', 'erded', 'erdgpi', 'gpr', 'gprfs', 'id', 'erdgpr'); None when loaded from a file.")
        .def_property_readonly("width", [](const Mesh& s) { return s.model.width; }, "Image width in pixels.")
        .def_property_readonly("height", [](const Mesh& s) { return s.model.height; }, "Image height in pixels.")
        .def_property_readonly("maxval", [](const Mesh& s) { return s.model.maxval; }, "Largest sample value of the image.")
        .def_property_readonly("stats", [](Mesh& s) {
            // Counting the constrained edges builds the mesh's adjacency: 2-3% of a generate call.
            if (!s.stats || s.stats.is_none()) s.stats = mesh_stats(s);
            return s.stats.attr("copy")();
        },
                               "The `erd generate --stats` fields as a dict: method, model, image, points, vertices, faces,\n"
                               "constrained_vertices, constrained_edges, dropped_constraints, other_kind_edges (ERD),\n"
                               "parameters (ERD: beta, r, l, epsilon, simple, edges), stop (greedy methods), stages (name, seconds).")
        .def_property_readonly("vertices", [](const Mesh& s) {
            return table<double>(s.model.vertices.size(), 2, [&](std::size_t i, std::size_t j) {
                const LatticePoint p = s.model.vertices[i];
                return 0.5 * double(j ? p.y : p.x);
            });
        }, "N x 2 float64: (x, y) in pixel units, x to the right, y down; ERD vertices may lie on half pixels.")
        .def_property_readonly("faces", [](const Mesh& s) {
            return table<std::int64_t>(s.model.faces.size(), 3, [&](std::size_t i, std::size_t j) { return std::int64_t(s.model.faces[i][j]); });
        }, "F x 3 int64: vertex indices of each triangle, counter-clockwise with y up (clockwise on screen).")
        .def_property_readonly("channels", [](const Mesh& s) { return s.model.channels; }, "1 (gray) or 3 (RGB).")
        .def_property_readonly("values", [](const Mesh& s) {
            const std::size_t C = std::size_t(s.model.channels);
            pyb::object t = table<double>(s.model.vertices.size(), C, [&](std::size_t i, std::size_t c) { return s.model.values[i * C + c]; });
            return C == 1 ? t.attr("reshape")(-1) : t;
        }, "N float64 (N x 3 for colour): the value at each vertex (ERD model: the mean of its wedge values).")
        .def_property_readonly("corner_values", [](const Mesh& s) {
            const bool erd = s.model.kind == ModelKind::erd;
            const std::size_t C = std::size_t(s.model.channels);
            pyb::object t = table<double>(s.model.faces.size() * 3, C, [&](std::size_t r, std::size_t c) {
                const std::size_t i = r / 3, j = r % 3;
                return erd ? s.model.corner_values[i * C + c][j] : s.model.values[std::size_t(s.model.faces[i][j]) * C + c];
            });
            return C == 1 ? t.attr("reshape")(-1, 3) : t.attr("reshape")(-1, 3, 3);
        }, "F x 3 float64 (F x 3 x 3 for colour: face, corner, channel): the value of face i at its corner j\n"
           "(ERD model: the wedge value; basic: the vertex value).")
        .def_property_readonly("constrained_edges", [](const Mesh& s) {
            return table<std::int64_t>(s.model.constraints.size(), 2, [&](std::size_t i, std::size_t j) { return std::int64_t(s.model.constraints[i][j]); });
        }, "E x 2 int64: vertex pairs (i < j) of the constrained edges (empty for a basic model). A mesh\n"
           "loaded from an .erd has those across which the corner values jump (what the file records).")
        .def("reconstruct", &reconstruct, pyb::arg("supersample") = pyb::none(),
             "reconstruct(supersample=None) -> numpy.ndarray\n\n"
             "The image the mesh stands for, H x W (H x W x 3 for colour), uint8 when maxval <= 255 else uint16. supersample=True\n"
             "takes the mean of 4x4 sub-samples at every pixel, False evaluates every pixel at its centre; None does\n"
             "what `erd reconstruct` does: 4x4 for a soft-edged ERD model, point evaluation for a hard-edged\n"
             "or basic one, and the pixels along edges_of_other_kind as their kind says.")
        .def_property_readonly("edge_kind", [](const Mesh& s) {
            return s.model.kind != ModelKind::erd ? pyb::object(pyb::none()) : pyb::object(pyb::str(s.model.edges == EdgeKind::hard ? "hard" : "soft"));
        }, "ERD model: 'soft' (pixels are 4x4 means) or 'hard' (pixels are the function at their centres), the kind of\n"
           "every edge but edges_of_other_kind; None for a basic model.")
        .def_property_readonly("edges_of_other_kind", [](const Mesh& s) {
            return table<std::int64_t>(s.model.kind_exceptions.size(), 2, [&](std::size_t i, std::size_t j) { return std::int64_t(s.model.kind_exceptions[i][j]); });
        }, "K x 2 int64: vertex pairs (i < j) of the edges whose kind is the other one than edge_kind (issue 44: each\n"
           "edge's kind chosen by fit); the pixels along them are evaluated as that kind says.")
        .def("save", &save, pyb::arg("path"),
             "save(path)\n\nWrites the mesh as `erd generate -o` does: a .model for a basic mesh, an .erd for an ERD one\n"
             "(byte-identical files), atomically. OSError when the file cannot be written.")
        .def("export", &export_file, pyb::arg("path"), pyb::arg("format") = pyb::none(), pyb::arg("zscale") = pyb::none(),
             "export(path, format=None, zscale=None)\n\n"
             "Writes the mesh as `erd export` does: Wavefront .obj, .ply, binary .stl or glTF 2.0 .glb (three.js,\n"
             "Cesium, Blender), the format from the name unless format= says; a mesh of a GeoTIFF in its world\n"
             "coordinates, holes over nodata open. zscale: height per value unit (default: erd export's).")
        .def("glb", [](const Mesh& m, pyb::object zscale) { return pyb::bytes(export_bytes(m, "glb", zscale)); },
             pyb::arg("zscale") = pyb::none(), "glb(zscale=None) -> bytes\n\nThe mesh as glTF 2.0 binary (.glb bytes), as export() writes it.")
        .def_property_readonly("real", [](const Mesh& s) { return s.model.real; },
                               "True for a mesh of a real-valued image (float, signed, with nodata): values in its units.")
        .def_property_readonly("value_range", [](const Mesh& s) {
            return s.model.real ? pyb::make_tuple(s.model.lo, s.model.hi) : pyb::make_tuple(0.0, double(s.model.maxval));
        }, "(lo, hi): a real mesh's image's range of valid values (its PSNR peak is hi - lo); (0, maxval) otherwise.")
        .def("__len__", [](const Mesh& s) { return s.model.vertices.size(); }, "Number of vertices.")
        .def("__repr__", [](const Mesh& s) {
            return "<erd.Mesh " + std::string(s.method.empty() ? (s.model.kind == ModelKind::erd ? "erd" : "basic") : s.method) +
                   " " + std::to_string(s.model.width) + "x" + std::to_string(s.model.height) + ", " +
                   std::to_string(s.model.vertices.size()) + " vertices, " + std::to_string(s.model.faces.size()) + " faces>";
        });
}

}  // namespace erd::py
