// tapeline.geodesic: distance fields by the named methods of `tapeline geodesic distances`, the
// solvers that keep their set-up (exact MMP, heat, curvature-flow paths) and point clouds.
#include "common.h"

#include <tapeline_python_docs.h>

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/curvature_flow_json.h>
#include <tapeline/geodesic/exact_mmp.h>
#include <tapeline/geodesic/exact_mmp_json.h>
#include <tapeline/geodesic/geodesic_json.h>
#include <tapeline/geodesic/heat.h>
#include <tapeline/geodesic/point_cloud.h>
#include <tapeline/geodesic/point_cloud_json.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::python {

namespace {

namespace tg = tapeline::geodesic;

/// An enum bound with its library names; Python strings convert to it ("mls", "plane", ...).
template <class E>
void bind_enum(py::module_& m, const char* name, std::initializer_list<E> values) {
    py::enum_<E> e(m, name);
    std::vector<E> all(values);
    for (E v : all) {
        e.value(tg::to_string(v), v);
    }
    e.def(py::init([all, name](const std::string& text) {
        std::string known;
        for (E v : all) {
            if (text == tg::to_string(v)) {
                return v;
            }
            known += (known.empty() ? "" : ", ") + std::string(tg::to_string(v));
        }
        throw InvalidInput(std::string(name) + " '" + text + "': expected one of " + known);
    }));
    e.def("__str__", [](E v) { return std::string(tg::to_string(v)); });
    py::implicitly_convertible<std::string, E>();
}

template <class Options>
py::dict options_dict(const Options& o) {
    return to_python(nlohmann::json(o)).template cast<py::dict>();
}

py::array_t<double> field_of(const ArrayMesh& mesh, const std::vector<double>& d) {
    return input_order(mesh.loaded, d);
}

/// Distances per mesh vertex into a vector indexed by Surface_mesh index (a WritablePropertyMap
/// with key Vertex).
struct FieldMap {
    std::vector<double>* values;
    friend void put(const FieldMap& m, Vertex v, double d) {
        (*m.values)[static_cast<std::size_t>(v.idx())] = d;
    }
};

py::tuple path_tuple(const tg::GeodesicPath<bench::Point>& p) {
    return py::make_tuple(points_array(p.points), p.length);
}

// --- exact MMP ---------------------------------------------------------------------------------

/// Exact polyhedral distances and shortest paths (MMP). One propagation per source set; the last
/// one is kept, so path() and distance() from the same source reuse it.
class ExactMmp {
public:
    ExactMmp(const py::object& V, const py::object& F, const tg::ExactMmpOptions& options)
        : mesh_(mesh_from_arrays(V, F, "ExactMmpSolver")), options_(options) {}

    py::array_t<double> distances(const py::object& sources) {
        const tg::ExactMmpSolver<Mesh>& s = solver_for(sources);
        std::vector<double> d(num_vertices(mesh_->loaded.mesh));
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            report_ = s.distances(FieldMap{&d});
        }
        return field_of(*mesh_, d);
    }

    double distance(const py::object& source, const py::object& target) {
        const auto t = surface_point(target, *mesh_, "target");
        const tg::ExactMmpSolver<Mesh>& s = solver_for(source);
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        return s.distance_to(t);
    }

    py::tuple path(const py::object& source, const py::object& target) {
        const auto t = surface_point(target, *mesh_, "target");
        const tg::ExactMmpSolver<Mesh>& s = solver_for(source);
        tg::GeodesicPath<bench::Point> p;
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            p = s.path_to(t);
        }
        return path_tuple(p);
    }

    py::dict report() const { return to_python(nlohmann::json(report_)).cast<py::dict>(); }
    py::dict mesh_report() const { return report_dict(mesh_->loaded.report); }
    py::dict options() const { return options_dict(options_); }

