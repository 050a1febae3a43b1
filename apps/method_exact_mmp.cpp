#include "app_types.h"

#include <tapeline/geodesic/exact_mmp.h>

#include <nlohmann/json.hpp>

namespace tapeline::app {

MethodResult run_exact_mmp(const Mesh& mesh, const Sources& sources) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    result.report =
        geodesic::exact_mmp_distances(mesh, sources, CGAL::make_property_map(result.distances));
    return result;
}

nlohmann::json exact_mmp_path_json(const Mesh& mesh, Vertex from, Vertex to) {
    using SP = geodesic::SurfacePoint<Mesh>;
    const auto path = geodesic::exact_mmp_path(mesh, SP(from), SP(to));
    nlohmann::json j;
    j["length"] = path.found() ? nlohmann::json(path.length) : nlohmann::json(nullptr);
    j["reachable"] = path.found();
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : path.points) {
        points.push_back({p.x(), p.y(), p.z()});
    }
    j["points"] = points;
    return j;
}

}  // namespace tapeline::app
