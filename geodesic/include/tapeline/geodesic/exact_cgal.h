// Exact polyhedral geodesic distances and shortest paths through CGAL's
// `Surface_mesh_shortest_path`, which implements the improved Chen-Han algorithm of
// S.-Q. Xin and G.-J. Wang, "Improving Chen and Han's algorithm on the discrete geodesic
// problem", ACM TOG 28(4), 2009 (sequence tree of windows; exact distances on the polyhedron).
//
// Guards on top of CGAL 5.5.1 (see geodesic/README.md):
//  - isolated vertices are never handed to SMSP (CGAL#5280: segfault); they get +infinity, or 0
//    when they are themselves a source;
//  - vertices on other components than the sources get +infinity (SMSP answers -1);
//  - face locations are cleaned (clamped, snapped, renormalised) and a location on a corner is
//    turned into that vertex, because SMSP classifies locations by exact comparison (CGAL#9646);
//  - a source on an edge is moved 1e-12 into its face: 5.5.1 roots edge sources at the mirror
//    image of the point along the edge (see off_the_edge below);
//  - border sources: CGAL#6681 (wrong distances from a source on a border edge) is fixed in
//    5.5.1 (PR #6739); the tests check border sources against the Euclidean distance on a flat
//    mesh so that a regression shows up;
//  - path polylines lose consecutive duplicate points (CGAL#8979 reports duplicates).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/Surface_mesh_shortest_path/Surface_mesh_shortest_path.h>
#include <CGAL/Surface_mesh_shortest_path/Surface_mesh_shortest_path_traits.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <variant>
#include <vector>

namespace tapeline::geodesic {

/// Exact distances from one source set; the sequence tree is built once in the constructor and
/// then answers distance and path queries to any vertex or face location.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `HalfedgeListGraph`, `VertexListGraph`
///         and `EdgeListGraph` (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a
///         triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map`, `halfedge_index_map` and `face_index_map`
///         (`ReadablePropertyMap`s onto [0, n)), `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class ExactCgalSolver {
    using P = internal::MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Kernel = typename P::GeomTraits;
    using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, TriangleMesh>;
    using Smsp =
        CGAL::Surface_mesh_shortest_path<Traits, typename P::VertexIndexMap,
                                         typename P::HalfedgeIndexMap, typename P::FaceIndexMap,
                                         typename P::VertexPointMap>;
    using Index =
        internal::MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>;

public:
    using vertex_descriptor = typename GT::vertex_descriptor;  ///< a vertex of the mesh
    using face_descriptor = typename GT::face_descriptor;      ///< a face of the mesh
    using Point_3 = typename Kernel::Point_3;                  ///< point type of the kernel
    using Path = GeodesicPath<Point_3>;                        ///< a polyline and its length

