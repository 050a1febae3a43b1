// Two-point geodesic paths by geodesic curvature flow: a sampled path between two surface points
// is moved, samples within their tangent planes, until its geodesic curvature vanishes (the
// discrete curve-shortening flow restricted to a surface). Follows the geodesic-curvature-flow
// section of the project's virtual-clothing thesis draft (shared seed 000_cb1f07c4c9923062:
// curvature from second differences of the polyline, tangent planes from the eigenvectors of the
// face-normal matrix around the nearest vertex, one sparse least-squares system per step, samples
// re-projected onto the faces around their nearest vertex); written from that description. The
// smooth output uses Phong tessellation: T. Boubekeur, M. Alexa, "Phong tessellation", ACM TOG
// 27(5), 2008.
//
// Two results: `on_mesh`, the samples on the faces joined by straight pieces traced across the
// faces (plane cut through consecutive samples), a path on the polyhedron; and `smooth`, the
// samples lifted by Phong tessellation with the vertex normals of the flow, a path on the
// smooth surface the mesh approximates.
#pragma once

#include <tapeline/core/compact_mesh.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/internal/gcf_distances.h>
#include <tapeline/geodesic/internal/gcf_engine.h>
#include <tapeline/geodesic/internal/gcf_repair.h>
#include <tapeline/geodesic/internal/gcf_steiner.h>
#include <tapeline/geodesic/internal/gcf_trace.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/internal/unfold_engine.h>
#include <tapeline/geodesic/sources.h>
#include <tapeline/geodesic/unfold_types.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace tapeline::geodesic {

/// Result of a curvature-flow path query: the path in two forms and how the flow went.
///
/// \tparam Point the kernel's `Point_3` (of the mesh's vertex point map).
template <class Point>
struct CurvatureFlowPath {
    GeodesicPath<Point> smooth;   ///< samples lifted towards the smooth surface
    GeodesicPath<Point> on_mesh;  ///< samples on the faces, traced across the faces
    CurvatureFlowReport report;   ///< iterations, status, residuals, timings
};

namespace internal {

inline void check_options(const CurvatureFlowOptions& o) {
    auto bad = [](const std::string& what) {
        throw InvalidInput("geodesic_path (curvature flow): " + what);
    };
    if (!std::isfinite(o.sample_spacing) || o.sample_spacing < 0)
        bad("sample_spacing must be finite and >= 0 (0 = mean edge length)");
    if (o.sample_count != 0 && o.sample_count < 3)
        bad("sample_count must be 0 (from the spacing) or >= 3");
    if (!std::isfinite(o.step) || !(o.step > 0))
        bad("step must be finite and > 0");
    if (!std::isfinite(o.tolerance) || o.tolerance < 0)
        bad("tolerance must be finite and >= 0");
    if (!std::isfinite(o.update_tolerance) || o.update_tolerance < 0)
        bad("update_tolerance must be finite and >= 0");
    if (!std::isfinite(o.endpoint_weight) || !(o.endpoint_weight > 0))
        bad("endpoint_weight must be finite and > 0");
    if (o.solver == CurvatureFlowSolver::ceres && !gcf::ceres_step_solver().load())
        bad("solver ceres needs <tapeline/geodesic/curvature_flow_ceres.h> in the program "
            "(CMake target tapeline::geodesic_ceres)");
}

template <class TriangleMesh, class NamedParameters>
class GcfSetup {
public:
    using P = MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Index = MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>;
    using Point_3 = typename P::Point_3;
    using vertex_descriptor = typename GT::vertex_descriptor;

    static constexpr const char* kWhere = "geodesic_path (curvature flow)";

    GcfSetup(const TriangleMesh& tm, const NamedParameters& np)
        : vpm_(P::vertex_point_map(tm, np)),
          index_(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), kWhere) {
        check_triangle_mesh(tm, vpm_, index_.vertex_index_map(), index_.face_index_map(), kWhere);
        const std::size_t nv = index_.vertex_count(), nf = index_.face_count();
        if (nv >= gcf::kNone / 2 || 3 * nf >= gcf::kNone / 2)
            throw InvalidInput(std::string(kWhere) + ": the mesh is too large (32-bit indices)");
        if (nf == 0)
            throw InvalidInput(std::string(kWhere) + ": the mesh has no faces");
        mesh_ = gcf::Mesh(make_compact_mesh(tm, vpm_, index_.vertex_index_map(),
                                            index_.face_index_map(), kWhere));
        components_ = connected_components(tm, index_);
    }

