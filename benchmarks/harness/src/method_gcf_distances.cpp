// `gcf-exact` (Algorithm 1: the whole polyline of every vertex flowed), `gcf-window` (Algorithm
// 2: only its last W samples, field-anchored windows) and `gcf-window-thesis` (Algorithm 2 with
// the thesis' prefix rule) distance methods.
#include <tapeline/bench/methods.h>

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/curvature_flow.h>

namespace tapeline::bench::internal {

MethodResult run_gcf(const Mesh& mesh, const Sources& sources,
                     const geodesic::CurvatureFlowDistanceOptions& options) {
    if (sources.vertices.size() != 1 || !sources.locations.empty()) {
        throw InvalidInput(
            "gcf-exact / gcf-window take exactly one vertex source (ring propagation from one "
            "vertex)");
    }
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    result.report = geodesic::gcf_distances(mesh, sources.vertices.front(),
                                            CGAL::make_property_map(result.distances), options);
    return result;
}

}  // namespace tapeline::bench::internal
