// A downstream program that knows Tapeline only through `find_package(tapeline)`; it follows the
// README's example (read a mesh, heat distances) plus the analytic surfaces and Dijkstra.
#include <tapeline/core/analytic_surfaces.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/mesh_writers.h>
#include <tapeline/geodesic/dijkstra.h>
#include <tapeline/geodesic/heat.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <vector>

int main() {
    using Mesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
    Mesh sphere;
    tapeline::make_surface_mesh(tapeline::SurfaceSpec::parse("icosphere:3"), sphere);
    tapeline::write_mesh("consumer_sphere.off", sphere);

    auto loaded = tapeline::read_triangle_mesh<Mesh>("consumer_sphere.off");
    std::remove("consumer_sphere.off");
    std::vector<double> heat(num_vertices(loaded.mesh)), edges(num_vertices(loaded.mesh));
    tapeline::geodesic::heat_distances(loaded.mesh, loaded.vertices[0],
                                       CGAL::make_property_map(heat));
    tapeline::geodesic::dijkstra_distances(loaded.mesh, loaded.vertices[0],
                                           CGAL::make_property_map(edges));
    // On the unit sphere the farthest point is pi away: heat is within a few percent of it, edge
    // paths are longer.
    const double far_heat = *std::max_element(heat.begin(), heat.end());
    const double far_edges = *std::max_element(edges.begin(), edges.end());
    if (num_vertices(loaded.mesh) != 642 || std::abs(far_heat - M_PI) > 0.1 * M_PI ||
        far_edges < M_PI || far_edges > 1.2 * M_PI) {
        std::cout << "consumer failed: " << num_vertices(loaded.mesh) << " vertices, farthest "
                  << far_heat << " (heat), " << far_edges << " (edges)\n";
        return 1;
    }
    std::cout << "consumer ok: farthest vertex at " << far_heat << " (heat), " << far_edges
              << " (edges)\n";
    return 0;
}
