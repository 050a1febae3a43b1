// Exact polyhedral geodesic distances and shortest paths by window propagation:
// J. S. B. Mitchell, D. M. Mount, C. H. Papadimitriou, "The discrete geodesic problem", SIAM J.
// Computing 16(4), 1987, in the practical form of V. Surazhsky, T. Surazhsky, D. Kirsanov,
// S. J. Gortler, H. Hoppe, "Fast exact and approximate geodesics on meshes", ACM TOG 24(3), 2005,
// with the vertex-distance window pruning of Y. Qin et al., "Fast and exact discrete geodesic
// computation based on triangle-oriented wavefront propagation", ACM TOG 35(4), 2016.
// Written from the papers; the machinery is in internal/mmp_engine.h (no CGAL there).
//
// Behaviour the MMP ports get wrong and this one guards (see geodesic/README.md, "Exact MMP"):
// meshes with border (border vertices are pseudo-sources, windows never enter the outside),
// unreachable vertices (+infinity, not 0), isolated vertices, zero-area and needle faces
// (their corners are pseudo-sources, windows on zero-length edges are dropped), non-manifold
// vertices of a Surface_mesh (pseudo-sources: a geodesic may pass from one fan to another through
// them), perfectly symmetric meshes (ties keep the window already there: nothing is propagated
// twice), and runaway propagation (a cap turns it into SolverFailure).
#pragma once

#include <tapeline/core/compact_mesh.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/geodesic/exact_mmp_types.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/mmp_engine.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <variant>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace tapeline::geodesic {

namespace internal {

/// Source-independent part of the exact MMP method: checked index maps and the compact mesh
/// (core/compact_mesh.h) with the lengths, layouts and flags of mmp_mesh.h.
/// Shared (read-only) by every solver of a distance matrix.
template <class TriangleMesh, class NamedParameters>
class MmpPrepared {
public:
    using P = MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Index = MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>;
    using vertex_descriptor = typename GT::vertex_descriptor;

    MmpPrepared(const TriangleMesh& tm, const NamedParameters& np)
        : tm_(tm),
          vpm_(P::vertex_point_map(tm, np)),
          index_(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), "exact_mmp") {
        const auto t0 = Clock::now();
        check_triangle_mesh(tm, vpm_, index_.vertex_index_map(), index_.face_index_map(),
                            "exact_mmp");
        if (index_.vertex_count() >= mmp::kNone / 2 || 3 * index_.face_count() >= mmp::kNone / 2)
            throw InvalidInput("exact_mmp: the mesh is too large (32-bit element indices)");
        components_ = connected_components(tm, index_);
        mesh_ = mmp::CompactMesh(make_compact_mesh(tm, vpm_, index_.vertex_index_map(),
                                                   index_.face_index_map(), "exact_mmp"));
        mesh_.finish();
        for (auto flags : mesh_.vflags)
            pseudo_vertices_ += (flags & mmp::kPseudoSource) ? 1 : 0;
        seconds_ = seconds_since(t0);
    }

    const TriangleMesh& mesh() const { return tm_; }
    const Index& index() const { return index_; }
    const mmp::CompactMesh& compact() const { return mesh_; }
    const Components& components() const { return components_; }
    typename P::VertexPointMap vertex_point_map() const { return vpm_; }
    double seconds() const { return seconds_; }
    std::size_t pseudo_vertices() const { return pseudo_vertices_; }

    /// A checked surface point: a vertex index, or a face index with clean barycentric
    /// coordinates (not on a corner).
    struct Point {
        std::uint32_t vertex = mmp::kNone;
        std::uint32_t face = mmp::kNone;
        std::array<double, 3> bary{0, 0, 0};
    };
    Point checked(const SurfacePoint<TriangleMesh>& p, const char* what) const {
        Point out;
        if (const auto* v = std::get_if<vertex_descriptor>(&p)) {
            out.vertex = static_cast<std::uint32_t>(index_.checked(*v, what));
            return out;
        }
        const auto clean = index_.checked(std::get<FaceLocation<TriangleMesh>>(p), what);
        const auto corner = index_.corner_vertex(clean);
        if (corner != GT::null_vertex()) {
            out.vertex = static_cast<std::uint32_t>(index_.index(corner));
            return out;
        }
        out.face = static_cast<std::uint32_t>(index_.index(clean.first));
        out.bary = {clean.second[0], clean.second[1], clean.second[2]};
        return out;
    }

