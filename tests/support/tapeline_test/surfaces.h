// Test facade for the analytic surfaces (DESIGN.md §5): plain functions compiled once in
// tapeline_test_support_surfaces, so test files include gtest and this header only.
#pragma once

#include <tapeline/surfaces/analytic_surface_types.h>

#include <cstddef>

namespace tapeline_test {

/// What CGAL says about the mesh built by tapeline::make_surface_mesh.
struct SurfaceMeshSummary {
    std::size_t vertices = 0, edges = 0, faces = 0;
    bool valid = false;                  // CGAL::is_valid_polygon_mesh
    bool triangle_mesh = false;          // CGAL::is_triangle_mesh
    bool closed = false;                 // CGAL::is_closed
    std::size_t border_halfedges = 0;    // halfedges with a null face
    std::size_t boundary_loops = 0;      // cycles of border halfedges
    long long euler_characteristic = 0;  // V - E + F
    bool vertex_order_kept = false;      // i-th vertex of the mesh has soup point i, bitwise
    bool face_order_kept = false;        // j-th face has soup triangle j in the same cyclic order
    double signed_volume = 0;            // sum of signed tetrahedra (origin, face)
    bool outward_oriented = false;       // PMP::is_outward_oriented (closed meshes only)
};

/// CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>.
SurfaceMeshSummary summarize_surface_mesh(const tapeline::SurfaceSpec& spec);
/// CGAL::Polyhedron_3<CGAL::Simple_cartesian<double>>.
SurfaceMeshSummary summarize_polyhedron(const tapeline::SurfaceSpec& spec);

}  // namespace tapeline_test