    /// Position, a nearby vertex and the face of a user surface point (checked).
    gcf::Sample locate(const SurfacePoint<TriangleMesh>& sp, const char* what) const {
        gcf::Sample s;
        if (const auto* v = std::get_if<vertex_descriptor>(&sp)) {
            const std::size_t i = index_.checked(*v, what);
            if (mesh_.vf_start[i] == mesh_.vf_start[i + 1]) {
                std::ostringstream m;
                m << kWhere << ": " << what << " (vertex #" << i << ") has no incident face";
                throw InvalidInput(m.str());
            }
            s.p = mesh_.xyz[i];
            s.vertex = static_cast<std::uint32_t>(i);
            s.face = mesh_.vf[mesh_.vf_start[i]];
            return s;
        }
        const auto loc = index_.checked(std::get<FaceLocation<TriangleMesh>>(sp), what);
        const std::size_t f = index_.index(loc.first);
        s.p = gcf::Vec3::Zero();
        double best = -1;
        for (int k = 0; k < 3; ++k) {
            s.p += loc.second[k] * mesh_.xyz[mesh_.corner[3 * f + k]];
            if (loc.second[k] > best) {
                best = loc.second[k];
                s.vertex = mesh_.corner[3 * f + k];
            }
        }
        s.face = static_cast<std::uint32_t>(f);
        return s;
    }

    /// Nearest vertex of an arbitrary point by brute force, then the face it projects onto.
    gcf::Sample locate_point(const gcf::Vec3& p) const {
        gcf::Sample s;
        s.p = p;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < mesh_.vertex_count(); ++i) {
            if (mesh_.vf_start[i] == mesh_.vf_start[i + 1])
                continue;
            const double d = (mesh_.xyz[i] - p).squaredNorm();
            if (d < best) {
                best = d;
                s.vertex = static_cast<std::uint32_t>(i);
            }
        }
        gcf::project_around(mesh_, s);
        return s;
    }

    const gcf::Mesh& mesh() const { return mesh_; }
    const Index& index() const { return index_; }
    const Components& components() const { return components_; }

private:
    typename P::VertexPointMap vpm_;
    Index index_;
    gcf::Mesh mesh_;
    Components components_;
};

template <class Point>
Point to_point(const gcf::Vec3& v) {
    return Point(v.x(), v.y(), v.z());
}

template <class PointRange>
std::vector<gcf::Vec3> to_vec3s(const PointRange& range) {
    std::vector<gcf::Vec3> out;
    for (const auto& p : range)
        out.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    return out;
}

/// The corner of face f nearest to p.
inline std::uint32_t nearest_corner(const gcf::Mesh& m, std::uint32_t f, const gcf::Vec3& p) {
    std::uint32_t v = m.corner[3 * f];
    for (int k = 1; k < 3; ++k)
        if ((m.xyz[m.corner[3 * f + k]] - p).squaredNorm() < (m.xyz[v] - p).squaredNorm())
            v = m.corner[3 * f + k];
    return v;
}

/// Appends to `out` (ending with a.p) a join on the faces of two samples the on-face trace
/// (gcf::trace_on_faces) could not cut, so that the on-mesh output can never be shorter than the
/// polyhedral distance: a's face corner, the shortest edge path to b's face corner, and b (the
/// straightening that follows shortens it within its faces). A chord, which cuts through the solid
/// (measured on a MakeHuman body: up to 54 % short), only if even the edge graph does not join
/// them (`off_faces` set).
inline void join_by_edge_path(const gcf::Mesh& m, const gcf::Sample& a, const gcf::Sample& b,
                              std::vector<gcf::Vec3>& out, bool& off_faces) {
    if (a.face == gcf::kNone || b.face == gcf::kNone) {
        off_faces = true;
        out.push_back(b.p);
        return;
    }
    const std::uint32_t va = nearest_corner(m, a.face, a.p), vb = nearest_corner(m, b.face, b.p);
    const auto verts = gcf::edge_path(m, va, vb);
    if (verts.empty()) {
        off_faces = true;
        out.push_back(b.p);
        return;
    }
    for (const std::uint32_t v : verts)
        if ((m.xyz[v] - out.back()).norm() > 0)
            out.push_back(m.xyz[v]);
    if ((b.p - out.back()).norm() > 0)
        out.push_back(b.p);
}