    /// Checks the mesh and the sources, then builds the sequence tree.
    ///
    /// \param tm the mesh; it must outlive the solver and stay unchanged.
    /// \param sources vertices and face locations of `tm`.
    /// \param options the method's options (ExactCgalOptions).
    /// \param np the named parameters listed with the class.
    /// \throws TopologyError when a face is not a triangle.
    /// \throws InvalidInput on a non-finite coordinate or a vertex, halfedge or face index map
    ///         that is not a bijection onto [0, n) (a Surface_mesh with removed elements needs
    ///         collect_garbage()).
    /// \throws InvalidInput also when `sources` is empty or holds a vertex or face location
    ///         that is not on the mesh.
    ExactCgalSolver(const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources,
                    const ExactCgalOptions& options = {},
                    const NamedParameters& np = CGAL::parameters::default_values())
        : tm_(tm),
          vpm_(P::vertex_point_map(tm, np)),
          index_(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), "exact_cgal"),
          options_(options) {
        internal::check_triangle_mesh(tm, vpm_, index_.vertex_index_map(), index_.face_index_map(),
                                      "exact_cgal");
        check_halfedge_index(P::halfedge_index_map(tm, np));
        if (sources.empty())
            throw InvalidInput("exact_cgal: the source set is empty");
        components_ = internal::connected_components(tm, index_);
        report_.method = "exact_cgal";
        report_.vertices = index_.vertex_count();
        report_.faces = index_.face_count();
        report_.sources = sources.size();
        report_.components = components_.count;

        // Check every source before any work.
        std::vector<vertex_descriptor> vsrc;
        std::vector<FaceLocation<TriangleMesh>> fsrc;
        for (auto v : sources.vertices) {
            index_.checked(v, "source vertex");
            vsrc.push_back(v);
        }
        for (const auto& l : sources.locations) {
            const auto clean = index_.checked(l, "source face location");
            const auto corner = index_.corner_vertex(clean);
            if (corner != GT::null_vertex())
                vsrc.push_back(corner);
            else
                fsrc.push_back(off_the_edge(clean));
        }
        isolated_source_.assign(index_.vertex_count(), 0);
        std::vector<vertex_descriptor> smsp_vertices;
        for (auto v : vsrc) {
            const std::size_t i = index_.index(v);
            if (components_.isolated[i])
                isolated_source_[i] = 1;  // never given to SMSP (CGAL#5280)
            else
                smsp_vertices.push_back(v);
        }

        const auto t0 = internal::Clock::now();
        smsp_ = std::make_unique<Smsp>(tm, index_.vertex_index_map(), P::halfedge_index_map(tm, np),
                                       index_.face_index_map(), vpm_, Traits(P::geom_traits(np)));
        report_.prepare_seconds = internal::seconds_since(t0);

        const auto t1 = internal::Clock::now();
        has_smsp_sources_ = !smsp_vertices.empty() || !fsrc.empty();
        for (auto v : smsp_vertices)
            smsp_->add_source_point(v);
        for (const auto& l : fsrc)
            smsp_->add_source_point(l.first, l.second);
        if (has_smsp_sources_)
            smsp_->build_sequence_tree();
        build_seconds_ = internal::seconds_since(t1);
        report_.query_seconds = build_seconds_;
        report_.seconds = report_.prepare_seconds + report_.query_seconds;
    }

    /// Single-vertex source; throws as the source-set constructor.
    ExactCgalSolver(const TriangleMesh& tm, vertex_descriptor source,
                    const ExactCgalOptions& options = {},
                    const NamedParameters& np = CGAL::parameters::default_values())
        : ExactCgalSolver(tm, SourceSet<TriangleMesh>(source), options, np) {}

    /// Writes the exact distance of every vertex (+infinity when unreachable) into `distances`.
    /// report().query_seconds = sequence tree + this reading.
    ///
    /// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
    ///         value double.
    /// \throws SolverFailure when a distance is NaN; `distances` is left untouched then.
    template <class VertexDistanceMap>
    DistanceReport distances(VertexDistanceMap distances) {
        const auto t0 = internal::Clock::now();
        std::vector<double> d(index_.vertex_count(), internal::kInfinity);
        for (std::size_t i = 0; i < d.size(); ++i)
            d[i] = vertex_distance(i);
        report_.unreachable = internal::write_distances(d, index_, distances, "exact_cgal");
        report_.query_seconds = build_seconds_ + internal::seconds_since(t0);
        report_.seconds = report_.prepare_seconds + report_.query_seconds;
        return report_;
    }

    /// Exact distance from the source set to a vertex or face location (+infinity if unreachable).
    ///
    /// \throws InvalidInput when `target` is not a vertex or face location of the mesh.
    double distance_to(const SurfacePoint<TriangleMesh>& target) const {
        const auto t = resolve(target);
        if (t.vertex != GT::null_vertex())
            return vertex_distance(index_.index(t.vertex));
        if (!has_smsp_sources_)
            return internal::kInfinity;
        const double d = CGAL::to_double(
            smsp_->shortest_distance_to_source_points(t.loc.first, t.loc.second).first);
        return d < 0 ? internal::kInfinity : d;
    }

    /// Shortest path from the nearest source to `target`, as a polyline from the source point to
    /// the target; length is the polyline length. Unreachable: no points, length +infinity.
    ///
    /// \throws InvalidInput when `target` is not a vertex or face location of the mesh.
    Path path_to(const SurfacePoint<TriangleMesh>& target) const {
        const auto t = resolve(target);
        Path path;
        if (t.vertex != GT::null_vertex()) {
            const std::size_t i = index_.index(t.vertex);
            if (components_.isolated[i]) {
                if (isolated_source_[i]) {
                    path.points.push_back(get(vpm_, t.vertex));
                    path.length = 0;
                }
                return path;
            }
        }
        if (!has_smsp_sources_)
            return path;
        std::vector<Point_3> pts;
        const auto result =
            t.vertex != GT::null_vertex()
                ? smsp_->shortest_path_points_to_source_points(t.vertex, std::back_inserter(pts))
                : smsp_->shortest_path_points_to_source_points(t.loc.first, t.loc.second,
                                                               std::back_inserter(pts));
        if (CGAL::to_double(result.first) < 0 || pts.empty())
            return path;
        // SMSP lists the points from the query back to the source.
        std::reverse(pts.begin(), pts.end());
        pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
        path.points = std::move(pts);
        path.length = 0;
        for (std::size_t k = 1; k < path.points.size(); ++k)
            path.length += std::sqrt(
                CGAL::to_double(CGAL::squared_distance(path.points[k - 1], path.points[k])));
        return path;
    }

    /// Sizes, unreachable count and timings.
    const DistanceReport& report() const { return report_; }
    /// The options the solver runs with.
    const ExactCgalOptions& options() const { return options_; }