    std::vector<std::uint32_t> checked_targets(const ExactMmpOptions& o) const {
        if (std::isnan(o.max_distance) || o.max_distance < 0) {
            std::ostringstream s;
            s << "exact_mmp: options.max_distance must be >= 0 (got " << o.max_distance << ")";
            throw InvalidInput(s.str());
        }
        std::vector<std::uint32_t> out;
        for (std::size_t t : o.target_vertices) {
            if (t >= index_.vertex_count()) {
                std::ostringstream s;
                s << "exact_mmp: options.target_vertices holds " << t << ", but the mesh has "
                  << index_.vertex_count() << " vertices";
                throw InvalidInput(s.str());
            }
            out.push_back(static_cast<std::uint32_t>(t));
        }
        return out;
    }

private:
    const TriangleMesh& tm_;
    typename P::VertexPointMap vpm_;
    Index index_;
    mmp::CompactMesh mesh_;
    Components components_;
    std::size_t pseudo_vertices_ = 0;
    double seconds_ = 0;
};

/// Runs the propagation from checked sources; SolverAbort becomes SolverFailure.
template <class Prepared>
std::unique_ptr<mmp::Engine> run_mmp(const Prepared& prep,
                                     const std::vector<typename Prepared::Point>& sources,
                                     const std::vector<std::uint32_t>& targets,
                                     const ExactMmpOptions& options, bool keep_windows,
                                     Progress* progress = nullptr) {
    auto engine = std::make_unique<mmp::Engine>(prep.compact(), options.max_distance,
                                                options.prune_with_vertex_distances,
                                                options.max_propagated_windows, keep_windows);
    for (const auto& s : sources) {
        if (s.vertex != mmp::kNone)
            engine->add_vertex_source(s.vertex);
        else
            engine->add_face_source(s.face, s.bary);
    }
    engine->set_targets(targets);
    try {
        engine->run(progress);
    } catch (const mmp::SolverAbort& e) {
        throw SolverFailure(std::string("exact_mmp: ") + e.what());
    }
    return engine;
}

}  // namespace internal

/// Exact distances from one source set. The windows are kept after the propagation, so that
/// distance_to() answers for any face location and path_to() back-traces shortest paths.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class ExactMmpSolver {
    using Prepared = internal::MmpPrepared<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Kernel = typename Prepared::P::GeomTraits;

public:
    using vertex_descriptor = typename GT::vertex_descriptor;  ///< a vertex of the mesh
    using face_descriptor = typename GT::face_descriptor;      ///< a face of the mesh
    using Point_3 = typename Kernel::Point_3;                  ///< point type of the kernel
    using Path = GeodesicPath<Point_3>;                        ///< a polyline and its length

    /// Checks the mesh and the sources, then runs the propagation from `sources`.
    ///
    /// \param tm the mesh; it must outlive the solver and stay unchanged.
    /// \param sources vertices and face locations of `tm`.
    /// \param options stop distance, targets, pruning and the window cap.
    /// \param np the named parameters listed with the class.
    /// \throws TopologyError when a face is not a triangle.
    /// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
    ///         onto [0, n) (a Surface_mesh with removed elements), a mesh beyond 32-bit
    ///         indices, an empty source set, a source that is not on the mesh, a negative
    ///         `options.max_distance` or an out-of-range `options.target_vertices` entry.
    /// \throws SolverFailure when the propagation exceeds `options.max_propagated_windows`.
    ExactMmpSolver(const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources,
                   const ExactMmpOptions& options = {},
                   const NamedParameters& np = CGAL::parameters::default_values())
        : prep_(std::make_shared<const Prepared>(tm, np)), options_(options) {
        init(sources);
    }

    /// Single-vertex source; throws as the source-set constructor.
    ExactMmpSolver(const TriangleMesh& tm, vertex_descriptor source,
                   const ExactMmpOptions& options = {},
                   const NamedParameters& np = CGAL::parameters::default_values())
        : ExactMmpSolver(tm, SourceSet<TriangleMesh>(source), options, np) {}

    /// Writes the exact distance of every vertex into `distances` (+infinity when unreachable or
    /// beyond the stop distance of the options); returns the report with the unreachable count.
    ///
    /// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
    ///         value double.
    /// \throws SolverFailure when a distance is NaN (nothing is written then).
    template <class VertexDistanceMap>
    ExactMmpReport distances(VertexDistanceMap distances) const {
        const auto t0 = internal::Clock::now();
        const auto& index = prep_->index();
        std::vector<double> d(index.vertex_count());
        for (std::size_t i = 0; i < d.size(); ++i)
            d[i] = engine_->vertex_distance(static_cast<std::uint32_t>(i));
        ExactMmpReport r = report_;
        r.unreachable = internal::write_distances(d, index, distances, "exact_mmp");
        r.query_seconds += internal::seconds_since(t0);
        r.seconds = r.prepare_seconds + r.query_seconds;
        return r;
    }

    /// Exact distance from the source set to a vertex or a face location (+infinity if
    /// unreachable or beyond the stop distance).
    ///
    /// \throws InvalidInput when `target` is not a vertex or face location of the mesh.
    /// \throws SolverFailure when the propagation that keeps the windows (run once here without
    ///         `options.keep_windows`) exceeds the window cap.
    double distance_to(const SurfacePoint<TriangleMesh>& target) const {
        const auto t = prep_->checked(target, "target");
        if (t.vertex != internal::mmp::kNone)
            return engine_->vertex_distance(t.vertex);
        return query_engine().face_distance(t.face, t.bary);
    }

    /// Shortest path from the nearest source to `target`: a polyline from the source point to
    /// the target, straight inside every face it crosses (a valid unfolding). Unreachable: no
    /// points, length +infinity.
    ///
    /// \throws InvalidInput as distance_to().
    /// \throws SolverFailure as distance_to().
    Path path_to(const SurfacePoint<TriangleMesh>& target) const {
        const auto t = prep_->checked(target, "target");
        const auto trace = query_engine().trace(t.face, t.bary, t.vertex);
        Path path;
        if (trace.empty())
            return path;
        for (auto it = trace.rbegin(); it != trace.rend(); ++it) {
            const Point_3 p(it->xyz[0], it->xyz[1], it->xyz[2]);
            if (path.points.empty() || path.points.back() != p)
                path.points.push_back(p);
        }
        path.length = 0;
        for (std::size_t k = 1; k < path.points.size(); ++k)
            path.length += std::sqrt(
                CGAL::to_double(CGAL::squared_distance(path.points[k - 1], path.points[k])));
        return path;
    }

    /// Sizes, window counts, timings and status of the propagation.
    const ExactMmpReport& report() const { return report_; }
    /// The options the solver runs with.
    const ExactMmpOptions& options() const { return options_; }

