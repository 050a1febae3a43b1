#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/exact_mmp.h>

namespace tapeline::bench::internal {

MethodResult run_exact_mmp(const Mesh& mesh, const Sources& sources) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    result.report =
        geodesic::exact_mmp_distances(mesh, sources, CGAL::make_property_map(result.distances));
    return result;
}

}  // namespace tapeline::bench::internal
