// The extension module `tapeline._tapeline`: exceptions, mesh reading and the array conversions
// every binding shares. The package `tapeline` (python/tapeline/) re-exports it.
#include "common.h"

#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/progress.h>

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <sstream>

namespace tapeline::python {

namespace {

template <class Json>
py::object json_to_python(const Json& j) {
    switch (j.type()) {
        case nlohmann::json::value_t::null:
            return py::none();
        case nlohmann::json::value_t::boolean:
            return py::bool_(j.template get<bool>());
        case nlohmann::json::value_t::number_integer:
            return py::int_(j.template get<std::int64_t>());
        case nlohmann::json::value_t::number_unsigned:
            return py::int_(j.template get<std::uint64_t>());
        case nlohmann::json::value_t::number_float:
            return py::float_(j.template get<double>());
        case nlohmann::json::value_t::string:
            return py::str(j.template get_ref<const std::string&>());
        case nlohmann::json::value_t::array: {
            py::list out;
            for (const auto& e : j) {
                out.append(json_to_python(e));
            }
            return std::move(out);
        }
        case nlohmann::json::value_t::object: {
            py::dict out;
            for (auto it = j.begin(); it != j.end(); ++it) {
                out[py::str(it.key())] = json_to_python(it.value());
            }
            return std::move(out);
        }
        default:
            return py::none();
    }
}

std::string shape_of(const py::array& a) {
    std::ostringstream s;
    s << a.dtype().attr("name").cast<std::string>() << " array of shape (";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) {
        s << (k ? ", " : "") << a.shape(k);
    }
    s << (a.ndim() == 1 ? ",)" : ")");
    return s.str();
}

py::array as_array(const py::handle& h, const char* what, const char* expected) {
    if (!py::isinstance<py::array>(h)) {
        // Lists of numbers are taken; anything numpy cannot make an array of is refused.
        try {
            return py::array(py::module_::import("numpy").attr("asarray")(h));
        } catch (const py::error_already_set&) {
            throw py::value_error(std::string(what) + ": expected " + expected + ", got " +
                                  py::str(py::type::of(h)).cast<std::string>());
        }
    }
    return py::reinterpret_borrow<py::array>(h);
}

std::vector<std::vector<std::size_t>> triangle_rows(const py::handle& F, const char* what) {
    const py::array a = as_array(F, what, "an integer array of shape (m, 3)");
    const char kind = a.dtype().kind();
    if ((kind != 'i' && kind != 'u') || a.ndim() != 2 || a.shape(1) != 3) {
        throw py::value_error(std::string(what) + ": expected an integer array of shape (m, 3), " +
                              "got " + shape_of(a));
    }
    const auto f = py::array_t<std::int64_t, py::array::forcecast>(a);
    const auto r = f.unchecked<2>();
    std::vector<std::vector<std::size_t>> rows;
    rows.reserve(static_cast<std::size_t>(r.shape(0)));
    for (py::ssize_t i = 0; i < r.shape(0); ++i) {
        for (py::ssize_t k = 0; k < 3; ++k) {
            if (r(i, k) < 0) {
                throw py::value_error(std::string(what) + ": face " + std::to_string(i) +
                                      " has a negative vertex index " + std::to_string(r(i, k)));
            }
        }
        // One allocation per face (the soup's face type).
        rows.push_back({static_cast<std::size_t>(r(i, 0)), static_cast<std::size_t>(r(i, 1)),
                        static_cast<std::size_t>(r(i, 2))});
    }
    return rows;
}

/// V and F of the loaded mesh; a face that comes from a triangle of `input_faces` starts at the
/// same corner as that triangle (PMP's corner order otherwise).
py::tuple mesh_arrays(const Loaded& loaded,
                      const std::vector<std::vector<std::size_t>>& input_faces) {
    const Mesh& mesh = loaded.mesh;
    py::array_t<double> V({static_cast<py::ssize_t>(num_vertices(mesh)), py::ssize_t{3}});
    auto v = V.mutable_unchecked<2>();
    for (Vertex x : vertices(mesh)) {
        const auto& p = mesh.point(x);
        const auto i = static_cast<py::ssize_t>(x.idx());
        v(i, 0) = p.x();
        v(i, 1) = p.y();
        v(i, 2) = p.z();
    }
    py::array_t<std::int64_t> F({static_cast<py::ssize_t>(num_faces(mesh)), py::ssize_t{3}});
    auto f = F.mutable_unchecked<2>();
    for (auto face : faces(mesh)) {
        // In PMP's corner order (source, target, next target of halfedge(face)): the order of
        // barycentric coordinates of (face, (b0, b1, b2)) points.
        const auto h = halfedge(face, mesh);
        const auto row = static_cast<py::ssize_t>(face.idx());
        const std::array<Vertex, 3> c{source(h, mesh), target(h, mesh),
                                      target(next(h, mesh), mesh)};
        std::size_t first = 0;
        const std::size_t in = loaded.face_input_index[static_cast<std::size_t>(face.idx())];
        if (in < input_faces.size() && input_faces[in].size() == 3) {
            const auto copies = loaded.mesh_vertices_of(input_faces[in][0]);
            for (std::size_t k = 0; k < 3; ++k) {
                if (std::find(copies.begin(), copies.end(), c[k]) != copies.end()) {
                    first = k;
                }
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {
            f(row, static_cast<py::ssize_t>(k)) =
                static_cast<std::int64_t>(c[(first + k) % 3].idx());
        }
    }
    return py::make_tuple(V, F);
}

}  // namespace

py::dict report_dict(const MeshReport& r) {
    py::dict d;
    d["file"] = r.file;
    d["format"] = r.format;
    const std::pair<const char*, std::size_t> counts[] = {
        {"input_vertices", r.input_vertices},
        {"input_faces", r.input_faces},
        {"vertices", r.vertices},
        {"faces", r.faces},
        {"polygons_triangulated", r.polygons_triangulated},
        {"duplicate_vertices_merged", r.duplicate_vertices_merged},
        {"unreferenced_vertices", r.unreferenced_vertices},
        {"degenerate_faces", r.degenerate_faces},
        {"needle_faces", r.needle_faces},
        {"non_manifold_edges", r.non_manifold_edges},
        {"non_manifold_vertices", r.non_manifold_vertices},
        {"vertices_split", r.vertices_split},
        {"boundary_loops", r.boundary_loops},
        {"components", r.components},
        {"collapsed_faces_dropped", r.collapsed_faces_dropped},
        {"duplicate_faces_dropped", r.duplicate_faces_dropped},
        {"faces_reoriented", r.faces_reoriented},
    };
    for (const auto& [key, n] : counts) {
        d[key] = n;
    }
    d["warnings"] = r.warnings;
    d["summary"] = r.summary();
    return d;
}

namespace {
extern "C" void on_interrupt(int) {
    tapeline::request_cancel();
}
}  // namespace

InterruptGuard::InterruptGuard() {
    // Signal handlers are the main thread's business in Python.
    if (PyGILState_Check() && py::module_::import("threading")
                                  .attr("current_thread")()
                                  .is(py::module_::import("threading").attr("main_thread")())) {
        tapeline::clear_cancel();
        struct sigaction action {};
        action.sa_handler = on_interrupt;
        sigemptyset(&action.sa_mask);
        installed_ = sigaction(SIGINT, &action, &previous_) == 0;
    }
}

InterruptGuard::~InterruptGuard() {
    if (installed_) {
        sigaction(SIGINT, &previous_, nullptr);
        // Ctrl-C during work that had no progress point left (or none at all): handed to Python,
        // which raises KeyboardInterrupt at its next check. Not when Cancelled is on its way out:
        // that becomes the KeyboardInterrupt itself.
        if (tapeline::internal::cancel_flag().load() && std::uncaught_exceptions() == 0) {
            PyErr_SetInterrupt();
        }
        tapeline::clear_cancel();
    }
}

void bad_option_value(const char* function, const std::string& key, const py::object& current,
                      const py::handle& given) {
    const py::object type = py::type::of(current);
    const std::string what = std::string(function) + "(): " + key + "=" +
                             py::repr(given).cast<std::string>() + ": expected ";
    if (py::hasattr(type, "__members__") && py::isinstance<py::str>(given)) {
        std::string names;
        for (const auto& m : type.attr("__members__").cast<py::dict>()) {
            names += (names.empty() ? "" : ", ") + py::str(m.first).cast<std::string>();
        }
        throw py::value_error(what + "one of " + names);
    }
    throw py::type_error(what + type.attr("__name__").cast<std::string>());
}

py::object to_python(const nlohmann::json& j) {
    return json_to_python(j);
}
py::object to_python(const nlohmann::ordered_json& j) {
    return json_to_python(j);
}

nlohmann::json json_of(const py::handle& value, const std::string& where) {
    const std::string text = py::module_::import("json").attr("dumps")(value).cast<std::string>();
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InvalidInput(where + ": not JSON: " + e.what());
    }
}

std::vector<double> float_rows(const py::handle& array, const char* what, std::size_t& rows,
                               std::size_t& dim, std::size_t want_dim) {
    const std::string expected =
        want_dim ? "a float array of shape (n, " + std::to_string(want_dim) + ")"
                 : std::string("a float array of shape (n, d)");
    const py::array a = as_array(array, what, expected.c_str());
    if (a.dtype().kind() != 'f' || a.ndim() != 2 || a.shape(1) < 1 ||
        (want_dim && a.shape(1) != static_cast<py::ssize_t>(want_dim))) {
        throw py::value_error(std::string(what) + ": expected " + expected + ", got " +
                              shape_of(a));
    }
    const auto d = py::array_t<double, py::array::forcecast>(a);
    const auto r = d.unchecked<2>();
    rows = static_cast<std::size_t>(r.shape(0));
    dim = static_cast<std::size_t>(r.shape(1));
    std::vector<double> out;
    out.reserve(rows * dim);
    for (py::ssize_t i = 0; i < r.shape(0); ++i) {
        for (py::ssize_t k = 0; k < r.shape(1); ++k) {
            out.push_back(r(i, k));
        }
    }
    return out;
}

std::shared_ptr<const ArrayMesh> mesh_from_arrays(const py::handle& V, const py::handle& F,
                                                  const std::string& name, bool strict) {
    std::size_t n = 0, dim = 0;
    std::vector<double> xyz = float_rows(V, "V", n, dim, 3);
    std::vector<std::array<double, 3>> points(n);
    static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double));
    std::memcpy(points.data(), xyz.data(), 3 * n * sizeof(double));  // same layout, rows of 3
    xyz = {};
    const auto rows = triangle_rows(F, "F");
    auto out = std::make_shared<ArrayMesh>();
    out->faces.reserve(rows.size());
    for (const auto& r : rows) {
        out->faces.push_back({r[0], r[1], r[2]});
    }
    MeshLoadOptions options;
    options.strict = strict;
    InterruptGuard interrupt_guard;
    py::gil_scoped_release release;
    const auto t0 = std::chrono::steady_clock::now();
    out->loaded = triangle_mesh_from_soup<Mesh>(points, rows, name, options);
    out->build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

