// The exact path of `tapeline geodesic path` (own translation unit: SMSP's path machinery is
// heavy).
#include "app_types.h"
#include "path_json.h"

#include <tapeline/geodesic/exact_cgal.h>

#include <nlohmann/json.hpp>

namespace tapeline::app {

nlohmann::json exact_cgal_path_json(const Mesh& mesh, Vertex from, Vertex to) {
    using SP = geodesic::SurfacePoint<Mesh>;
    return path_json(geodesic::exact_cgal_path(mesh, SP(from), SP(to)));
}

}  // namespace tapeline::app
