// tapeline.measure: landmarks, tape girths and skin lengths of a body mesh, as the measurement
// JSON `tapeline measure --out` writes (a dict here).
#include "common.h"

#include <tapeline/bench/measure_run.h>
#include <tapeline/measurement/measurement_json.h>
#include <tapeline/sizes/read_input.h>

#include <pybind11/stl.h>

#include <optional>
#include <string>

namespace tapeline::python {

namespace {

namespace tm = tapeline::measurement;

py::dict measure_arrays(const py::object& V, const py::object& F,
                        const std::optional<std::string>& units, const std::string& up,
                        const std::string& front, const std::string& pose,
                        const py::object& landmarks, const std::string& name, bool smooth_surface) {
    const tm::BodyOptions options =
        tm::parse_body_options(name, units.value_or(""), up, front, pose);
    tm::LandmarkOverrides overrides;
    if (!landmarks.is_none()) {
        // A dict in the landmark-override format ({"frame": ..., "landmarks": {...}}).
        overrides =
            tm::parse_landmark_overrides(json_of(landmarks, "landmarks").dump(), "landmarks");
    }
    const auto mesh = mesh_from_arrays(V, F, name);
    bench::MeasureRun run;
    {
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        tm::MeasureOptions measure;
        measure.smooth_surface = smooth_surface;
        run = bench::measure_mesh(mesh->loaded.mesh, options, overrides, true, measure);
    }
    const auto& r = run.result;
    nlohmann::ordered_json j = tm::body_measurements_json(name, r.frame, r.measurements,
                                                          r.landmarks, r.report, r.warnings);
    return to_python(j).cast<py::dict>();
}

}  // namespace

sizes::MeasurementSet measurement_set_of(const py::handle& h, const char* what) {
    if (py::isinstance<py::str>(h)) {
        return sizes::read_measurement_input(h.cast<std::string>());
    }
    if (!py::isinstance<py::dict>(h)) {
        throw py::value_error(std::string(what) +
                              ": expected a measurement file path or a dict of measurements");
    }
    return sizes::measurement_set_from_json(json_of(h, what), what);
}

void bind_measurement(py::module_& m) {
    const tm::BodyOptions defaults;
    m.def(
        "measure", &measure_arrays, py::arg("V"), py::arg("F"), py::arg("units") = py::none(),
        py::arg("up") = defaults.up.to_string(), py::arg("front") = defaults.front.to_string(),
        py::arg("pose") = std::string(tm::to_string(defaults.pose)),
        py::arg("landmarks") = py::none(), py::arg("name") = defaults.name,
        py::arg("smooth_surface") = tm::MeasureOptions{}.smooth_surface,
        "Measures the body mesh (V, F) as `tapeline measure` does: landmarks, tape girths and "
        "lengths along the skin. units: 'm', 'dm', 'cm' or 'mm' (None: inferred from the "
        "height); up, front: '+X' .. '-Z'; pose: 'A' or 'T'; landmarks: an override dict in "
        "the format of `tapeline measure --landmarks`; smooth_surface=False takes the girths round "
        "the flat facets (`tapeline measure --flat-facets`). Returns the measurement JSON as a "
        "dict: "
        "'measurements' (each with its ISO 8559-1 number, FreeSewing and Seamly2D names, value "
        "in mm and the tape loop or path), 'missing', 'landmarks', 'frame', 'report', "
        "'warnings'.");
}

}  // namespace tapeline::python
