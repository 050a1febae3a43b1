// `tapeline geodesic path --method gcf`: the two-point geodesic by curvature flow, with both of
// its polylines (the smooth one, pulled towards the surface the mesh approximates, and the one
// traced on the faces) and the flow's report.
#include "app_types.h"
#include "path_json.h"

#include <tapeline/geodesic/curvature_flow.h>

#include <nlohmann/json.hpp>

namespace tapeline::app {

nlohmann::json gcf_path_json(const Mesh& mesh, Vertex from, Vertex to) {
    using SP = geodesic::SurfacePoint<Mesh>;
    const auto result = geodesic::geodesic_path(mesh, SP(from), SP(to));
    nlohmann::json j = path_json(result.on_mesh);  // top-level length/points: the path on the mesh
    j["smooth"] = path_json(result.smooth);
    const geodesic::CurvatureFlowReport& r = result.report;
    j["report"] = {{"status", r.status},
                   {"samples", r.samples},
                   {"iterations", r.iterations},
                   {"initial_length", r.initial_length},
                   {"max_geodesic_curvature", r.max_geodesic_curvature},
                   {"scaled_max_geodesic_curvature", r.scaled_max_geodesic_curvature},
                   {"residual", r.residual},
                   {"traced_length", r.traced_length},
                   {"straightened", r.straightened},
                   {"straighten_flips", r.straighten_flips},
                   {"straighten_bends", r.straighten_bends},
                   {"init_seconds", r.init_seconds},
                   {"flow_seconds", r.flow_seconds},
                   {"solver", r.solver}};
    return j;
}

}  // namespace tapeline::app