/// The flow from an initial polyline (pts with vertex hints); endpoints are a and b.
template <class Point, class Setup>
CurvatureFlowPath<Point> run_flow(const Setup& setup, const gcf::Sample& a, const gcf::Sample& b,
                                  std::vector<gcf::Vec3> pts, std::vector<std::uint32_t> hints,
                                  const CurvatureFlowOptions& o, Clock::time_point t0) {
    const gcf::Mesh& m = setup.mesh();
    CurvatureFlowPath<Point> out;
    CurvatureFlowReport& r = out.report;
    r.vertices = m.vertex_count();
    r.faces = m.face_count();
    r.solver = to_string(o.solver);
    r.initial_length = gcf::polyline_length(pts);
    const std::vector<gcf::Vec3> initial = o.straighten ? pts : std::vector<gcf::Vec3>{};
    const double h = m.mean_edge > 0 ? m.mean_edge : 1.0;
    const double spacing = o.sample_spacing > 0 ? o.sample_spacing : h;
    std::size_t count = o.sample_count;
    if (count == 0)
        count = std::max<std::size_t>(
            3, static_cast<std::size_t>(std::llround(r.initial_length / spacing)) + 1);
    std::vector<gcf::Sample> s = gcf::resample(pts, hints, count);
    s.front() = a;
    s.back() = b;
    for (std::size_t i = 1; i + 1 < s.size(); ++i) {
        s[i].vertex = gcf::nearest_vertex_walk(m, s[i].p, s[i].vertex);
        gcf::project_around(m, s[i]);
    }
    r.samples = s.size();
    r.init_seconds = seconds_since(t0);
    const auto t1 = Clock::now();
    auto spacing_now = [&]() {
        double len = 0;
        for (std::size_t i = 1; i < s.size(); ++i)
            len += (s[i].p - s[i - 1].p).norm();
        return len / static_cast<double>(s.size() - 1);
    };
    auto scaled = [&](double k) {
        const double dh = spacing_now();
        return dh > 0 ? k / (dh * dh) * h : 0.0;
    };
    double kmax = 0, res = 0;
    gcf::curvature(m, s, o.interpolate_normals, kmax, res);
    r.status = "max_iterations";
    if (scaled(kmax) <= o.tolerance)
        r.status = "converged";
    // Full steps (options.step): a Levenberg-Marquardt safeguard (undo a step that raises the
    // residual, retry with a smaller step) was tried and converged less often: the residual after
    // re-projection is not the quantity the linearised step decreases.
    while (r.status != "converged" && r.iterations < o.max_iterations) {
        double upd = 0;
        if (!gcf::flow_step(m, s, o, o.step, upd))
            throw SolverFailure(std::string(Setup::kWhere) + ": the " + r.solver +
                                " solve failed at iteration " + std::to_string(r.iterations));
        ++r.iterations;
        r.max_update = upd;
        gcf::curvature(m, s, o.interpolate_normals, kmax, res);
        if (scaled(kmax) <= o.tolerance) {
            r.status = "converged";
            break;
        }
        if (upd <= o.update_tolerance * h) {
            r.status = "stalled";
            break;
        }
    }
    const double dh = spacing_now();
    r.max_geodesic_curvature = dh > 0 ? kmax / (dh * dh) : 0.0;
    r.scaled_max_geodesic_curvature = r.max_geodesic_curvature * h;
    r.residual = res;
    r.flow_seconds = seconds_since(t1);

    // Outputs. Endpoints are the given points exactly.
    std::vector<gcf::Vec3> smooth(s.size()), traced;
    for (std::size_t i = 0; i < s.size(); ++i)
        smooth[i] = (i == 0 || i + 1 == s.size()) ? s[i].p : gcf::phong_lift(m, s[i].face, s[i].p);
    traced.push_back(s.front().p);
    bool off_faces = false;  // a segment was left as a chord (no on-face connection at all)
    auto join = [&](const gcf::Sample& p, const gcf::Sample& q, std::vector<gcf::Vec3>& to) {
        join_by_edge_path(m, p, q, to, off_faces);
    };
    for (std::size_t i = 1; i < s.size(); ++i) {
        if (gcf::trace_on_faces(m, s[i - 1], s[i], traced, join) > 0)
            ++r.trace_fallbacks;
    }
    r.traced_length = gcf::polyline_length(traced);
    // The shortest path through the faces a polyline on the faces crosses, made locally shortest
    // across vertices; nullopt when the polyline is not on the faces or the result is longer.
    auto straightened = [&](const std::vector<gcf::Vec3>& on_faces, std::uint32_t first_face,
                            double than) -> std::optional<unfold::Straightened> {
        std::size_t bad = gcf::kNone;
        unfold::Strip strip;
        unfold::unfold_polyline(m, on_faces, UnfoldOptions{}, first_face, bad, &strip);
        if (bad != gcf::kNone || strip.faces.empty())
            return std::nullopt;
        const std::size_t cap = 4 * strip.faces.size() + 16;
        auto st = unfold::straighten(m, std::move(strip), on_faces.front(), on_faces.back(), cap);
        if (!(st.length <= than))
            return std::nullopt;
        return st;
    };
    if (o.straighten && traced.size() >= 2) {
        double best = off_faces ? std::numeric_limits<double>::infinity() : r.traced_length;
        std::optional<unfold::Straightened> st;
        if (!off_faces)
            st = straightened(traced, s.front().face, best);
        if (st)
            best = st->length;
        // The initial path straightened too: where the flow leaves the initial path's homotopy
        // class for a longer locally shortest one (sharp concave creases, whose averaged normals
        // tilt the tangent planes), the initial path's own geodesic is the shorter answer.
        if (initial.size() >= 2) {
            if (auto si = straightened(initial, s.front().face, best)) {
                if (si->length < best * (1 - 1e-12)) {
                    st = std::move(si);
                    r.on_mesh_from_initial = true;
                }
            }
        }
        if (st) {
            traced = std::move(st->points);
            off_faces = false;
            r.straightened = true;
            r.straighten_flips = st->flips;
            r.straighten_bends = st->bends;
        }
    }
    for (const auto& p : smooth)
        out.smooth.points.push_back(to_point<Point>(p));
    out.smooth.length = gcf::polyline_length(smooth);
    for (const auto& p : traced)
        out.on_mesh.points.push_back(to_point<Point>(p));
    out.on_mesh.length = gcf::polyline_length(traced);
    r.seconds = seconds_since(t0);
    return out;
}

}  // namespace internal

