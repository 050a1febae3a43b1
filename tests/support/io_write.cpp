// Instantiates the mesh writers for the tests (tapeline_test/io.h).
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/mesh_writers.h>
#include <tapeline_test/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tapeline_test {
namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
}  // namespace

void write_mesh_from_soup(const std::string& path, const Points& points, const Faces& faces) {
    const auto loaded = tapeline::triangle_mesh_from_soup<SurfaceMesh>(points, faces, "soup");
    tapeline::write_mesh(path, loaded.mesh);
}

void rewrite_mesh(const std::string& mesh_path, const std::string& out_path) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(mesh_path);
    tapeline::write_mesh(out_path, loaded.mesh);
}

void write_scalar_from_soup(const std::string& path, const Points& points, const Faces& faces,
                            const std::vector<double>& values,
                            const tapeline::ScalarPlyOptions& options) {
    const auto loaded = tapeline::triangle_mesh_from_soup<SurfaceMesh>(points, faces, "soup");
    tapeline::write_scalar_ply(path, loaded.mesh, values, options);
}

}  // namespace tapeline_test
