#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/heat.h>

namespace tapeline::bench::internal {

MethodResult run_heat(const Mesh& mesh, const Sources& sources,
                      const geodesic::HeatOptions& options) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    auto map = CGAL::make_property_map(result.distances);
    result.report = geodesic::heat_distances(mesh, sources, map, options);
    return result;
}

}  // namespace tapeline::bench::internal