/// Reusable part of the flow: the checked index maps, the compact mesh arrays, the components and
/// the vertex frames (computed on first use and kept). Build once, query many pairs: a query then
/// costs one Dijkstra run and the iterations. Queries may run concurrently (see paths()).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class GeodesicPathSolver {
public:
    using Setup = internal::GcfSetup<TriangleMesh, NamedParameters>;  ///< the prepared mesh
    using Point_3 = typename Setup::Point_3;    ///< point type of the vertex point map
    using Result = CurvatureFlowPath<Point_3>;  ///< a path query's answer

    /// Checks the mesh and builds its compact arrays and components.
    ///
    /// \param tm the mesh; it must outlive the solver and stay unchanged.
    /// \param np the named parameters listed with the class.
    /// \throws TopologyError when a face is not a triangle.
    /// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
    ///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
    /// \throws InvalidInput also when the mesh has no faces or is beyond 32-bit indices.
    explicit GeodesicPathSolver(const TriangleMesh& tm,
                                const NamedParameters& np = CGAL::parameters::default_values())
        : setup_(tm, np) {}

    /// Path between two surface points, started from the Dijkstra edge path between their
    /// nearest corners. Endpoints in different components give empty paths (length +infinity)
    /// and status "unreachable". InvalidInput on bad options, points not on the mesh, from == to.
    ///
    /// \throws InvalidInput on bad options (non-finite or negative spacing, tolerances, step;
    ///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
    /// \throws InvalidInput when a point is not on the mesh, is a vertex without an incident face,
    ///         or when both points coincide.
    /// \throws SolverFailure when the linear solve of a flow step fails.
    Result path(const SurfacePoint<TriangleMesh>& from, const SurfacePoint<TriangleMesh>& to,
                const CurvatureFlowOptions& options = {}) const {
        const auto t0 = internal::Clock::now();
        internal::check_options(options);
        const auto a = setup_.locate(from, "the start point");
        const auto b = setup_.locate(to, "the end point");
        const auto& m = setup_.mesh();
        check_distinct(a, b);
        if (setup_.components().label[a.vertex] != setup_.components().label[b.vertex]) {
            Result out;
            out.report.vertices = m.vertex_count();
            out.report.faces = m.face_count();
            out.report.status = "unreachable";
            out.report.solver = to_string(options.solver);
            out.report.seconds = internal::seconds_since(t0);
            return out;
        }
        const auto fp = internal::gcf::face_path(m, a.vertex, b.vertex);
        std::vector<internal::gcf::Vec3> pts{a.p};
        std::vector<std::uint32_t> hints{a.vertex};
        for (std::size_t k = 0; k < fp.points.size(); ++k) {
            if ((fp.points[k] - pts.back()).norm() > 0) {
                pts.push_back(fp.points[k]);
                hints.push_back(fp.hints[k]);
            }
        }
        if ((b.p - pts.back()).norm() > 0) {
            pts.push_back(b.p);
            hints.push_back(b.vertex);
        }
        return internal::run_flow<Point_3>(setup_, a, b, std::move(pts), std::move(hints), options,
                                           t0);
    }

    /// Path started from a caller-given polyline (at least two points, in the same component).
    /// Its first and last points, projected onto the faces around their nearest vertex, are the
    /// endpoints.
    ///
    /// \tparam PointRange a range of points with x(), y(), z() convertible by CGAL::to_double.
    /// \throws InvalidInput on bad options (non-finite or negative spacing, tolerances, step;
    ///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
    /// \throws InvalidInput when the polyline has fewer than two points, a non-finite point, or
    ///         endpoints that project onto the same point.
    /// \throws SolverFailure when the linear solve of a flow step fails.
    template <class PointRange>
    Result path_from_polyline(const PointRange& initial,
                              const CurvatureFlowOptions& options = {}) const {
        const auto t0 = internal::Clock::now();
        internal::check_options(options);
        const auto& m = setup_.mesh();
        std::vector<internal::gcf::Vec3> pts;
        for (const auto& p : initial) {
            const internal::gcf::Vec3 v(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                        CGAL::to_double(p.z()));
            if (!v.allFinite())
                throw InvalidInput(std::string(Setup::kWhere) +
                                   ": the initial polyline has a non-finite point");
            pts.push_back(v);
        }
        if (pts.size() < 2)
            throw InvalidInput(std::string(Setup::kWhere) +
                               ": the initial polyline needs at least two points");
        // Both endpoints by a search over all vertices; the points between by walking from the
        // point before (a walk can stop at a local minimum of the distance on a fold, which
        // moved the end point of a path on a coarse mesh by 40 % of its length).
        const auto a = setup_.locate_point(pts.front());
        const auto b = setup_.locate_point(pts.back());
        std::vector<std::uint32_t> hints{a.vertex};
        for (std::size_t i = 1; i + 1 < pts.size(); ++i)
            hints.push_back(internal::gcf::nearest_vertex_walk(m, pts[i], hints.back()));
        hints.push_back(b.vertex);
        pts.front() = a.p;
        pts.back() = b.p;
        check_distinct(a, b);
        return internal::run_flow<Point_3>(setup_, a, b, std::move(pts), std::move(hints), options,
                                           t0);
    }

    /// Start and end point of one query of paths().
    using PointPair = std::pair<SurfacePoint<TriangleMesh>, SurfacePoint<TriangleMesh>>;

    /// Paths between many pairs of surface points, in the order of the pairs, each exactly what
    /// path(from, to, options) gives. The queries run in parallel (tbb::parallel_for when CGAL is
    /// linked with TBB, i.e. CGAL::TBB_support; else one after another): they share the mesh
    /// arrays read-only and its frame cache, which threads may fill at once. Every pair is checked
    /// before any work (InvalidInput naming the pair).
    ///
    /// \throws InvalidInput on bad options (non-finite or negative spacing, tolerances, step;
    ///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
    /// \throws InvalidInput when a point is not on the mesh, is a vertex without an incident face,
    ///         or when both points coincide.
    /// \throws SolverFailure when the linear solve of a flow step fails.
    std::vector<Result> paths(const std::vector<PointPair>& pairs,
                              const CurvatureFlowOptions& options = {}) const {
        internal::check_options(options);
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            try {
                const auto a = setup_.locate(pairs[k].first, "the start point");
                const auto b = setup_.locate(pairs[k].second, "the end point");
                check_distinct(a, b);
            } catch (const InvalidInput& e) {
                throw InvalidInput(std::string(e.what()) + " (pair #" + std::to_string(k) + ")");
            }
        }
        std::vector<Result> out(pairs.size());