private:
    const tg::ExactMmpSolver<Mesh>& solver_for(const py::object& sources) {
        const Sources s = sources_from(sources, *mesh_, "source");
        if (!solver_ || s.vertices != last_.vertices || !same_locations(s, last_)) {
            solver_.reset();
            {
                InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                solver_.emplace(mesh_->loaded.mesh, s, options_);
            }
            last_ = s;
            report_ = solver_->report();
        }
        return *solver_;
    }
    static bool same_locations(const Sources& a, const Sources& b) {
        if (a.locations.size() != b.locations.size()) {
            return false;
        }
        for (std::size_t i = 0; i < a.locations.size(); ++i) {
            if (a.locations[i].first != b.locations[i].first ||
                a.locations[i].second != b.locations[i].second) {
                return false;
            }
        }
        return true;
    }

    std::shared_ptr<const ArrayMesh> mesh_;
    tg::ExactMmpOptions options_;
    std::optional<tg::ExactMmpSolver<Mesh>> solver_;
    Sources last_;
    tg::ExactMmpReport report_;
};

// --- heat --------------------------------------------------------------------------------------

/// The heat method, factorised once in the constructor.
class Heat {
public:
    Heat(const py::object& V, const py::object& F, const tg::HeatOptions& options)
        : mesh_(mesh_from_arrays(V, F, "HeatSolver")) {
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        solver_ = std::make_unique<tg::HeatDistanceSolver<Mesh>>(mesh_->loaded.mesh, options);
    }
    py::array_t<double> distances(const py::object& sources) {
        const Sources s = sources_from(sources, *mesh_, "sources");
        std::vector<double> d(num_vertices(mesh_->loaded.mesh));
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            report_ = solver_->distances(s, FieldMap{&d});
        }
        return field_of(*mesh_, d);
    }
    py::dict report() const { return to_python(nlohmann::json(report_)).cast<py::dict>(); }
    py::dict options() const { return options_dict(solver_->options()); }

private:
    std::shared_ptr<const ArrayMesh> mesh_;
    std::unique_ptr<tg::HeatDistanceSolver<Mesh>> solver_;
    tg::DistanceReport report_;
};

// --- curvature-flow paths ----------------------------------------------------------------------

/// Geodesic paths by curvature flow between two surface points; the mesh set-up is kept.
class FlowPaths {
public:
    FlowPaths(const py::object& V, const py::object& F)
        : mesh_(mesh_from_arrays(V, F, "CurvatureFlowPathSolver")) {
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        solver_ = std::make_unique<tg::GeodesicPathSolver<Mesh>>(mesh_->loaded.mesh);
    }
    py::tuple path(const py::object& from, const py::object& to, bool smooth,
                   const tg::CurvatureFlowOptions& options) {
        const auto a = surface_point(from, *mesh_, "from");
        const auto b = surface_point(to, *mesh_, "to");
        tg::CurvatureFlowPath<bench::Point> r;
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            r = solver_->path(a, b, options);
        }
        report_ = r.report;
        return path_tuple(smooth ? r.smooth : r.on_mesh);
    }
    py::dict report() const { return to_python(nlohmann::json(report_)).cast<py::dict>(); }

private:
    std::shared_ptr<const ArrayMesh> mesh_;
    std::unique_ptr<tg::GeodesicPathSolver<Mesh>> solver_;
    tg::CurvatureFlowReport report_;
};

// --- point clouds ------------------------------------------------------------------------------

/// A row of the caller's (n, d) float64 array, without a copy.
struct Row {
    const double* first;
    const double* last;
    const double* begin() const { return first; }
    const double* end() const { return last; }
};

