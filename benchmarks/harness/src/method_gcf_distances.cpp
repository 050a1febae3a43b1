// `gcf-exact` (Algorithm 1: the whole polyline of every vertex flowed), `gcf-window` (Algorithm
// 2: only its last W samples, field-anchored windows) and `gcf-window-thesis` (Algorithm 2 with
// the thesis' prefix rule) distance methods.
#include <tapeline/bench/methods.h>

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/curvature_flow.h>

#include <string>

namespace tapeline::bench::internal {

MethodResult run_gcf(const Mesh& mesh, const Sources& sources,
                     const geodesic::CurvatureFlowDistanceOptions& options) {
    if (sources.vertices.size() > 1 && sources.locations.empty()) {
        // One input vertex on a non-manifold edge or vertex has one mesh copy per sheet.
        throw InvalidInput(
            "gcf-exact / gcf-window take exactly one vertex source, and the source given stands "
            "for " +
            std::to_string(sources.vertices.size()) +
            " mesh vertices (several sources, or one vertex split where the mesh is not "
            "manifold); give one source away from the split or use exact-mmp");
    }
    if (sources.vertices.size() != 1 || !sources.locations.empty()) {
        throw InvalidInput(
            "gcf-exact / gcf-window take exactly one vertex source (ring propagation from one "
            "vertex)");
    }
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    const geodesic::CurvatureFlowDistanceReport r = geodesic::gcf_distances(
        mesh, sources.vertices.front(), CGAL::make_property_map(result.distances), options);
    result.report = r;
    result.extra = {{"epsilon", r.epsilon},
                    {"max_faces", r.max_faces},
                    {"error_bound", r.error_bound},
                    {"flows", r.flows},
                    {"flow_iterations", r.iterations},
                    {"repair_seconds", r.repair_seconds}};
    return result;
}

}  // namespace tapeline::bench::internal
