#include "app_types.h"
#include "path_json.h"

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
    return path_json(geodesic::exact_mmp_path(mesh, SP(from), SP(to)));
}

}  // namespace tapeline::app
