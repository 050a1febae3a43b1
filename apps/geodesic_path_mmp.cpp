// The exact MMP path of `tapeline geodesic path` (own translation unit: the window propagation is
// heavy).
#include "app_types.h"
#include "path_json.h"

#include <tapeline/geodesic/exact_mmp.h>

#include <nlohmann/json.hpp>

namespace tapeline::app {

nlohmann::json exact_mmp_path_json(const Mesh& mesh, Vertex from, Vertex to) {
    using SP = geodesic::SurfacePoint<Mesh>;
    return path_json(geodesic::exact_mmp_path(mesh, SP(from), SP(to)));
}

}  // namespace tapeline::app
