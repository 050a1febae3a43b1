// tapeline.garment: a body dressed in a pattern as `tapeline dress` dresses it (placement, sewing
// along geodesic strings, the drape and its quality gates), and the fabric library.
#include "common.h"

#include <tapeline_python_docs.h>

#include <tapeline/bench/dress_run.h>
#include <tapeline/core/errors.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/validate.h>

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace tapeline::python {

namespace {

namespace tgm = tapeline::garment;
namespace tm = tapeline::measurement;

/// A fabric given as a library name, a .json fabric file or a fabric dict (the JSON of
/// `tapeline fabric show`).
tgm::Fabric fabric_of(const py::handle& h) {
    if (py::isinstance<py::str>(h)) {
        return tgm::fabric_record_from(h.cast<std::string>());
    }
    if (py::isinstance<py::dict>(h)) {
        return tgm::fabric_from_json(json_of(h, "fabric"), "fabric");
    }
    throw py::value_error("fabric: expected a library name, a .json fabric file or a fabric dict");
}

template <class T>
py::array_t<T> array_of(const T* data, std::size_t rows, std::size_t cols) {
    py::array_t<T> out(cols == 0 ? std::vector<py::ssize_t>{py::ssize_t(rows)}
                                 : std::vector<py::ssize_t>{py::ssize_t(rows), py::ssize_t(cols)});
    std::copy(data, data + rows * (cols == 0 ? 1 : cols), out.mutable_data());
    return out;
}

py::dict dress_arrays(const py::object& V, const py::object& F, const py::dict& pattern,
                      const std::optional<std::string>& units, const std::string& up,
                      const std::string& front, const std::string& name, const py::object& fabric,
                      const py::object& base, std::uint32_t seed, bool strict,
                      tgm::DressOptions options) {
    const tm::BodyOptions body = tm::parse_body_options(name, units.value_or(""), up, front,
                                                        tm::to_string(tm::BodyOptions{}.pose));
    options.fabric = fabric_of(fabric).params;
    pattern::Pattern p = pattern::from_json(json_of(pattern, "pattern"), "pattern");
    pattern::require_valid(p);
    std::optional<sizes::MeasurementSet> from;
    if (!base.is_none()) {
        from = measurement_set_of(base, "base");
    }
    const std::string pattern_name = p.name;
    const auto mesh = mesh_from_arrays(V, F, name);
    bench::DressRun run;
    {
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        run = bench::dress_mesh(mesh->loaded.mesh, body, std::move(p), options,
                                from ? &*from : nullptr, seed);
    }
    const std::string failed = bench::failed_gates(run.report);
    if (strict && !failed.empty()) {
        throw SolverFailure(name +
                            ": the drape failed its quality gates with strict=True: " + failed);
    }
    // The garment in the body's own coordinates and unit (as `tapeline dress --out` writes it).
    const tgm::GarmentMesh& g = run.garment;
    const tm::BodyFrame& frame = run.body.frame;
    std::vector<double> xyz;
    xyz.reserve(3 * g.positions.size());
    for (const tgm::Vec3& q : g.positions) {
        const tgm::Vec3 p_in = frame.to_input(q);
        xyz.insert(xyz.end(), p_in.begin(), p_in.end());
    }
    std::vector<std::int64_t> tri;
    std::vector<double> uv;
    tri.reserve(3 * g.triangles.size());
    uv.reserve(6 * g.triangles.size());
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            tri.push_back(g.triangles[f][k]);
            uv.push_back(g.uv[f][k][0]);
            uv.push_back(g.uv[f][k][1]);
        }
    }
    std::vector<std::int64_t> piece(g.triangle_piece.begin(), g.triangle_piece.end());
    py::dict out;
    out["V"] = array_of(xyz.data(), g.positions.size(), 3);
    out["F"] = array_of(tri.data(), g.triangles.size(), 3);
    py::array_t<double> uv_array({py::ssize_t(g.triangles.size()), py::ssize_t{3}, py::ssize_t{2}});
    std::copy(uv.begin(), uv.end(), uv_array.mutable_data());
    out["uv"] = uv_array;
    out["piece"] = array_of(piece.data(), piece.size(), 0);
    out["piece_names"] = g.piece_names;
    out["stretch"] = array_of(run.stretch.data(), run.stretch.size(), 0);
    out["report"] = to_python(bench::dress_report_json(run, name, pattern_name, options));
    out["warnings"] = run.warnings;
    out["grading_notes"] = run.grading_notes;
    return out;
}

/// A kwargs constructor for an options class bound with def_readwrite.
template <class Options>
Options options_init(const py::kwargs& kw, const char* name) {
    return options_from<Options>(kw, name);
}

}  // namespace

