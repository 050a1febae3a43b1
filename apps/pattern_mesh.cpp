#include <tapeline/core/errors.h>
#include <tapeline/pattern/meshing.h>

#include <cmath>
#include <sstream>
#include <string>

namespace tapeline::app {

std::string export_pattern_mesh(const pattern::Pattern& p, const std::string& path, double edge_mm,
                                const std::string& shown_as) {
    if (!(edge_mm > 0) || !std::isfinite(edge_mm)) {
        throw InvalidInput("--edge-length must be a positive number of millimetres");
    }
    pattern::MeshingOptions options;
    options.target_edge_mm = edge_mm;
    pattern::MeshingReport report;
    const pattern::PatternMesh mesh = pattern::mesh_pattern(p, options, &report);
    pattern::write_mesh(mesh, path);
    std::ostringstream said;
    said << "wrote " << shown_as << " (" << report.pieces << " pieces, " << report.vertices
         << " vertices, " << report.triangles << " triangles, longest edge " << report.max_edge_mm
         << " mm)\n";
    return said.str();
}

}  // namespace tapeline::app
