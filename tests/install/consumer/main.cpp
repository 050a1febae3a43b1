// A downstream program that knows Tapeline only through `find_package(tapeline)`.
#include <tapeline/core/analytic_surfaces.h>
#include <tapeline/geodesic/dijkstra.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
    using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
    Mesh mesh;
    tapeline::make_surface_mesh(tapeline::SurfaceSpec::parse("icosphere:2"), mesh);
    std::vector<double> d(num_vertices(mesh));
    tapeline::geodesic::SourceSet<Mesh> sources;
    sources.vertices.push_back(*vertices(mesh).begin());
    tapeline::geodesic::dijkstra_distances(mesh, sources, CGAL::make_property_map(d));
    double far = 0;
    for (double x : d) {
        far = std::max(far, x);
    }
    // On the unit sphere the farthest point is pi away; edge paths are a little longer.
    if (num_vertices(mesh) != 162 || far < M_PI || far > 1.2 * M_PI) {
        std::cout << "consumer failed: " << num_vertices(mesh) << " vertices, farthest " << far
                  << '\n';
        return 1;
    }
    std::cout << "consumer ok: farthest vertex at " << far << '\n';
    return 0;
}