#ifdef CGAL_LINKED_WITH_TBB
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 1),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t k = r.begin(); k != r.end(); ++k)
                                  out[k] = path(pairs[k].first, pairs[k].second, options);
                          });
#else
        for (std::size_t k = 0; k < pairs.size(); ++k)
            out[k] = path(pairs[k].first, pairs[k].second, options);
#endif
        return out;
    }

    /// Number of mesh vertices.
    std::size_t vertex_count() const {
        return setup_.mesh().vertex_count();
    }
    /// The checked index maps and the compact mesh arrays the queries run on.
    const Setup& setup() const {
        return setup_;
    }
    /// Mean edge length of the mesh: the default sample spacing.
    double mean_edge_length() const {
        return setup_.mesh().mean_edge;
    }

    /// The faces crossed by a path on this mesh (e.g. result.on_mesh.points) unfolded into the
    /// plane (see unfold_path in unfold.h).
    ///
    /// \tparam PointRange a range of points with x(), y(), z() convertible by CGAL::to_double.
    /// \throws InvalidInput on a bad tolerance, a point off the mesh or fewer than two distinct
    ///         points.
    template <class PointRange>
    UnfoldedPath unfold(const PointRange& path, const UnfoldOptions& options = {}) const {
        return internal::unfold::unfold_checked(setup_.mesh(), internal::to_vec3s(path), options,
                                                "unfold_path");
    }