private:
    void init(const SourceSet<TriangleMesh>& sources) {
        if (sources.empty())
            throw InvalidInput("exact_mmp: the source set is empty");
        std::vector<typename Prepared::Point> pts;
        for (auto v : sources.vertices)
            pts.push_back(prep_->checked(SurfacePoint<TriangleMesh>(v), "source vertex"));
        for (const auto& l : sources.locations)
            pts.push_back(prep_->checked(SurfacePoint<TriangleMesh>(l), "source face location"));
        const auto targets = prep_->checked_targets(options_);
        const auto t0 = internal::Clock::now();
        Progress progress("exact-mmp windows");
        engine_ =
            internal::run_mmp(*prep_, pts, targets, options_, options_.keep_windows, &progress);
        sources_ = std::move(pts);
        report_.method = "exact_mmp";
        report_.vertices = prep_->index().vertex_count();
        report_.faces = prep_->index().face_count();
        report_.sources = sources.size();
        report_.components = prep_->components().count;
        report_.prepare_seconds = prep_->seconds();
        report_.query_seconds = internal::seconds_since(t0);
        report_.seconds = report_.prepare_seconds + report_.query_seconds;
        const auto& st = engine_->stats();
        report_.windows_created = st.created;
        report_.windows_propagated = st.propagated;
        report_.windows_pruned = st.pruned;
        report_.windows_kept = engine_->windows_alive();
        report_.windows_peak = st.peak;
        report_.pseudo_sources = st.emitted;
        report_.saddle_or_boundary_vertices = prep_->pseudo_vertices();
        const auto& cm = prep_->compact();
        report_.peak_bytes = st.peak_bytes + cm.xyz.size() * 8 + cm.corner.size() * 16 +
                             cm.vcorners.size() * 4 + cm.vstart.size() * 4 + cm.vflags.size();
        report_.stopped_at = st.stopped_at;
        if (st.stopped_at < internal::kInfinity) {
            report_.status = "stopped";
            std::ostringstream s;
            s << "propagation stopped at distance " << st.stopped_at
              << "; farther vertices are +infinity";
            report_.message = s.str();
        }
    }

    // The engine that kept its windows; without options.keep_windows, a second propagation
    // that keeps them runs once, on the first query that needs them.
    const internal::mmp::Engine& query_engine() const {
        if (options_.keep_windows)
            return *engine_;
        std::lock_guard<std::mutex> lock(*query_mutex_);
        if (!query_engine_)
            query_engine_ = internal::run_mmp(*prep_, sources_, prep_->checked_targets(options_),
                                              options_, true);
        return *query_engine_;
    }

    std::shared_ptr<const Prepared> prep_;
    ExactMmpOptions options_;
    std::vector<typename Prepared::Point> sources_;
    std::unique_ptr<internal::mmp::Engine> engine_;
    // Behind a pointer so that the solver stays movable.
    std::unique_ptr<std::mutex> query_mutex_ = std::make_unique<std::mutex>();
    mutable std::unique_ptr<internal::mmp::Engine> query_engine_;
    ExactMmpReport report_;
};

