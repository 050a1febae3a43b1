#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/dijkstra.h>

namespace tapeline::bench::internal {

MethodResult run_dijkstra(const Mesh& mesh, const Sources& sources) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    auto map = CGAL::make_property_map(result.distances);
    result.report = geodesic::dijkstra_distances(mesh, sources, map);
    return result;
}

}  // namespace tapeline::bench::internal
