// `tapeline geodesic path --svg`: the faces crossed by the path, unfolded into the plane (own
// translation unit: unfold.h instantiates the curvature-flow mesh preparation).
#include "path_unfold.h"
#include "app_types.h"

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/unfold.h>
#include <tapeline/geodesic/unfold_svg.h>

#include <sstream>
#include <vector>

namespace tapeline::app {

UnfoldOutput unfold_path_output(const Mesh& mesh, const nlohmann::json& points,
                                const std::string& title) {
    std::vector<Point> pts;
    for (const auto& p : points) {
        pts.emplace_back(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
    }
    if (pts.size() < 2) {
        throw InvalidInput("--svg: there is no path to unfold (the end points are not connected)");
    }
    const geodesic::UnfoldedPath u = geodesic::unfold_path(mesh, pts);
    UnfoldOutput out;
    out.summary = {{"faces", u.faces.size()},
                   {"fan_faces", u.fan_faces},
                   {"vertex_points", u.vertex_points},
                   {"traced_length", u.traced_length},
                   {"unfolded_length", u.unfolded_length},
                   {"straight_length", u.straight_length},
                   {"straight_inside", u.straight_inside}};
    std::ostringstream svg;
    geodesic::write_unfold_svg(svg, u, title);
    out.svg = svg.str();
    return out;
}

}  // namespace tapeline::app