/// One-shot exact distances from a source set into `distances` (+infinity when unreachable).
/// The windows are dropped as the propagation goes, so the peak memory is lower than with
/// ExactMmpSolver.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
///         value double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements), a mesh beyond 32-bit
///         indices, an empty source set, a source that is not on the mesh, a negative
///         `options.max_distance` or an out-of-range `options.target_vertices` entry.
/// \throws SolverFailure when the propagation exceeds `options.max_propagated_windows`.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
ExactMmpReport exact_mmp_distances(const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources,
                                   VertexDistanceMap distances, const ExactMmpOptions& options = {},
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
    ExactMmpOptions o = options;
    o.keep_windows = false;
    const ExactMmpSolver<TriangleMesh, NamedParameters> solver(tm, sources, o, np);
    return solver.distances(distances);
}

/// One-shot exact distances from one vertex; template parameters and exceptions as the
/// source-set overload.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
ExactMmpReport exact_mmp_distances(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    VertexDistanceMap distances, const ExactMmpOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    return exact_mmp_distances(tm, SourceSet<TriangleMesh>(source), distances, options, np);
}

/// Exact shortest path between two surface points, as a polyline from `from` to `to` (no points
/// and length +infinity when `to` is unreachable).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements), a mesh beyond 32-bit
///         indices, an empty source set, a source that is not on the mesh, a negative
///         `options.max_distance` or an out-of-range `options.target_vertices` entry.
/// \throws SolverFailure when the propagation exceeds `options.max_propagated_windows`.
/// \throws InvalidInput also when `to` is not a vertex or face location of the mesh.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
typename ExactMmpSolver<TriangleMesh, NamedParameters>::Path exact_mmp_path(
    const TriangleMesh& tm, const SurfacePoint<TriangleMesh>& from,
    const SurfacePoint<TriangleMesh>& to, const ExactMmpOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    const ExactMmpSolver<TriangleMesh, NamedParameters> solver(tm, SourceSet<TriangleMesh>(from),
                                                               options, np);
    return solver.path_to(to);
}

/// Distance matrix: row s holds the exact distances from sources[s] to every vertex, indexed by
/// the vertex index map (+infinity when unreachable). The rows are computed in parallel, one
/// propagation per task on a shared read-only compact mesh: tbb::parallel_for when CGAL is linked
/// with TBB (CGAL_LINKED_WITH_TBB, i.e. CGAL::TBB_support), std::thread otherwise.
/// `threads` = 0 uses every hardware thread (ignored with TBB, which uses its own arena).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements), a mesh beyond 32-bit
///         indices, a source that is not on the mesh, a negative
///         `options.max_distance` or an out-of-range `options.target_vertices` entry.
/// \throws SolverFailure when the propagation exceeds `options.max_propagated_windows`.
///         Every source is checked before any propagation starts; the first failing row's
///         exception is rethrown after the others finish.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::vector<double>> exact_mmp_distance_matrix(
    const TriangleMesh& tm, const std::vector<SurfacePoint<TriangleMesh>>& sources,
    const ExactMmpOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values(), unsigned threads = 0) {
    using Prepared = internal::MmpPrepared<TriangleMesh, NamedParameters>;
    const Prepared prep(tm, np);
    // Check everything before any work.
    std::vector<typename Prepared::Point> pts;
    for (const auto& s : sources)
        pts.push_back(prep.checked(s, "source"));
    const auto targets = prep.checked_targets(options);
    const std::size_t nv = prep.index().vertex_count();
    std::vector<std::vector<double>> rows(sources.size());
    Progress progress("exact-mmp distance matrix rows", sources.size());
    auto row = [&](std::size_t s) {
        const auto engine = internal::run_mmp(prep, {pts[s]}, targets, options, false);
        std::vector<double>& r = rows[s];
        r.resize(nv);
        for (std::size_t i = 0; i < nv; ++i)
            r[i] = engine->vertex_distance(static_cast<std::uint32_t>(i));
        progress.advance();
    };
#ifdef CGAL_LINKED_WITH_TBB
    (void)threads;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sources.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t s = r.begin(); s != r.end(); ++s)
                              row(s);
                      });
#else
    unsigned n = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
    n = static_cast<unsigned>(std::min<std::size_t>(n, sources.size()));
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&] {
        for (std::size_t s = next++; s < sources.size(); s = next++) {
            try {
                row(s);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error)
                    error = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t)
        pool.emplace_back(work);
    work();
    for (auto& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
#endif
    return rows;
}

}  // namespace tapeline::geodesic
