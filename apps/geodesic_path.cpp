// The exact path of `tapeline geodesic path` (own translation unit: SMSP's path machinery is
// heavy).
#include "app_types.h"

#include <tapeline/geodesic/exact_cgal.h>

#include <nlohmann/json.hpp>

namespace tapeline::app {

nlohmann::json exact_cgal_path_json(const Mesh& mesh, Vertex from, Vertex to) {
    using SP = geodesic::SurfacePoint<Mesh>;
    const auto path = geodesic::exact_cgal_path(mesh, SP(from), SP(to));
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
