// Shared by the binding translation units: numpy arrays to meshes and sources, results back to
// numpy arrays in the input's vertex order, JSON reports to Python dicts, and the GIL released
// around long work.
#pragma once

#include <tapeline/bench/methods.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/sizes/measurement_set.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include <array>
#include <csignal>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::python {

namespace py = pybind11;

using Mesh = bench::Mesh;
using Vertex = bench::Vertex;
using Sources = bench::Sources;
using Loaded = LoadedMesh<Mesh>;

/// While alive on the main thread: Ctrl-C (SIGINT) asks the library to stop at its next progress
/// point (tapeline::request_cancel; the call then raises KeyboardInterrupt). Python's own handler
/// cannot run while the GIL is released; it is put back afterwards.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    bool installed_ = false;
    struct sigaction previous_ {};
};

/// Python dict / list / scalar of a JSON value (objects keep their key order).
py::object to_python(const nlohmann::json& j);
py::object to_python(const nlohmann::ordered_json& j);
/// The JSON of a Python dict / list / scalar (through Python's json module); InvalidInput naming
/// `where` when it is not JSON.
nlohmann::json json_of(const py::handle& value, const std::string& where);

/// A float array of shape (n, d) (any floating dtype, any strides) as rows of doubles; ValueError
/// naming `what` on another dtype, shape or a non-finite value when `finite`.
std::vector<double> float_rows(const py::handle& array, const char* what, std::size_t& rows,
                               std::size_t& dim, std::size_t want_dim = 0);

/// A mesh given as arrays: the validated, repaired mesh and the input's faces (for points given
/// as (face, barycentric coordinates) of the input).
struct ArrayMesh {
    Loaded loaded;
    std::vector<std::array<std::size_t, 3>> faces;
    double build_seconds = 0;  ///< triangle_mesh_from_soup (the C++ loader's own work)
};

/// The triangle mesh of V (float, (n, 3)) and F (integer, (m, 3)), validated and repaired as
/// read_triangle_mesh does (triangle_mesh_from_soup); `name` appears in messages.
std::shared_ptr<const ArrayMesh> mesh_from_arrays(const py::handle& V, const py::handle& F,
                                                  const std::string& name, bool strict = false);

/// The loader's report as a dict (the counts of MeshReport, its warnings and summary()).
py::dict report_dict(const MeshReport& r);

/// Sources given as an input vertex index, a sequence of them, or (face, (b0, b1, b2)) points of
/// the input's faces; `what` names the argument in messages.
Sources sources_from(const py::handle& sources, const ArrayMesh& mesh, const char* what);

/// One surface point (vertex index or (face, (b0, b1, b2))).
geodesic::SurfacePoint<Mesh> surface_point(const py::handle& point, const ArrayMesh& mesh,
                                           const char* what);

/// Values per mesh vertex as a numpy array over the input's vertices (+inf for unused ones).
py::array_t<double> input_order(const Loaded& mesh, const std::vector<double>& per_mesh_vertex);

/// A polyline as an (n, 3) float64 array.
template <class PointRange>
py::array_t<double> points_array(const PointRange& points) {
    py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
    auto w = out.mutable_unchecked<2>();
    py::ssize_t i = 0;
    for (const auto& p : points) {
        w(i, 0) = p.x();
        w(i, 1) = p.y();
        w(i, 2) = p.z();
        ++i;
    }
    return out;
}

/// Raises the error for an option value of the wrong type: ValueError naming the accepted names
/// for an enum field given an unknown name, TypeError naming the expected type otherwise.
[[noreturn]] void bad_option_value(const char* function, const std::string& key,
                                   const py::object& current, const py::handle& given);

/// Sets the fields of an options object bound with def_readwrite (a copy of `start`) from keyword
/// arguments; TypeError naming the function and the keyword for one the options do not have.
template <class Options>
Options options_from(const py::kwargs& kwargs, const char* function,
                     const Options& start = Options{}) {
    py::object o = py::cast(start);
    for (const auto& item : kwargs) {
        const std::string key = py::str(item.first);
        if (key.empty() || key[0] == '_' || !py::hasattr(o, key.c_str())) {
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                                 key + "'");
        }
        try {
            o.attr(key.c_str()) = item.second;
        } catch (py::error_already_set& e) {
            if (!e.matches(PyExc_TypeError)) {
                throw;
            }
            bad_option_value(function, key, o.attr(key.c_str()), item.second);
        }
    }
    return o.cast<Options>();
}

/// A measurement set given as a file path (any form `tapeline grade --from` reads), a measurement
/// JSON dict (what tapeline.measure returns) or a flat dict {name: millimetres}; `what` names the
/// argument in messages.
sizes::MeasurementSet measurement_set_of(const py::handle& h, const char* what);

void bind_geodesic(py::module_& m);
void bind_measurement(py::module_& m);
void bind_pattern(py::module_& m);
void bind_grading(py::module_& m);
void bind_garment(py::module_& m);

}  // namespace tapeline::python
