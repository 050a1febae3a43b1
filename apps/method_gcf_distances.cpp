// `gcf-exact` (Algorithm 1: the whole polyline of every vertex flowed), `gcf-window` (Algorithm
// 2: only its last W samples, field-anchored windows) and `gcf-window-thesis` (Algorithm 2 with
// the thesis' prefix rule) distance methods.
#include "app_types.h"

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/curvature_flow.h>

namespace tapeline::app {

MethodResult run_gcf(const Mesh& mesh, const Sources& sources, std::size_t window,
                     bool thesis_anchor, bool on_faces, bool repair) {
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
    geodesic::CurvatureFlowDistanceOptions options;
    options.window = window;
    options.anchor = thesis_anchor ? geodesic::WindowAnchor::prefix : geodesic::WindowAnchor::field;
    options.cut_locus_guard = !thesis_anchor;
    options.smooth_length = !on_faces;  // gcf-window-thesis: the thesis' rule as written
    if (!repair) {
        options.repair_tolerance = -1;
    }
    const geodesic::CurvatureFlowDistanceReport r = geodesic::gcf_distances(
        mesh, sources.vertices.front(), CGAL::make_property_map(result.distances), options);
    result.report.method =
        window == 0 ? "gcf_exact" : (thesis_anchor ? "gcf_window_thesis" : "gcf_window");
    result.report.vertices = num_vertices(mesh);
    result.report.faces = num_faces(mesh);
    result.report.sources = 1;
    result.report.unreachable = r.unreachable;
    result.report.pre_seconds = r.init_seconds;
    result.report.query_seconds = r.seconds - r.init_seconds;
    result.report.status = r.status;
    return result;
}

}  // namespace tapeline::app