void bind_garment(py::module_& parent) {
    py::module_ m = parent.def_submodule(
        "garment",
        "A body dressed in a pattern: the pieces placed around it, sewn along geodesic strings, "
        "draped by the cloth solver, with quality gates; the fabric library.");
    py::class_<tgm::PlacementOptions>(m, "PlacementOptions", cxx_doc("PlacementOptions"))
        .def(py::init([](const py::kwargs& kw) {
            return options_init<tgm::PlacementOptions>(kw, "PlacementOptions");
        }))
        .def_readwrite("gap_mm", &tgm::PlacementOptions::gap_mm, cxx_doc("PlacementOptions.gap_mm"))
        .def_readwrite("slice_mm", &tgm::PlacementOptions::slice_mm,
                       cxx_doc("PlacementOptions.slice_mm"))
        .def_readwrite("layer_gap_mm", &tgm::PlacementOptions::layer_gap_mm,
                       cxx_doc("PlacementOptions.layer_gap_mm"));
    py::class_<tgm::SewingOptions>(m, "SewingOptions", cxx_doc("SewingOptions"))
        .def(py::init([](const py::kwargs& kw) {
            return options_init<tgm::SewingOptions>(kw, "SewingOptions");
        }))
        .def_readwrite("sew_seconds", &tgm::SewingOptions::sew_seconds,
                       cxx_doc("SewingOptions.sew_seconds"))
        .def_readwrite("settle_seconds", &tgm::SewingOptions::settle_seconds,
                       cxx_doc("SewingOptions.settle_seconds"))
        .def_readwrite("max_extra_seconds", &tgm::SewingOptions::max_extra_seconds,
                       cxx_doc("SewingOptions.max_extra_seconds"))
        .def_readwrite("settle_damping_per_second", &tgm::SewingOptions::settle_damping_per_second,
                       cxx_doc("SewingOptions.settle_damping_per_second"))
        .def_readwrite("string_offset_mm", &tgm::SewingOptions::string_offset_mm,
                       cxx_doc("SewingOptions.string_offset_mm"))
        .def_readwrite("compliance", &tgm::SewingOptions::compliance,
                       cxx_doc("SewingOptions.compliance"))
        .def_readwrite("length_mismatch", &tgm::SewingOptions::length_mismatch,
                       cxx_doc("SewingOptions.length_mismatch"))
        .def_readwrite("weld_within_mm", &tgm::SewingOptions::weld_within_mm,
                       cxx_doc("SewingOptions.weld_within_mm"));
    py::class_<tgm::DrapeOptions>(m, "DrapeOptions", cxx_doc("DrapeOptions"))
        .def(py::init([](const py::kwargs& kw) {
            return options_init<tgm::DrapeOptions>(kw, "DrapeOptions");
        }))
        .def_readwrite("frame_seconds", &tgm::DrapeOptions::frame_seconds,
                       cxx_doc("DrapeOptions.frame_seconds"))
        .def_readwrite("substeps", &tgm::DrapeOptions::substeps, cxx_doc("DrapeOptions.substeps"))
        .def_readwrite("iterations", &tgm::DrapeOptions::iterations,
                       cxx_doc("DrapeOptions.iterations"))
        .def_readwrite("gravity", &tgm::DrapeOptions::gravity, cxx_doc("DrapeOptions.gravity"))
        .def_readwrite("damping_per_second", &tgm::DrapeOptions::damping_per_second,
                       cxx_doc("DrapeOptions.damping_per_second"))
        .def_readwrite("body_clearance_mm", &tgm::DrapeOptions::body_clearance_mm,
                       cxx_doc("DrapeOptions.body_clearance_mm"))
        .def_readwrite("self_collision", &tgm::DrapeOptions::self_collision,
                       cxx_doc("DrapeOptions.self_collision"))
        .def_readwrite("edge_edge_collision", &tgm::DrapeOptions::edge_edge_collision,
                       cxx_doc("DrapeOptions.edge_edge_collision"))
        .def_readwrite("untangle", &tgm::DrapeOptions::untangle, cxx_doc("DrapeOptions.untangle"))
        .def_readwrite("tether_stretch", &tgm::DrapeOptions::tether_stretch,
                       cxx_doc("DrapeOptions.tether_stretch"))
        .def_readwrite("threads", &tgm::DrapeOptions::threads, cxx_doc("DrapeOptions.threads"))
        .def_readwrite("max_speed_mm_s", &tgm::DrapeOptions::max_speed_mm_s,
                       cxx_doc("DrapeOptions.max_speed_mm_s"))
        .def_readwrite("max_energy_growth", &tgm::DrapeOptions::max_energy_growth,
                       cxx_doc("DrapeOptions.max_energy_growth"));
    py::class_<tgm::RelaxOptions>(m, "RelaxOptions", cxx_doc("RelaxOptions"))
        .def(py::init([](const py::kwargs& kw) {
            return options_init<tgm::RelaxOptions>(kw, "RelaxOptions");
        }))
        .def_readwrite("max_iterations", &tgm::RelaxOptions::max_iterations,
                       cxx_doc("RelaxOptions.max_iterations"))
        .def_readwrite("friction_from_iteration", &tgm::RelaxOptions::friction_from_iteration,
                       cxx_doc("RelaxOptions.friction_from_iteration"))
        .def_readwrite("release_until_iteration", &tgm::RelaxOptions::release_until_iteration,
                       cxx_doc("RelaxOptions.release_until_iteration"))
        .def_readwrite("tolerance_mm", &tgm::RelaxOptions::tolerance_mm,
                       cxx_doc("RelaxOptions.tolerance_mm"))
        .def_readwrite("initial_step_seconds", &tgm::RelaxOptions::initial_step_seconds,
                       cxx_doc("RelaxOptions.initial_step_seconds"))
        .def_readwrite("settle_iterations", &tgm::RelaxOptions::settle_iterations,
                       cxx_doc("RelaxOptions.settle_iterations"))
        .def_readwrite("settle_fraction", &tgm::RelaxOptions::settle_fraction,
                       cxx_doc("RelaxOptions.settle_fraction"))
        .def_readwrite("stall_rejections", &tgm::RelaxOptions::stall_rejections,
                       cxx_doc("RelaxOptions.stall_rejections"));
    py::class_<tgm::FoldOptions>(m, "FoldOptions", cxx_doc("FoldOptions"))
        .def(py::init(
            [](const py::kwargs& kw) { return options_init<tgm::FoldOptions>(kw, "FoldOptions"); }))
        .def_readwrite("max_rounds", &tgm::FoldOptions::max_rounds,
                       cxx_doc("FoldOptions.max_rounds"))
        .def_readwrite("rings", &tgm::FoldOptions::rings, cxx_doc("FoldOptions.rings"))
        .def_readwrite("sweeps", &tgm::FoldOptions::sweeps, cxx_doc("FoldOptions.sweeps"));
    py::class_<tgm::DressOptions>(m, "DressOptions", cxx_doc("DressOptions"))
        .def(py::init([](const py::kwargs& kw) {
            return options_init<tgm::DressOptions>(kw, "DressOptions");
        }))
        .def_readwrite("resolution_mm", &tgm::DressOptions::resolution_mm,
                       cxx_doc("DressOptions.resolution_mm"))
        .def_readwrite("placement", &tgm::DressOptions::placement,
                       cxx_doc("DressOptions.placement"))
        .def_readwrite("sewing", &tgm::DressOptions::sewing, cxx_doc("DressOptions.sewing"))
        .def_readwrite("drape", &tgm::DressOptions::drape, cxx_doc("DressOptions.drape"))
        .def_readwrite("without_pieces", &tgm::DressOptions::without_pieces,
                       cxx_doc("DressOptions.without_pieces"))
        .def_readwrite("relax", &tgm::DressOptions::relax, cxx_doc("DressOptions.relax"))
        .def_readwrite("relax_options", &tgm::DressOptions::relax_options,
                       cxx_doc("DressOptions.relax_options"))
        .def_readwrite("relax_again_options", &tgm::DressOptions::relax_again_options,
                       cxx_doc("DressOptions.relax_again_options"))
        .def_readwrite("body_points", &tgm::DressOptions::body_points,
                       cxx_doc("DressOptions.body_points"))
        .def_readwrite("smooth_folds", &tgm::DressOptions::smooth_folds,
                       cxx_doc("DressOptions.smooth_folds"))
        .def_readwrite("fold_options", &tgm::DressOptions::fold_options,
                       cxx_doc("DressOptions.fold_options"))
        .def_readwrite("fold_cycles", &tgm::DressOptions::fold_cycles,
                       cxx_doc("DressOptions.fold_cycles"))
        .def_readwrite("sdf_cell_mm", &tgm::DressOptions::sdf_cell_mm,
                       cxx_doc("DressOptions.sdf_cell_mm"))
        .def_readwrite("waistband", &tgm::DressOptions::waistband,
                       cxx_doc("DressOptions.waistband"))
        .def_readwrite("waistband_sag_mm", &tgm::DressOptions::waistband_sag_mm,
                       cxx_doc("DressOptions.waistband_sag_mm"));
    const tm::BodyOptions body_defaults;
    m.def(
        "dress",
        [](const py::object& V, const py::object& F, const py::dict& pattern,
           const std::optional<std::string>& units, const std::string& up, const std::string& front,
           const std::string& name, const py::object& fabric, const py::object& base,
           std::uint32_t seed, bool strict, const std::optional<tgm::DressOptions>& options,
           const py::kwargs& kw) {
            // Keyword options: DressOptions' own fields, over `options` (or the defaults);
            // `placement`, `sewing`, `drape` take their option objects.
            return dress_arrays(V, F, pattern, units, up, front, name, fabric, base, seed, strict,
                                options_from<tgm::DressOptions>(
                                    kw, "dress", options.value_or(tgm::DressOptions{})));
        },
        py::arg("V"), py::arg("F"), py::arg("pattern"), py::kw_only(),
        py::arg("units") = py::none(), py::arg("up") = body_defaults.up.to_string(),
        py::arg("front") = body_defaults.front.to_string(), py::arg("name") = body_defaults.name,
        py::arg("fabric") = tgm::FabricParams{}.name, py::arg("base") = py::none(),
        py::arg("seed") = 1u, py::arg("strict") = false, py::arg("options") = py::none(),
        "Dresses the body mesh (V, F) in a pattern dict as `tapeline dress` does: measures the "
        "body, places the pieces around it, sews them along geodesic strings on the body and "
        "drapes them with the cloth solver. units, up, front: as tapeline.measure; fabric: a "
        "library name (fabrics()), a .json fabric file or a fabric dict; base: the measurement "
        "set the pattern was drafted for (a file path, a measurement dict or {name: mm}) to grade "
        "the pattern to the body first (`dress --to-body --from`), seed: the grading's; strict: "
        "raise SolverFailure when a quality gate fails; options: a DressOptions (None: the "
        "defaults). Further keyword arguments set its fields (resolution_mm, without_pieces, "
        "sdf_cell_mm, relax, body_points, smooth_folds, fold_cycles, waistband, "
        "waistband_sag_mm, and placement, sewing, "
        "drape, relax_options, relax_again_options, fold_options as PlacementOptions, "
        "SewingOptions, DrapeOptions, RelaxOptions, RelaxOptions, FoldOptions). Returns a dict: "
        "'V' (n, 3) and 'F' (m, 3) "
        "of the welded garment in the body's coordinates and unit, 'uv' (m, 3, 2) pattern "
        "millimetres per corner, 'piece' (m,) piece index per triangle, 'piece_names', 'stretch' "
        "(m,) largest principal stretch per triangle, 'report' (the JSON of `dress --report`: "
        "gates, quality, seams, pieces, timings), 'warnings' and 'grading_notes'.");
    m.def(
        "bindings_from_body",
        [](const py::object& V, const py::object& F, const py::dict& pattern,
           const std::optional<std::string>& units, const std::string& up, const std::string& front,
           const std::string& name) {
            const tm::BodyOptions body = tm::parse_body_options(
                name, units.value_or(""), up, front, tm::to_string(tm::BodyOptions{}.pose));
            pattern::Pattern p = pattern::from_json(json_of(pattern, "pattern"), "pattern");
            pattern::require_valid(p);
            const auto mesh = mesh_from_arrays(V, F, name);
            bench::BodyBase b;
            {
                InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                b = bench::base_from_mesh(std::move(p), mesh->loaded.mesh, body);
            }
            py::dict base;
            for (const auto& [key, value] : b.measurements.values) {
                base[py::str(key)] = value;
            }
            return py::make_tuple(to_python(pattern::to_json(b.pattern)), base, py::cast(b.notes));
        },
        py::arg("V"), py::arg("F"), py::arg("pattern"), py::kw_only(),
        py::arg("units") = py::none(), py::arg("up") = body_defaults.up.to_string(),
        py::arg("front") = body_defaults.front.to_string(), py::arg("name") = body_defaults.name,
        "The girth bindings of a pattern dict found by laying it on the body mesh (V, F) it was "
        "made for, as `tapeline grade --base-body` finds them: the body measured, the pattern "
        "laid out as dressing lays it, each horizontal torso girth cut across the torso and "
        "skirt pieces. units, up, front: as tapeline.measure. Returns (the pattern dict with the "
        "found bindings and their named points, the body's measurements {name: mm} to grade "
        "from, one note per girth: bound or why not); tapeline.grade(pattern, base, target) "
        "then grades it.");
    m.def(
        "fabrics",
        [] {
            py::list out;
            for (const tgm::Fabric& f : tgm::fabric_library()) {
                out.append(to_python(tgm::fabric_json(f)));
            }
            return out;
        },
        "The fabric library as fabric dicts (the JSON of `tapeline fabric show`), in the order of "
        "`tapeline fabric list`.");
    m.def(
        "fabric", [](const py::object& f) { return to_python(tgm::fabric_json(fabric_of(f))); },
        py::arg("fabric"),
        "A fabric dict (the JSON of `tapeline fabric show`) of a library name, a .json fabric file "
        "or a fabric dict (checked, derived figures filled in).");
}

}  // namespace tapeline::python
