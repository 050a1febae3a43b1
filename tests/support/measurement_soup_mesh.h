// Support-internal (not a test facade: it includes CGAL): a Soup (tapeline_test/measurement.h)
// to a CGAL mesh and back, shared by the support files that build meshes from soups or read them.
#pragma once

#include <tapeline/core/mesh_writers.h>
#include <tapeline_test/measurement.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cstdint>
#include <vector>

namespace tapeline_test::measurement {

/// `mesh` built from the soup's points and triangles (CGAL's polygon_soup_to_polygon_mesh; no
/// validation or repair).
template <class Mesh>
void mesh_from_soup(const std::vector<Vec3>& points, const Triangles& triangles, Mesh& mesh) {
    using Point = typename boost::property_traits<
        typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
    std::vector<Point> pts;
    for (const auto& p : points) {
        pts.emplace_back(p[0], p[1], p[2]);
    }
    std::vector<std::vector<std::size_t>> polys;
    for (const auto& t : triangles) {
        polys.push_back({t[0], t[1], t[2]});
    }
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, mesh);
}

/// The mesh's vertices (in its order) and the first three corners of each face.
template <class Mesh>
Soup soup_from_mesh(const Mesh& mesh) {
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<std::size_t>> polygons;
    tapeline::internal::mesh_arrays(mesh, points, polygons);
    Soup s;
    s.points.assign(points.begin(), points.end());
    for (const auto& f : polygons) {
        std::array<std::uint32_t, 3> t{};
        for (std::size_t k = 0; k < 3 && k < f.size(); ++k) {
            t[k] = static_cast<std::uint32_t>(f[k]);
        }
        s.triangles.push_back(t);
    }
    return s;
}

}  // namespace tapeline_test::measurement
