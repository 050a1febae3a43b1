#include "app_types.h"

#include <tapeline/geodesic/heat.h>

namespace tapeline::app {

MethodResult run_heat(const Mesh& mesh, const Sources& sources, bool intrinsic_delaunay) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    auto map = CGAL::make_property_map(result.distances);
    geodesic::HeatOptions options;
    options.intrinsic_delaunay = intrinsic_delaunay;
    result.report = geodesic::heat_distances(mesh, sources, map, options);
    return result;
}

}  // namespace tapeline::app