namespace {

bool is_index(const py::handle& h) {
    return !py::isinstance<py::float_>(h) && PyIndex_Check(h.ptr()) != 0;
}

}  // namespace

geodesic::SurfacePoint<Mesh> surface_point(const py::handle& point, const ArrayMesh& mesh,
                                           const char* what) {
    const std::string where = std::string(what) + ": ";
    const Loaded& loaded = mesh.loaded;
    if (is_index(point)) {
        const long long i = point.cast<long long>();
        if (i < 0) {
            throw py::value_error(where + "vertex " + std::to_string(i) +
                                  ": vertex indices start at 0");
        }
        const auto copies = loaded.mesh_vertices_of(static_cast<std::size_t>(i));
        if (copies.empty()) {
            throw py::value_error(where + "vertex " + std::to_string(i) +
                                  " is not used by any face");
        }
        return copies.front();
    }
    // (face, (b0, b1, b2)): a point of input face `face`, barycentric over its corners F[face].
    if (!py::isinstance<py::sequence>(point) || py::isinstance<py::str>(point) ||
        py::len(point) != 2) {
        throw py::value_error(where + "expected a vertex index or (face, (b0, b1, b2)), got " +
                              py::repr(point).cast<std::string>());
    }
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    long long face = -1;
    std::array<double, 3> bary{};
    try {
        if (!is_index(pair[0])) {
            throw py::cast_error();
        }
        face = pair[0].cast<long long>();
        const py::sequence b = pair[1].cast<py::sequence>();
        if (py::len(b) != 3) {
            throw py::cast_error();
        }
        for (std::size_t k = 0; k < 3; ++k) {
            bary[k] = b[k].cast<double>();
        }
    } catch (const py::cast_error&) {
        throw py::value_error(where + "expected (face, (b0, b1, b2)), got " +
                              py::repr(point).cast<std::string>());
    }
    const std::size_t input_faces = mesh.faces.size();
    if (face < 0 || static_cast<std::size_t>(face) >= input_faces) {
        throw py::value_error(where + "face " + std::to_string(face) +
                              " does not exist (the input has " + std::to_string(input_faces) +
                              " faces)");
    }
    const double sum = bary[0] + bary[1] + bary[2];
    if (!std::isfinite(sum) || std::abs(sum - 1.0) > 1e-6 ||
        *std::min_element(bary.begin(), bary.end()) < -1e-12) {
        throw py::value_error(where + "barycentric coordinates must be >= 0 and sum to 1");
    }
    // The mesh face built from input face `face` (the loader may have reoriented it), with the
    // coordinates reordered to its corners.
    const auto k = std::find(loaded.face_input_index.begin(), loaded.face_input_index.end(),
                             static_cast<std::size_t>(face));
    if (k == loaded.face_input_index.end()) {
        throw py::value_error(where + "face " + std::to_string(face) +
                              " was dropped by the loader (see check_mesh)");
    }
    const auto f = loaded.faces[static_cast<std::size_t>(k - loaded.face_input_index.begin())];
    const auto& corners = mesh.faces[static_cast<std::size_t>(face)];
    std::array<double, 3> on_mesh{};
    std::size_t i = 0;
    // PMP's order of the coordinates: source, target and next target of halfedge(f).
    const auto h = halfedge(f, loaded.mesh);
    for (Vertex v : {source(h, loaded.mesh), target(h, loaded.mesh),
                     target(next(h, loaded.mesh), loaded.mesh)}) {
        bool found = false;
        for (std::size_t j = 0; j < 3 && !found; ++j) {
            const auto copies = loaded.mesh_vertices_of(corners[j]);
            if (std::find(copies.begin(), copies.end(), v) != copies.end()) {
                on_mesh[i] = bary[j];
                found = true;
            }
        }
        if (!found) {
            throw py::value_error(where + "face " + std::to_string(face) +
                                  " was rebuilt by the loader from other corners");
        }
        ++i;
    }
    return geodesic::FaceLocation<Mesh>(f, on_mesh);
}