private:
    struct Resolved {
        vertex_descriptor vertex = GT::null_vertex();
        FaceLocation<TriangleMesh> loc;
    };

    Resolved resolve(const SurfacePoint<TriangleMesh>& target) const {
        Resolved r;
        if (const auto* v = std::get_if<vertex_descriptor>(&target)) {
            index_.checked(*v, "target vertex");
            r.vertex = *v;
        } else {
            r.loc = index_.checked(std::get<FaceLocation<TriangleMesh>>(target),
                                   "target face location");
            r.vertex = index_.corner_vertex(r.loc);
        }
        return r;
    }

    // CGAL 5.5.1 roots a source that lies on an edge at the mirror image of the point along the
    // edge: expand_root passes the weight of the edge's source vertex where face_location(he, t)
    // expects the weight of its target (measured on a flat square: 0.05 off for a point at 0.3
    // of an edge of length 0.125). A point strictly inside the face takes the face-root path,
    // which is right, so an edge source is moved into its face by kEdgeNudge of the barycentric
    // range (a displacement of ~1e-12 h, far below every tolerance of the method).
    static FaceLocation<TriangleMesh> off_the_edge(FaceLocation<TriangleMesh> loc) {
        constexpr double kEdgeNudge = 1e-12;
        int zeros = 0;
        for (double c : loc.second)
            zeros += c == 0.0 ? 1 : 0;
        if (zeros != 1)
            return loc;
        for (double& c : loc.second)
            c = c == 0.0 ? kEdgeNudge : c * (1.0 - kEdgeNudge);
        return loc;
    }

    double vertex_distance(std::size_t i) const {
        if (components_.isolated[i])
            return isolated_source_[i] ? 0.0 : internal::kInfinity;
        if (!has_smsp_sources_)
            return internal::kInfinity;
        const double d =
            CGAL::to_double(smsp_->shortest_distance_to_source_points(index_.vertex(i)).first);
        return d < 0 ? internal::kInfinity : d;
    }

    template <class HalfedgeIndexMap>
    void check_halfedge_index(HalfedgeIndexMap him) const {
        std::vector<char> seen(num_halfedges(tm_), 0);
        for (auto h : halfedges(tm_)) {
            const std::size_t i = static_cast<std::size_t>(get(him, h));
            if (i >= seen.size() || seen[i])
                throw InvalidInput(
                    "exact_cgal: the halfedge index map is not a bijection onto [0, "
                    "num_halfedges) (a Surface_mesh with removed elements needs "
                    "collect_garbage())");
            seen[i] = 1;
        }
    }

    const TriangleMesh& tm_;
    typename P::VertexPointMap vpm_;
    Index index_;
    ExactCgalOptions options_;
    internal::Components components_;
    std::vector<char> isolated_source_;
    // SMSP's queries are non-const (they may rebuild the tree); the tree is built once in the
    // constructor, so the const query interface of this class is sound.
    std::unique_ptr<Smsp> smsp_;
    bool has_smsp_sources_ = false;
    double build_seconds_ = 0;
    DistanceReport report_;
};

/// One-shot exact distances from a source set into `distances` (+infinity when unreachable).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `HalfedgeListGraph`, `VertexListGraph`
///         and `EdgeListGraph` (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a
///         triangle.
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
///         value double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map`, `halfedge_index_map` and `face_index_map`
///         (`ReadablePropertyMap`s onto [0, n)), `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or a vertex, halfedge or face index map
///         that is not a bijection onto [0, n) (a Surface_mesh with removed elements needs
///         collect_garbage()).
/// \throws InvalidInput also when `sources` is empty or holds a vertex or face location
///         that is not on the mesh.
/// \throws SolverFailure when a distance is NaN; `distances` is left untouched then.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport exact_cgal_distances(
    const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources, VertexDistanceMap distances,
    const ExactCgalOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    ExactCgalSolver<TriangleMesh, NamedParameters> solver(tm, sources, options, np);
    return solver.distances(distances);
}

/// One-shot exact distances from one vertex; as the source-set overload.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport exact_cgal_distances(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    VertexDistanceMap distances, const ExactCgalOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    return exact_cgal_distances(tm, SourceSet<TriangleMesh>(source), distances, options, np);
}

/// Exact shortest path between two surface points (vertices or face locations), as a polyline
/// from `from` to `to` (no points and length +infinity when `to` is unreachable).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `HalfedgeListGraph`, `VertexListGraph`
///         and `EdgeListGraph` (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a
///         triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map`, `halfedge_index_map` and `face_index_map`
///         (`ReadablePropertyMap`s onto [0, n)), `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or a vertex, halfedge or face index map
///         that is not a bijection onto [0, n) (a Surface_mesh with removed elements needs
///         collect_garbage()).
/// \throws InvalidInput also when `from` or `to` is not a vertex or face location of the mesh.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
typename ExactCgalSolver<TriangleMesh, NamedParameters>::Path exact_cgal_path(
    const TriangleMesh& tm, const SurfacePoint<TriangleMesh>& from,
    const SurfacePoint<TriangleMesh>& to,
    const NamedParameters& np = CGAL::parameters::default_values()) {
    ExactCgalSolver<TriangleMesh, NamedParameters> solver(tm, SourceSet<TriangleMesh>(from),
                                                          ExactCgalOptions{}, np);
    return solver.path_to(to);
}

}  // namespace tapeline::geodesic
