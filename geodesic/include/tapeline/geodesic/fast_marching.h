// Fast marching on triangle meshes: R. Kimmel and J. A. Sethian, "Computing geodesic paths on
// manifolds", PNAS 95(15), 8431-8435, 1998 — the first-order upwind solution of the eikonal
// equation |∇d| = 1 on the mesh, one vertex at a time in order of distance as in Dijkstra's
// algorithm, each vertex updated from its faces by a plane wave through two final corners, and
// obtuse corners split by unfolding (internal/fmm_engine.h has the scheme).
//
// Approximate: a plane wave through two corners cannot follow the wavefront's curvature near a
// point source, so the error falls a little slower than the edge length (mean relative error
// against the great-circle distance 2.0e-2, 1.5e-2, 9.6e-3 on icospheres of levels 3, 4, 5). It
// never exceeds Dijkstra's edge-path distance (every vertex's one-vertex updates are among its
// candidates); it can fall below the exact polyhedral distance (on a torus's saddles). A baseline
// for the time/error front: one pass over the mesh, no factorisation.
#pragma once

#include <tapeline/core/compact_mesh.h>
#include <tapeline/core/errors.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/internal/fmm_engine.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/sources.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::geodesic {

/// Fast marching distances; the mesh is prepared once (edge lengths, corner angles, the virtual
/// edges of obtuse corners) and any number of source sets are then marched from it.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class FastMarchingSolver {
    using P = internal::MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Index =
        internal::MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>;
    static constexpr const char* kWhere = "fast_marching";

public:
    using vertex_descriptor = typename GT::vertex_descriptor;  ///< a vertex of the mesh

    /// Checks the mesh and prepares it.
    ///
    /// \param tm the mesh; it must outlive the solver and stay unchanged.
    /// \param options obtuse-corner unfolding.
    /// \param np the named parameters listed with the class.
    /// \throws TopologyError when a face is not a triangle.
    /// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
    ///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()) or a
    ///         mesh beyond 32-bit indices.
    explicit FastMarchingSolver(const TriangleMesh& tm, const FastMarchingOptions& options = {},
                                const NamedParameters& np = CGAL::parameters::default_values())
        : tm_(tm),
          vpm_(P::vertex_point_map(tm, np)),
          index_(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), kWhere),
          options_(options) {
        const auto t0 = internal::Clock::now();
        internal::check_triangle_mesh(tm, vpm_, index_.vertex_index_map(), index_.face_index_map(),
                                      kWhere);
        compact_ = std::make_unique<CompactMesh>(make_compact_mesh(
            tm, vpm_, index_.vertex_index_map(), index_.face_index_map(), kWhere));
        mesh_ = std::make_unique<internal::fmm::Mesh>(*compact_, options.unfold_obtuse,
                                                      options.max_unfold_faces);
        report_.method = kWhere;
        report_.vertices = index_.vertex_count();
        report_.faces = index_.face_count();
        report_.components = internal::connected_components(tm, index_).count;
        report_.obtuse_corners = mesh_->obtuse_corners();
        report_.virtual_edges = mesh_->virtual_edges();
        report_.unsplit_obtuse = options.unfold_obtuse
                                     ? report_.obtuse_corners - report_.virtual_edges
                                     : report_.obtuse_corners;
        report_.prepare_seconds = internal::seconds_since(t0);
        report_.seconds = report_.prepare_seconds;
    }

    /// Distances from a source set into `distances` (+infinity where unreachable). A vertex
    /// source is at 0; a face location seeds the corners of its face with their straight-line
    /// distance from it (exact within the face).
    ///
    /// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
    ///         value double.
    /// \throws InvalidInput when `sources` is empty or holds a vertex or face location that is
    ///         not on the mesh (checked before any work).
    /// \throws SolverFailure when a distance is NaN; `distances` is left untouched then.
    template <class VertexDistanceMap>
    FastMarchingReport distances(const SourceSet<TriangleMesh>& sources,
                                 VertexDistanceMap distances) const {
        if (sources.empty())
            throw InvalidInput(std::string(kWhere) + ": the source set is empty");
        std::vector<double> d(index_.vertex_count(), internal::kInfinity);
        internal::seed_corners(tm_, vpm_, index_, sources, d);
        const auto t0 = internal::Clock::now();
        const internal::fmm::RunStats stats = internal::fmm::run(*mesh_, d);
        FastMarchingReport report = report_;
        report.sources = sources.size();
        report.face_updates = stats.face_updates;
        report.edge_updates = stats.edge_updates;
        report.unreachable = internal::write_distances(d, index_, distances, kWhere);
        report.query_seconds = internal::seconds_since(t0);
        report.seconds = report.prepare_seconds + report.query_seconds;
        return report;
    }

    /// Distances from one vertex; as the source-set overload.
    template <class VertexDistanceMap>
    FastMarchingReport distances(vertex_descriptor source, VertexDistanceMap distances) const {
        return this->distances(SourceSet<TriangleMesh>(source), distances);
    }

    /// Sizes, obtuse corners and preparation time.
    const FastMarchingReport& report() const { return report_; }
    /// The options the solver runs with.
    const FastMarchingOptions& options() const { return options_; }

private:
    const TriangleMesh& tm_;
    typename P::VertexPointMap vpm_;
    Index index_;
    FastMarchingOptions options_;
    std::unique_ptr<CompactMesh> compact_;  // the engine's mesh keeps a reference to it
    std::unique_ptr<internal::fmm::Mesh> mesh_;
    FastMarchingReport report_;
};

/// Fast marching distances from a source set into `distances`: prepares the mesh and marches
/// once (report.prepare_seconds and report.query_seconds tell the two apart). As
/// FastMarchingSolver's constructor and distances().
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
FastMarchingReport fast_marching_distances(
    const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources, VertexDistanceMap distances,
    const FastMarchingOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    const FastMarchingSolver<TriangleMesh, NamedParameters> solver(tm, options, np);
    return solver.distances(sources, distances);
}

/// Fast marching distances from one vertex; as the source-set overload.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
FastMarchingReport fast_marching_distances(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    VertexDistanceMap distances, const FastMarchingOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    return fast_marching_distances(tm, SourceSet<TriangleMesh>(source), distances, options, np);
}

}  // namespace tapeline::geodesic