private:
    void check_distinct(const internal::gcf::Sample& a, const internal::gcf::Sample& b) const {
        if ((a.p - b.p).norm() <= 1e-12 * setup_.mesh().mean_edge)
            throw InvalidInput(
                std::string(Setup::kWhere) +
                ": the start and end points coincide; a path needs two distinct points");
    }

    Setup setup_;
};

/// One-shot: geodesic path between two surface points by geodesic curvature flow (see
/// GeodesicPathSolver::path). The report's init_seconds include the mesh preparation.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
/// \throws InvalidInput also when the mesh has no faces or is beyond 32-bit indices.
/// \throws InvalidInput on bad options (non-finite or negative spacing, tolerances, step;
///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
/// \throws InvalidInput when a point is not on the mesh, is a vertex without an incident face,
///         or when both points coincide.
/// \throws SolverFailure when the linear solve of a flow step fails.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
CurvatureFlowPath<typename internal::MeshParameters<TriangleMesh, NamedParameters>::Point_3>
geodesic_path(const TriangleMesh& tm, const SurfacePoint<TriangleMesh>& from,
              const SurfacePoint<TriangleMesh>& to, const CurvatureFlowOptions& options = {},
              const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = internal::Clock::now();
    internal::check_options(options);
    const GeodesicPathSolver<TriangleMesh, NamedParameters> solver(tm, np);
    const double prep = internal::seconds_since(t0);
    auto out = solver.path(from, to, options);
    out.report.init_seconds += prep;
    out.report.seconds += prep;
    return out;
}

/// One-shot, started from a caller-given polyline (see GeodesicPathSolver::path_from_polyline).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam Point a point type with x(), y(), z() convertible by CGAL::to_double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
/// \throws InvalidInput also when the mesh has no faces or is beyond 32-bit indices.
/// \throws InvalidInput on bad options (non-finite or negative spacing, tolerances, step;
///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
/// \throws InvalidInput when the polyline has fewer than two points, a non-finite point, or
///         endpoints that project onto the same point.
/// \throws SolverFailure when the linear solve of a flow step fails.
template <class TriangleMesh, class Point,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
CurvatureFlowPath<typename internal::MeshParameters<TriangleMesh, NamedParameters>::Point_3>
geodesic_path(const TriangleMesh& tm, const std::vector<Point>& initial,
              const CurvatureFlowOptions& options = {},
              const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = internal::Clock::now();
    internal::check_options(options);
    const GeodesicPathSolver<TriangleMesh, NamedParameters> solver(tm, np);
    const double prep = internal::seconds_since(t0);
    auto out = solver.path_from_polyline(initial, options);
    out.report.init_seconds += prep;
    out.report.seconds += prep;
    return out;
}

