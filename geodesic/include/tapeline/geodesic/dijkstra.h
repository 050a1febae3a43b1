// Graph distances along mesh edges: E. W. Dijkstra, "A note on two problems in connexion with
// graphs", Numerische Mathematik 1, 1959, run with Boost.Graph on the mesh's own
// boost::graph_traits (CGAL's BGL adaptors), with Euclidean edge lengths as weights.
//
// An edge path is a path on the surface, so these distances are upper bounds of the exact
// polyhedral ones (on a regular triangulation they overestimate by a few percent, and the error
// does not vanish under refinement). Face-location sources seed the three corners of their face
// with the straight-line distance from the point, which is exact within the face.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/boost/graph/properties.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace tapeline::geodesic {

/// Dijkstra distances on the edge graph from a source set into `distances` (+infinity when
/// unreachable). report.query_seconds is the whole run; there is no pre-computation.
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
/// \throws InvalidInput also when `sources` is empty or holds a vertex or face location that
///         is not on the mesh.
/// \throws SolverFailure when a distance is NaN; `distances` is left untouched then.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport dijkstra_distances(const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources,
                                  VertexDistanceMap distances, const DijkstraOptions& = {},
                                  const NamedParameters& np = CGAL::parameters::default_values()) {
    using P = internal::MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using vertex_descriptor = typename GT::vertex_descriptor;
    using edge_descriptor = typename GT::edge_descriptor;
    const char* w = "dijkstra";

    const auto vpm = P::vertex_point_map(tm, np);
    const internal::MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>
        index(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), w);
    internal::check_triangle_mesh(tm, vpm, index.vertex_index_map(), index.face_index_map(), w);
    if (sources.empty())
        throw InvalidInput(std::string(w) + ": the source set is empty");

    const std::size_t n = index.vertex_count();
    std::vector<double> d(n, internal::kInfinity);
    auto point_distance = [](const auto& p, const auto& q) {
        const double dx = CGAL::to_double(p.x()) - CGAL::to_double(q.x());
        const double dy = CGAL::to_double(p.y()) - CGAL::to_double(q.y());
        const double dz = CGAL::to_double(p.z()) - CGAL::to_double(q.z());
        return std::sqrt(dx * dx + dy * dy + dz * dz);
    };
    // Seeds (checked before any work): vertex sources at 0, face-location sources at their
    // straight-line distance to the corners of their face.
    internal::seed_corners(tm, vpm, index, sources, d);

    const auto t0 = internal::Clock::now();
    const internal::Components components = internal::connected_components(tm, index);
    std::vector<vertex_descriptor> seeds;
    for (std::size_t i = 0; i < n; ++i)
        // Each seed once (the heap must not hold duplicates); an isolated vertex has no
        // out-edges to walk (halfedge(v) is null) and keeps its 0.
        if (d[i] < internal::kInfinity && !components.isolated[i])
            seeds.push_back(index.vertex(i));

    auto weight = boost::make_function_property_map<edge_descriptor, double>(
        [&tm, vpm, &point_distance](const edge_descriptor& e) {
            const auto h = halfedge(e, tm);
            return point_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
        });
    auto distance_map = boost::make_iterator_property_map(d.begin(), index.vertex_index_map());
    // The no_init variant keeps the seeded distances (the plain one would reset them to 0).
    boost::dijkstra_shortest_paths_no_init(
        tm, seeds.begin(), seeds.end(), boost::dummy_property_map(), distance_map, weight,
        index.vertex_index_map(), std::less<double>(), std::plus<double>(), 0.0,
        boost::default_dijkstra_visitor());

    DistanceReport report;
    report.method = w;
    report.vertices = n;
    report.faces = index.face_count();
    report.sources = sources.size();
    report.components = components.count;
    report.unreachable = internal::write_distances(d, index, distances, w);
    report.query_seconds = internal::seconds_since(t0);
    report.seconds = report.query_seconds;
    return report;
}

/// Dijkstra distances from one vertex; as the source-set overload.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport dijkstra_distances(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
    VertexDistanceMap distances, const DijkstraOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    return dijkstra_distances(tm, SourceSet<TriangleMesh>(source), distances, options, np);
}

}  // namespace tapeline::geodesic
