#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/exact_cgal.h>

namespace tapeline::bench::internal {

MethodResult run_exact_cgal(const Mesh& mesh, const Sources& sources) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    auto map = CGAL::make_property_map(result.distances);
    result.report = geodesic::exact_cgal_distances(mesh, sources, map);
    return result;
}

}  // namespace tapeline::bench::internal