/// Single-source distances by geodesic curvature flow (the thesis' Algorithms 1 and 2): vertices
/// are visited in the order of a priority queue on the tentative distance min over visited
/// neighbours u of d(u) + |uv| (continuous Dijkstra); the source's 1-ring gets straight edges;
/// every other vertex w starts from the polyline of the visited neighbour u whose last tangent
/// continues most straightly into the edge (u, w), with the edge appended (subdivided at the
/// sample spacing), which is then flowed (whole, or its last `window` samples); with
/// options.shortest_parent every visited neighbour is continued and the shortest result kept. d(w)
/// is the length of the resulting sample polyline (Phong-lifted by default, see the options).
/// Writes every vertex (+infinity outside the source's component). InvalidInput on bad options or a
/// source that is not a vertex of the mesh with an incident face.
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
/// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
/// \throws InvalidInput also when the mesh has no faces or is beyond 32-bit indices.
/// \throws InvalidInput on bad options (`sample_spacing`, `repair_steiner_points`,
///         `repair_graph_margin`, and the flow's: non-finite or negative spacing, tolerances, step;
///         `sample_count` 1 or 2; the Ceres solver without curvature_flow_ceres.h).
/// \throws InvalidInput when `source` is not a vertex of the mesh with an incident face.
/// \throws SolverFailure when a flow solve fails or a distance is NaN; `distances` is left
///         untouched then.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
CurvatureFlowDistanceReport gcf_distances(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    VertexDistanceMap distances, const CurvatureFlowDistanceOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = internal::Clock::now();
    internal::check_options(options.flow);
    if (!std::isfinite(options.sample_spacing) || options.sample_spacing < 0)
        throw InvalidInput(
            "gcf_distances: sample_spacing must be finite and >= 0 (0 = the mean edge length)");
    if (options.repair_steiner_points < -1)
        throw InvalidInput(
            "gcf_distances: repair_steiner_points must be -1 (automatic), 0 (none) or positive");
    if (!(options.repair_graph_margin == -1 ||
          (options.repair_graph_margin >= 0 && options.repair_graph_margin <= 1)))
        throw InvalidInput(
            "gcf_distances: repair_graph_margin must be -1 (automatic) or in [0, 1]");
    // One set-up for the propagation and the repair's two-point paths.
    using Solver = GeodesicPathSolver<TriangleMesh, NamedParameters>;
    const Solver solver(tm, np);
    const auto& setup = solver.setup();
    const auto a = setup.locate(SurfacePoint<TriangleMesh>(source), "the source");
    const auto& m = setup.mesh();
    CurvatureFlowDistanceReport r;
    r.vertices = m.vertex_count();
    r.faces = m.face_count();
    r.prepare_seconds = internal::seconds_since(t0);
    const double h = m.mean_edge > 0 ? m.mean_edge : 1.0;
    r.sample_spacing = options.sample_spacing > 0 ? options.sample_spacing : h;
    internal::gcf::PropagateParams pp;
    pp.window = options.window;
    pp.spacing = r.sample_spacing;
    pp.smooth = options.smooth_length;
    pp.traced = options.polyhedral_length;
    pp.straighten = options.polyhedral_length;
    pp.shortest_parent = options.shortest_parent;
    pp.field_anchor = options.anchor == WindowAnchor::field;
    pp.near_source_samples = options.near_source_samples;
    pp.anchor_slides = options.anchor_slides;
    pp.cut_locus_guard = options.cut_locus_guard;
    pp.window_max_iterations = options.window > 0 ? options.window_max_iterations : 0;
    auto f = internal::gcf::propagate(m, a.vertex, pp, options.flow);
    f.counts.write(r);
    r.stored_samples = f.stored_samples;
    r.epsilon = f.epsilon;
    r.max_faces = f.max_faces;
    r.error_bound = f.epsilon * static_cast<double>(f.max_faces) * m.mean_edge;
    if (!options.smooth_length && options.repair_tolerance >= 0 && options.repair_rounds > 0) {
        // Vertices whose distance differs from what their neighbours' distances imply, or from
        // their Steiner-graph distance (above it, or far below it), are re-solved as two-point
        // paths from the source, started from a fresh search (path()), from the best neighbour's
        // path with the vertex appended, from the graph's path and from the field's descent path
        // (path_from_polyline()). A straightened on-mesh length is a path on the faces (never
        // below the exact distance): kept where shorter, where the distance was far below the
        // graph's, or where it was too short and the path agrees better with the neighbours
        // (repaired_distance).
        const auto t1 = internal::Clock::now();
        std::vector<char> skip(m.vertex_count(), 0);
        skip[a.vertex] = 1;
        for (std::uint32_t k = m.vv_start[a.vertex]; k < m.vv_start[a.vertex + 1]; ++k)
            skip[m.vv[k]] = 1;  // the 1-ring: straight edges, exact on the faces
        Progress progress("gcf distances: repaired vertices");
        CurvatureFlowOptions repair_flow;
        repair_flow.max_iterations = options.repair_flow_iterations;
        // Each vertex is re-solved once (its shortest path length is kept); every round checks
        // all vertices again with the distances as they stand, so a vertex whose neighbours were
        // mended after it was solved is judged again against them.
        std::vector<double> solved(m.vertex_count(), std::numeric_limits<double>::quiet_NaN());
        std::optional<internal::gcf::SteinerTree> graph;
        const int points = options.repair_steiner_points >= 0 ? options.repair_steiner_points
                           : m.vertex_count() < 50000         ? 8
                                                              : 3;
        if (points > 0) {
            const auto tg0 = internal::Clock::now();
            // 32 points on the edges within 12 mean edge lengths of the source: there the graph's
            // relative error is largest (up to 4 % with 8 points at 2-10 edges from the source on
            // blub and bunny; 0.8 % with 32), and it must stay below the margin.
            graph.emplace(m, a.vertex, static_cast<std::uint32_t>(points), 32u, 12 * m.mean_edge);
            r.repair_graph_seconds = internal::seconds_since(tg0);
        }
        const double margin = options.repair_graph_margin >= 0 ? options.repair_graph_margin
                              : points >= 8                    ? 0.01
                                                               : 0.03;
        // Far below the graph distance (by more than the graph's own error): no path on the faces
        // is that short, whatever the neighbours say.
        auto far_below = [&](std::uint32_t v) {
            return graph && f.d[v] < graph->distance(v) * (1 - margin);
        };
        for (std::size_t round = 0; round < options.repair_rounds; ++round) {
            auto flagged =
                internal::gcf::suspicious_vertices(m, f.d, skip, options.repair_tolerance);
            if (graph) {
                // Above the length of a path on the faces by more than the tolerance: too long
                // whatever the neighbours say; far below it: see far_below. (Without the tolerance,
                // on an icosphere whose graph paths along the grid lines are as long as the
                // geodesics, 1e-7 above the graph flagged most vertices: level 7 took 99 s instead
                // of 12.)
                std::vector<char> in(m.vertex_count(), 0);
                for (const std::uint32_t v : flagged)
                    in[v] = 1;
                for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
                    if (!skip[v] && !in[v] &&
                        (f.d[v] > graph->distance(v) * (1 + options.repair_tolerance) ||
                         far_below(v))) {
                        flagged.push_back(v);
                        r.repair_graph_flagged += std::isnan(solved[v]) ? 1 : 0;
                    }
                }
            }
            std::vector<std::uint32_t> fresh;
            for (const std::uint32_t v : flagged)
                if (std::isnan(solved[v]))
                    fresh.push_back(v);
            auto solve = [&](std::uint32_t v) {
                double best = std::numeric_limits<double>::infinity();
                auto keep = [&](const typename Solver::Result& p) {
                    if (p.on_mesh.found())
                        best = std::min(best, p.on_mesh.length);
                };
                keep(solver.path(SurfacePoint<TriangleMesh>(source),
                                 SurfacePoint<TriangleMesh>(setup.index().vertex(v)), repair_flow));
                // The geodesic of the neighbour u that the distances say is the best way in (the
                // smallest d(u) + |uv|), with v appended: where the fresh search and the descent
                // both start in a longer class (coarse meshes, paths through saddle vertices).
                const std::uint32_t via = internal::gcf::entry_neighbour(m, f.d, v, a.vertex);
                if (via != internal::gcf::kNone) {
                    const auto pu = solver.path(
                        SurfacePoint<TriangleMesh>(source),
                        SurfacePoint<TriangleMesh>(setup.index().vertex(via)), repair_flow);
                    if (pu.on_mesh.found()) {
                        auto poly = pu.on_mesh.points;
                        poly.push_back(internal::to_point<typename Solver::Point_3>(m.xyz[v]));
                        keep(solver.path_from_polyline(poly, repair_flow));
                    }
                }
                if (graph) {
                    std::vector<typename Solver::Point_3> poly;
                    for (const auto& p : graph->path_to(v))
                        poly.push_back(internal::to_point<typename Solver::Point_3>(p));
                    if (poly.size() >= 2)
                        keep(solver.path_from_polyline(poly, repair_flow));
                }
                if (graph)  // the graph path is a path on the faces too
                    best = std::min(best, graph->distance(v));
                const auto down = internal::gcf::descent_path(m, f.d, v, a.vertex);
                if (down.size() >= 2) {
                    std::vector<typename Solver::Point_3> poly;
                    for (const std::uint32_t u : down)
                        poly.push_back(internal::to_point<typename Solver::Point_3>(m.xyz[u]));
                    keep(solver.path_from_polyline(poly, repair_flow));
                }
                solved[v] = best;
                progress.advance();
            };
#ifdef CGAL_LINKED_WITH_TBB
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, fresh.size(), 1),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  for (std::size_t k = range.begin(); k != range.end(); ++k)
                                      solve(fresh[k]);
                              });
