// Re-meshed bodies (tapeline_test/measurement_remesh.h).
#include <tapeline/core/remesh.h>
#include <tapeline_test/measurement_remesh.h>

#include "measurement_soup_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tapeline_test::measurement {
namespace {

using RemeshMesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

}  // namespace

Soup remeshed_soup(const Soup& soup, double edge) {
    RemeshMesh m;
    mesh_from_soup(soup.points, soup.triangles, m);
    tapeline::remesh_isotropic(m, edge, 3, "remeshed soup");
    return soup_from_mesh(m);
}

Soup simplified_soup(const Soup& soup, std::size_t vertices) {
    RemeshMesh m;
    mesh_from_soup(soup.points, soup.triangles, m);
    tapeline::simplify_to_vertices(m, vertices, "simplified soup");
    return soup_from_mesh(m);
}

}  // namespace tapeline_test::measurement