/// Distances and paths on a point set of any dimension (the thesis' Algorithm 3).
class PointCloud {
public:
    PointCloud(const py::object& P, const tg::PointCloudDistanceOptions& options) {
        const py::array given = py::array::ensure(P);
        if (!given || given.dtype().kind() != 'f' || given.ndim() != 2 || given.shape(1) < 1) {
            std::size_t n = 0, d = 0;
            float_rows(P, "P", n, d);  // throws the ValueError naming dtype and shape
        }
        const auto a =
            py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
        const auto n = static_cast<std::size_t>(a.shape(0));
        const auto d = static_cast<std::size_t>(a.shape(1));
        std::vector<Row> rows(n);
        for (std::size_t i = 0; i < n; ++i) {
            rows[i] = Row{a.data() + i * d, a.data() + (i + 1) * d};
        }
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        solver_ = std::make_unique<Solver>(rows, options);
        size_ = n;
        dimension_ = d;
    }
    py::array_t<double> distances(std::size_t source) {
        py::array_t<double> out(static_cast<py::ssize_t>(size_));
        double* d = out.mutable_data();
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            report_ =
                solver_->distances(source, boost::make_function_property_map<std::size_t, double&>(
                                               [d](std::size_t i) -> double& { return d[i]; }));
        }
        return out;
    }
    py::tuple path(std::size_t from, std::size_t to) {
        tg::PointCloudPath p;
        {
            InterruptGuard interrupt_guard;
            py::gil_scoped_release release;
            p = solver_->path(from, to);
        }
        report_ = p.report;
        py::array_t<double> pts(
            {static_cast<py::ssize_t>(p.samples()), static_cast<py::ssize_t>(p.dimension)});
        std::copy(p.coordinates.begin(), p.coordinates.end(), pts.mutable_data());
        return py::make_tuple(pts, p.length);
    }
    py::dict report() const { return to_python(nlohmann::json(report_)).cast<py::dict>(); }
    std::size_t dimension() const { return dimension_; }

private:
    using Solver = tg::PointCloudGeodesicSolver<std::vector<Row>>;
    std::unique_ptr<Solver> solver_;
    std::size_t size_ = 0, dimension_ = 0;
    tg::PointCloudDistanceReport report_;
};

}  // namespace