#else
            for (const std::uint32_t v : fresh)
                solve(v);
#endif
            r.repair_checked += fresh.size();
            std::vector<double> update(flagged.size());
            for (std::size_t k = 0; k < flagged.size(); ++k)
                update[k] = internal::gcf::face_update(m, f.d, flagged[k]);
            std::size_t changed = 0;
            for (std::size_t k = 0; k < flagged.size(); ++k) {
                const std::uint32_t v = flagged[k];
                const double d = far_below(v) && std::isfinite(solved[v])
                                     ? solved[v]
                                     : internal::gcf::repaired_distance(
                                           f.d[v], solved[v], update[k], options.repair_tolerance);
                if (d != f.d[v]) {
                    f.d[v] = d;
                    ++changed;
                }
            }
            r.repair_improved += changed;
            if (changed == 0)
                break;
        }
        r.repair_seconds = internal::seconds_since(t1);
    }
    r.unreachable = internal::write_distances(f.d, setup.index(), distances, "gcf_distances");
    r.reached = r.vertices - r.unreachable;
    if (r.solver_failures > 0)
        r.status = "solver_failure";
    else if (r.max_iterations > 0)
        r.status = "max_iterations";
    r.method = options.window == 0                      ? "gcf_exact"
               : options.anchor == WindowAnchor::prefix ? "gcf_window_thesis"
                                                        : "gcf_window";
    r.sources = 1;
    r.seconds = internal::seconds_since(t0);
    r.query_seconds = r.seconds - r.prepare_seconds;
    return r;
}

}  // namespace tapeline::geodesic