Sources sources_from(const py::handle& sources, const ArrayMesh& mesh, const char* what) {
    Sources out;
    auto add = [&](const py::handle& p) {
        const auto s = surface_point(p, mesh, what);
        if (std::holds_alternative<Vertex>(s)) {
            // Every copy of the input vertex (the loader splits non-manifold vertices).
            const long long i = p.cast<long long>();
            for (Vertex c : mesh.loaded.mesh_vertices_of(static_cast<std::size_t>(i))) {
                out.vertices.push_back(c);
            }
        } else {
            out.locations.push_back(std::get<geodesic::FaceLocation<Mesh>>(s));
        }
    };
    if (is_index(sources)) {
        add(sources);
    } else if ((py::isinstance<py::sequence>(sources) && !py::isinstance<py::str>(sources)) ||
               py::isinstance<py::array>(sources)) {
        for (const py::handle& p : sources) {
            add(p);
        }
    } else {
        throw py::value_error(std::string(what) +
                              ": expected a vertex index, a sequence of them or of (face, (b0, "
                              "b1, b2)) points, got " +
                              py::repr(sources).cast<std::string>());
    }
    if (out.vertices.empty() && out.locations.empty()) {
        throw py::value_error(std::string(what) + ": no source given");
    }
    return out;
}

py::array_t<double> input_order(const Loaded& mesh, const std::vector<double>& per_mesh_vertex) {
    const std::vector<double> in = mesh.to_input_order(per_mesh_vertex);
    py::array_t<double> out(static_cast<py::ssize_t>(in.size()));
    std::copy(in.begin(), in.end(), out.mutable_data());
    return out;
}

}  // namespace tapeline::python