void bind_geodesic(py::module_& parent) {
    py::module_ m = parent.def_submodule(
        "geodesic", "Geodesic distances and paths on triangle meshes and point clouds.");

    bind_enum<tg::HeatMultiSource>(
        m, "HeatMultiSource",
        {tg::HeatMultiSource::min_of_single_sources, tg::HeatMultiSource::cgal_joint});
    bind_enum<tg::PointCloudProjection>(
        m, "PointCloudProjection",
        {tg::PointCloudProjection::mls, tg::PointCloudProjection::plane});
    bind_enum<tg::PointCloudKnn>(
        m, "PointCloudKnn",
        {tg::PointCloudKnn::automatic, tg::PointCloudKnn::cgal, tg::PointCloudKnn::nanoflann});
    bind_enum<tg::CurvatureFlowSolver>(
        m, "CurvatureFlowSolver",
        {tg::CurvatureFlowSolver::eigen_normal_ldlt, tg::CurvatureFlowSolver::eigen_sparse_qr,
         tg::CurvatureFlowSolver::eigen_lscg, tg::CurvatureFlowSolver::ceres});

    py::class_<tg::ExactMmpOptions>(m, "ExactMmpOptions", cxx_doc("ExactMmpOptions"))
        .def(py::init<>())
        .def_readwrite("max_distance", &tg::ExactMmpOptions::max_distance,
                       cxx_doc("ExactMmpOptions.max_distance"))
        .def_readwrite("target_vertices", &tg::ExactMmpOptions::target_vertices,
                       cxx_doc("ExactMmpOptions.target_vertices"))
        .def_readwrite("prune_with_vertex_distances",
                       &tg::ExactMmpOptions::prune_with_vertex_distances,
                       cxx_doc("ExactMmpOptions.prune_with_vertex_distances"))
        .def_readwrite("keep_windows", &tg::ExactMmpOptions::keep_windows,
                       cxx_doc("ExactMmpOptions.keep_windows"))
        .def_readwrite("max_propagated_windows", &tg::ExactMmpOptions::max_propagated_windows,
                       cxx_doc("ExactMmpOptions.max_propagated_windows"))
        .def("to_dict", &options_dict<tg::ExactMmpOptions>);
    py::class_<tg::HeatOptions>(m, "HeatOptions", cxx_doc("HeatOptions"))
        .def(py::init<>())
        .def_readwrite("intrinsic_delaunay", &tg::HeatOptions::intrinsic_delaunay,
                       cxx_doc("HeatOptions.intrinsic_delaunay"))
        .def_readwrite("multi_source", &tg::HeatOptions::multi_source,
                       cxx_doc("HeatOptions.multi_source"))
        .def_readwrite("degenerate_face_tolerance", &tg::HeatOptions::degenerate_face_tolerance,
                       cxx_doc("HeatOptions.degenerate_face_tolerance"))
        .def_readwrite("reject_degenerate_faces", &tg::HeatOptions::reject_degenerate_faces,
                       cxx_doc("HeatOptions.reject_degenerate_faces"))
        .def("to_dict", &options_dict<tg::HeatOptions>);
    py::class_<tg::CurvatureFlowOptions>(m, "CurvatureFlowOptions", cxx_doc("CurvatureFlowOptions"))
        .def(py::init<>())
        .def_readwrite("sample_spacing", &tg::CurvatureFlowOptions::sample_spacing,
                       cxx_doc("CurvatureFlowOptions.sample_spacing"))
        .def_readwrite("sample_count", &tg::CurvatureFlowOptions::sample_count,
                       cxx_doc("CurvatureFlowOptions.sample_count"))
        .def_readwrite("step", &tg::CurvatureFlowOptions::step,
                       cxx_doc("CurvatureFlowOptions.step"))
        .def_readwrite("tolerance", &tg::CurvatureFlowOptions::tolerance,
                       cxx_doc("CurvatureFlowOptions.tolerance"))
        .def_readwrite("update_tolerance", &tg::CurvatureFlowOptions::update_tolerance,
                       cxx_doc("CurvatureFlowOptions.update_tolerance"))
        .def_readwrite("max_iterations", &tg::CurvatureFlowOptions::max_iterations,
                       cxx_doc("CurvatureFlowOptions.max_iterations"))
        .def_readwrite("endpoint_weight", &tg::CurvatureFlowOptions::endpoint_weight,
                       cxx_doc("CurvatureFlowOptions.endpoint_weight"))
        .def_readwrite("solver", &tg::CurvatureFlowOptions::solver,
                       cxx_doc("CurvatureFlowOptions.solver"))
        .def_readwrite("straighten", &tg::CurvatureFlowOptions::straighten,
                       cxx_doc("CurvatureFlowOptions.straighten"))
        .def_readwrite("interpolate_normals", &tg::CurvatureFlowOptions::interpolate_normals,
                       cxx_doc("CurvatureFlowOptions.interpolate_normals"))
        .def("to_dict", &options_dict<tg::CurvatureFlowOptions>);
    py::class_<tg::PointCloudDistanceOptions>(m, "PointCloudOptions",
                                              cxx_doc("PointCloudDistanceOptions"))
        .def(py::init<>())
        .def_readwrite("cell_size", &tg::PointCloudDistanceOptions::cell_size,
                       cxx_doc("PointCloudDistanceOptions.cell_size"))
        .def_readwrite("neighbours", &tg::PointCloudDistanceOptions::neighbours,
                       cxx_doc("PointCloudDistanceOptions.neighbours"))
        .def_readwrite("window", &tg::PointCloudDistanceOptions::window,
                       cxx_doc("PointCloudDistanceOptions.window"))
        .def_readwrite("manifold_dimension", &tg::PointCloudDistanceOptions::manifold_dimension,
                       cxx_doc("PointCloudDistanceOptions.manifold_dimension"))
        .def_readwrite("projection", &tg::PointCloudDistanceOptions::projection,
                       cxx_doc("PointCloudDistanceOptions.projection"))
        .def_readwrite("knn", &tg::PointCloudDistanceOptions::knn,
                       cxx_doc("PointCloudDistanceOptions.knn"))
        .def_readwrite("sample_spacing", &tg::PointCloudDistanceOptions::sample_spacing,
                       cxx_doc("PointCloudDistanceOptions.sample_spacing"))
        .def_readwrite("cut_locus_guard", &tg::PointCloudDistanceOptions::cut_locus_guard,
                       cxx_doc("PointCloudDistanceOptions.cut_locus_guard"))
        .def_readwrite("near_source_samples", &tg::PointCloudDistanceOptions::near_source_samples,
                       cxx_doc("PointCloudDistanceOptions.near_source_samples"))
        .def_readwrite("anchor_slides", &tg::PointCloudDistanceOptions::anchor_slides,
                       cxx_doc("PointCloudDistanceOptions.anchor_slides"))
        .def("to_dict", &options_dict<tg::PointCloudDistanceOptions>);

    m.def(
        "distance_matrix",
        [](const py::object& V, const py::object& F, const py::object& sources, unsigned threads) {
            const auto mesh = mesh_from_arrays(V, F, "distance_matrix");
            std::vector<Vertex> rows;
            // One index (a Python or numpy integer) or a sequence / array of them.
            const bool many =
                (py::isinstance<py::sequence>(sources) && !py::isinstance<py::str>(sources)) ||
                (py::isinstance<py::array>(sources) &&
                 py::reinterpret_borrow<py::array>(sources).ndim() > 0);
            const py::object list = many ? py::reinterpret_borrow<py::object>(sources)
                                         : py::object(py::make_tuple(sources));
            for (const py::handle& p : list) {
                const auto s = surface_point(p, *mesh, "distance_matrix sources");
                if (!std::holds_alternative<Vertex>(s)) {
                    throw py::value_error(
                        "distance_matrix sources: a row needs a vertex index, got " +
                        py::repr(p).cast<std::string>());
                }
                const auto copies =
                    mesh->loaded.mesh_vertices_of(static_cast<std::size_t>(p.cast<long long>()));
                if (copies.size() != 1) {
                    throw py::value_error("distance_matrix sources: vertex " +
                                          py::repr(p).cast<std::string>() + " stands for " +
                                          std::to_string(copies.size()) +
                                          " mesh vertices (split where the mesh is not manifold)");
                }
                rows.push_back(copies.front());
            }
            if (rows.empty()) {
                throw py::value_error("distance_matrix: no source given");
            }
            std::vector<std::vector<double>> m;
            {
                InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                m = bench::exact_mmp_matrix(mesh->loaded.mesh, rows, threads);
            }
            const std::size_t n = mesh->loaded.to_input_order(m.front()).size();
            py::array_t<double> out(
                {static_cast<py::ssize_t>(m.size()), static_cast<py::ssize_t>(n)});
            for (std::size_t r = 0; r < m.size(); ++r) {
                const std::vector<double> in = mesh->loaded.to_input_order(m[r]);
                std::copy(in.begin(), in.end(), out.mutable_data() + r * n);
            }
            return out;
        },
        py::arg("V"), py::arg("F"), py::arg("sources"), py::arg("threads") = 0,
        "Exact distances (exact-mmp) from each source vertex to every row of V: a float64 array "
        "of shape (len(sources), len(V)), row s from sources[s], inf where unreachable or "
        "unused. The rows are computed in parallel on `threads` threads (0: every hardware "
        "thread); the result does not depend on it.");

    m.def("methods", &bench::distance_methods,
          "The names `distances` takes (as `tapeline geodesic distances --method`).");
    m.def(
        "distances",
        [](const py::object& V, const py::object& F, const py::object& sources,
           const std::string& method, std::size_t window, bool with_report) {
            const auto mesh = mesh_from_arrays(V, F, "distances");
            const Sources s = sources_from(sources, *mesh, "sources");
            bench::MethodSettings settings;
            settings.window = window;
            bench::MethodResult r;
            double call_seconds = 0;
            {
                InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                const auto t0 = std::chrono::steady_clock::now();
                r = bench::run_distance_method(method, mesh->loaded.mesh, s, settings);
                call_seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            }
            py::array_t<double> d = input_order(mesh->loaded, r.distances);
            if (!with_report) {
                return py::object(d);
            }
            py::dict report = to_python(nlohmann::json(r.report)).cast<py::dict>();
            report["options"] = to_python(bench::method_options_json(method, settings));
            report["mesh_seconds"] = mesh->build_seconds;  // the loader's checks and repairs
            // The whole C++ call (the method's own input checks included), wall clock.
            report["call_seconds"] = call_seconds;
            return py::object(py::make_tuple(d, report));
        },
        py::arg("V"), py::arg("F"), py::arg("sources"), py::arg("method") = "exact-mmp",
        py::arg("window") = bench::default_window(), py::arg("with_report") = false,
        "Geodesic distance from `sources` to every vertex of the mesh (V, F), by a named method "
        "(see methods(): exact-mmp, exact-cgal, heat, heat-idt, dijkstra, fmm, fmm-no-unfold, "
        "gcf-exact, "
        "gcf-window, "
        "gcf-window-thesis, gcf-points; gcf methods take ':W' and '/faces'). sources: a vertex "
        "index, a sequence of them, or (face, (b0, b1, b2)) points of F's faces. Returns a "
        "float64 array with one distance per row of V (inf where unreachable or unused); with "
        "with_report, (distances, report dict with the options used, mesh_seconds, the time "
        "the C++ loader took to check and build the mesh, and call_seconds, the whole C++ call "
        "of the method).");

    py::class_<ExactMmp>(m, "ExactMmpSolver",
                         "Exact polyhedral geodesics (Mitchell-Mount-Papadimitriou). The mesh is "
                         "checked once; each new source set runs one propagation, kept for "
                         "distance() and path() queries from it.")
        .def(py::init([](const py::object& V, const py::object& F, const py::kwargs& kw) {
                 return std::make_unique<ExactMmp>(
                     V, F, options_from<tg::ExactMmpOptions>(kw, "ExactMmpSolver"));
             }),
             py::arg("V"), py::arg("F"))
        .def("distances", &ExactMmp::distances, py::arg("sources"),
             "Exact distance from the sources to every vertex (float64, one per row of V).")
        .def("distance", &ExactMmp::distance, py::arg("source"), py::arg("target"),
             "Exact distance between two surface points (vertex or (face, (b0, b1, b2))).")
        .def("path", &ExactMmp::path, py::arg("source"), py::arg("target"),
             "Shortest path: (points (k, 3), length); straight inside every face it crosses.")
        .def_property_readonly("report", &ExactMmp::report,
                               "What the last propagation reported (windows, timings).")
        .def_property_readonly("mesh_report", &ExactMmp::mesh_report)
        .def_property_readonly("options", &ExactMmp::options);

    py::class_<Heat>(m, "HeatSolver",
                     "The heat method (Crane et al.), factorised once; intrinsic_delaunay=True "
                     "is heat-idt.")
        .def(py::init([](const py::object& V, const py::object& F, const py::kwargs& kw) {
                 return std::make_unique<Heat>(V, F,
                                               options_from<tg::HeatOptions>(kw, "HeatSolver"));
             }),
             py::arg("V"), py::arg("F"))
        .def("distances", &Heat::distances, py::arg("sources"),
             "Approximate geodesic distance to every vertex (float64, one per row of V).")
        .def_property_readonly("report", &Heat::report)
        .def_property_readonly("options", &Heat::options);

    py::class_<FlowPaths>(m, "CurvatureFlowPathSolver",
                          "Geodesic paths by geodesic curvature flow; the mesh set-up is kept.")
        .def(py::init<const py::object&, const py::object&>(), py::arg("V"), py::arg("F"))
        .def(
            "path",
            [](FlowPaths& self, const py::object& from, const py::object& to, bool smooth,
               const py::kwargs& kw) {
                return self.path(from, to, smooth,
                                 options_from<tg::CurvatureFlowOptions>(kw, "path"));
            },
            py::arg("source"), py::arg("target"), py::arg("smooth") = false,
            "Path between two surface points: (points (k, 3), length) of the trace on the faces, "
            "or of the samples lifted towards the smooth surface with smooth=True. Keyword "
            "arguments: the fields of CurvatureFlowOptions.")
        .def_property_readonly("report", &FlowPaths::report,
                               "The last path's report (iterations, curvature, status).");

    py::class_<PointCloud>(m, "PointCloudSolver",
                           "Geodesics on a point set of any dimension (curvature flow over a grid "
                           "of cells); the neighbourhoods and grid are built once.")
        .def(py::init([](const py::object& P, const py::kwargs& kw) {
                 return std::make_unique<PointCloud>(
                     P, options_from<tg::PointCloudDistanceOptions>(kw, "PointCloudSolver"));
             }),
             py::arg("P"))
        .def("distances", &PointCloud::distances, py::arg("source"),
             "Distance from point `source` to every point (float64, inf where unreachable).")
        .def("path", &PointCloud::path, py::arg("source"), py::arg("target"),
             "Path between two points: (samples (k, d), length).")
        .def_property_readonly("report", &PointCloud::report)
        .def_property_readonly("dimension", &PointCloud::dimension);
}

}  // namespace tapeline::python
