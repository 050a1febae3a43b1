// tapeline.grade: a pattern resized to a target measurement set, as `tapeline grade` does it.
#include "common.h"

#include <tapeline_python_docs.h>

#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/bench/grade_run.h>
#include <tapeline/grading/grading_json.h>
#include <tapeline/grading/output.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/validate.h>
#endif

#include <pybind11/stl.h>

#include <string>

namespace tapeline::python {

#ifdef TAPELINE_HAVE_GRADING
namespace {

namespace tg = tapeline::grading;

template <class T>
py::array_t<T> column(const std::vector<tg::ParetoPoint>& front, T tg::ParetoPoint::*field) {
    py::array_t<T> out(static_cast<py::ssize_t>(front.size()));
    for (std::size_t i = 0; i < front.size(); ++i) {
        out.mutable_data()[i] = front[i].*field;
    }
    return out;
}

py::tuple grade(const py::dict& pattern, const py::object& base, const py::object& target,
                bool freesewing_bindings, const tg::GradingOptions& options) {
    pattern::Pattern p = pattern::from_json(json_of(pattern, "pattern"), "pattern");
    pattern::require_valid(p);
    const sizes::MeasurementSet from = measurement_set_of(base, "base");
    const sizes::MeasurementSet to = measurement_set_of(target, "target");
    tg::GradeResult g;
    {
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        g = bench::grade_as_tool(std::move(p), from, to, options, freesewing_bindings);
    }
    py::dict report = to_python(tg::report_json(g.report)).cast<py::dict>();
    // The Pareto front as arrays, one entry per candidate (report["chosen"] indexes them).
    py::dict front;
    front["fit"] = column(g.report.front, &tg::ParetoPoint::fit);
    front["style"] = column(g.report.front, &tg::ParetoPoint::style);
    front["max_fit_error_mm"] = column(g.report.front, &tg::ParetoPoint::max_fit_error_mm);
    front["max_seam_mismatch_mm"] = column(g.report.front, &tg::ParetoPoint::max_seam_mismatch_mm);
    front["polished"] = column(g.report.front, &tg::ParetoPoint::polished);
    front["within_tolerance"] = column(g.report.front, &tg::ParetoPoint::within_tolerance);
    report["pareto"] = front;
    report["options"] = to_python(nlohmann::json(options));
    report["from"] = from.name;
    report["to"] = to.name;
    return py::make_tuple(to_python(pattern::to_json(g.pattern)), report);
}

}  // namespace

void bind_grading(py::module_& m) {
    py::enum_<tg::EaseMode>(m, "EaseMode")
        .value("proportional", tg::EaseMode::proportional)
        .value("keep_mm", tg::EaseMode::keep_mm)
        .def(py::init([](const std::string& s) {
            if (s == tg::to_string(tg::EaseMode::proportional)) {
                return tg::EaseMode::proportional;
            }
            if (s == tg::to_string(tg::EaseMode::keep_mm)) {
                return tg::EaseMode::keep_mm;
            }
            throw InvalidInput("ease '" + s + "': expected proportional or keep_mm");
        }));
    py::implicitly_convertible<std::string, tg::EaseMode>();
    py::class_<tg::GradingOptions>(m, "GradingOptions", cxx_doc("GradingOptions"))
        .def(py::init<>())
        .def_readwrite("seed", &tg::GradingOptions::seed, cxx_doc("GradingOptions.seed"))
        .def_readwrite("population", &tg::GradingOptions::population,
                       cxx_doc("GradingOptions.population"))
        .def_readwrite("generations", &tg::GradingOptions::generations,
                       cxx_doc("GradingOptions.generations"))
        .def_readwrite("ease", &tg::GradingOptions::ease, cxx_doc("GradingOptions.ease"))
        .def_readwrite("threads", &tg::GradingOptions::threads, cxx_doc("GradingOptions.threads"))
        .def_readwrite("ceres_polish", &tg::GradingOptions::ceres_polish,
                       cxx_doc("GradingOptions.ceres_polish"))
        .def_readwrite("ceres_iterations", &tg::GradingOptions::ceres_iterations,
                       cxx_doc("GradingOptions.ceres_iterations"))
        .def_readwrite("reference_length_mm", &tg::GradingOptions::reference_length_mm,
                       cxx_doc("GradingOptions.reference_length_mm"))
        .def_readwrite("neighbours", &tg::GradingOptions::neighbours,
                       cxx_doc("GradingOptions.neighbours"))
        .def_readwrite("min_fit_factor", &tg::GradingOptions::min_fit_factor,
                       cxx_doc("GradingOptions.min_fit_factor"))
        .def_readwrite("max_fit_factor", &tg::GradingOptions::max_fit_factor,
                       cxx_doc("GradingOptions.max_fit_factor"))
        .def_readwrite("split_girths", &tg::GradingOptions::split_girths,
                       cxx_doc("GradingOptions.split_girths"))
        .def_readwrite("trim_aspect", &tg::GradingOptions::trim_aspect,
                       cxx_doc("GradingOptions.trim_aspect"))
        .def_readwrite("max_target_ratio", &tg::GradingOptions::max_target_ratio,
                       cxx_doc("GradingOptions.max_target_ratio"))
        .def("to_dict", [](const tg::GradingOptions& o) { return to_python(nlohmann::json(o)); });
    m.def(
        "grade",
        [](const py::dict& pattern, const py::object& base, const py::object& target,
           bool freesewing_bindings, const py::kwargs& kw) {
            return grade(pattern, base, target, freesewing_bindings,
                         options_from<tg::GradingOptions>(kw, "grade"));
        },
        py::arg("pattern"), py::arg("base"), py::arg("target"),
        py::arg("freesewing_bindings") = true,
        "Grades a pattern dict from the base measurement set to the target one, as `tapeline "
        "grade` does. base, target: a measurement file path, a measurement JSON dict (what "
        "tapeline.measure returns) or a flat dict {name: mm}. Keyword arguments: the fields of "
        "GradingOptions (seed, population, generations, ease, ...). Returns (graded pattern "
        "dict, report dict: fit and seam tables, style metrics, the Pareto front as arrays under "
        "'pareto', 'chosen', timings, notes).");
}
#else
void bind_grading(py::module_&) {}
#endif

}  // namespace tapeline::python