namespace py = pybind11;

PYBIND11_MODULE(_tapeline, m) {
    namespace tp = tapeline::python;
    m.doc() = "Tapeline: geodesics and body measurement on triangle meshes, numpy in and out.";
    // Error types: the library's one-line messages, under Python's usual base classes.
    py::register_exception<tapeline::InvalidInput>(m, "InvalidInput", PyExc_ValueError);
    py::register_exception<tapeline::TopologyError>(m, "TopologyError", PyExc_ValueError);
    py::register_exception<tapeline::SolverFailure>(m, "SolverFailure", PyExc_RuntimeError);
    // Work stopped by Ctrl-C (InterruptGuard) ends as Python's KeyboardInterrupt.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const tapeline::Cancelled& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        }
    });

    m.def(
        "read_mesh",
        [](const std::string& path, bool strict, double needle_angle_degrees) {
            tapeline::MeshLoadOptions options;
            options.strict = strict;
            options.needle_angle_degrees = needle_angle_degrees;
            tp::Loaded loaded;
            tapeline::PolygonSoup soup;
            {
                tp::InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                soup = tapeline::read_polygon_soup(path);
                loaded = tapeline::triangle_mesh_from_soup<tp::Mesh>(soup.points, soup.faces, path,
                                                                     options);
                loaded.report.format = soup.format;
            }
            py::tuple va = tp::mesh_arrays(loaded, soup.faces);
            return py::make_tuple(va[0], va[1], tp::report_dict(loaded.report));
        },
        py::arg("path"), py::arg("strict") = tapeline::MeshLoadOptions{}.strict,
        py::arg("needle_angle_degrees") = tapeline::MeshLoadOptions{}.needle_angle_degrees,
        "Reads a triangle mesh (.off, .obj, .ply, .stl), validates and repairs it as the C++ "
        "read_triangle_mesh does; returns (V, F, report): V float64 (n, 3), F int64 (m, 3) of the "
        "repaired mesh, report a dict (counts of repairs, warnings, summary). strict: refuse "
        "(TopologyError) instead of repairing.");
    m.def(
        "check_mesh",
        [](const py::object& V, const py::object& F, bool strict) {
            return tp::report_dict(tp::mesh_from_arrays(V, F, "arrays", strict)->loaded.report);
        },
        py::arg("V"), py::arg("F"), py::arg("strict") = false,
        "What the loader finds in the mesh (V, F) and would repair: the report dict of read_mesh.");
    tp::bind_geodesic(m);
    tp::bind_measurement(m);
    tp::bind_pattern(m);
    tp::bind_grading(m);
    tp::bind_garment(m);
}
