// A downstream program that knows Tapeline only through `find_package(tapeline)`; it follows the
// README's example (read a mesh, heat distances) plus Dijkstra, and the analytic surfaces with
// their exact geodesics (tapeline::surfaces, which brings GeographicLib).
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/mesh_writers.h>
#include <tapeline/geodesic/dijkstra.h>
#include <tapeline/geodesic/heat.h>
#include <tapeline/surfaces/analytic_geodesics.h>
#include <tapeline/surfaces/analytic_surfaces.h>

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
    // The mesh vertices are the soup's points in order: the truth is the great-circle angle. The
    // ellipsoid of revolution goes through GeographicLib, so the link is exercised too.
    const tapeline::SurfaceSpec spec = tapeline::SurfaceSpec::parse("icosphere:3");
    const std::vector<double> truth =
        tapeline::analytic_distances(spec, tapeline::generate_surface(spec).points, 0);
    const tapeline::SurfaceSpec oblate = tapeline::SurfaceSpec::parse("ellipsoid:1,1,0.5:1");
    const std::vector<double> oblate_truth =
        tapeline::analytic_distances(oblate, tapeline::generate_surface(oblate).points, 0);
    double worst = 0;
    for (std::size_t i = 0; i < truth.size() && i < heat.size(); ++i) {
        worst = std::max(worst, std::abs(heat[i] - truth[i]));
    }
    if (truth.size() != heat.size() || worst > 0.1 || oblate_truth.size() != 42 ||
        !(oblate_truth[1] > 0)) {
        std::cout << "consumer failed: heat differs from the great circle by " << worst << ", "
                  << oblate_truth.size() << " ellipsoid distances\n";
        return 1;
    }
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
