// Test facade for mesh I/O (DESIGN.md §5): plain types only, so test files compile without CGAL.
// The CGAL-heavy calls are compiled once in tests/support/io_*.cpp.
#pragma once

#include <tapeline/core/mesh_io_types.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tapeline_test {

using Points = std::vector<std::array<double, 3>>;
using Faces = std::vector<std::vector<std::size_t>>;

/// Mesh types the loader is instantiated for.
enum class MeshKind {
    surface_mesh,         // CGAL::Surface_mesh<Epick::Point_3>
    surface_mesh_simple,  // CGAL::Surface_mesh<Simple_cartesian<double>::Point_3>
    polyhedron,           // CGAL::Polyhedron_3<Epick>
};

/// A LoadedMesh in plain types.
struct LoadedView {
    tapeline::MeshReport report;
    bool valid_polygon_mesh = false;                    // CGAL::is_valid_polygon_mesh
    bool triangle_mesh = false;                         // CGAL::is_triangle_mesh
    bool closed = false;                                // CGAL::is_closed
    Points points;                                      // mesh vertices in mesh order
    std::vector<std::array<std::size_t, 3>> triangles;  // positions in `points`
    std::vector<std::size_t> input_index, face_input_index;
    std::size_t input_vertex_count = 0;
    std::vector<std::vector<std::size_t>>
        copies;                            // per input vertex: mesh_vertices_of, as positions
    std::vector<double> x_in_input_order;  // to_input_order(x of each mesh vertex)
    double area = 0;                       // total triangle area
};

/// read_triangle_mesh on `path`.
LoadedView load(const std::string& path, const tapeline::MeshLoadOptions& options = {},
                MeshKind kind = MeshKind::surface_mesh);
/// triangle_mesh_from_soup.
LoadedView load_soup(const Points& points, const Faces& faces, const std::string& name,
                     const tapeline::MeshLoadOptions& options = {},
                     MeshKind kind = MeshKind::surface_mesh);
/// read_triangle_mesh, then mesh_vertices_of(input_vertex).size() (throws as the library does).
std::size_t count_mesh_vertices_of(const std::string& path, std::size_t input_vertex);
/// read_polygon_soup.
tapeline::PolygonSoup read_soup(const std::string& path);

/// Builds a Surface_mesh from the soup (triangle_mesh_from_soup) and calls write_mesh.
void write_mesh_from_soup(const std::string& path, const Points& points, const Faces& faces);
/// Loads `mesh_path` and calls write_mesh on the result.
void rewrite_mesh(const std::string& mesh_path, const std::string& out_path);
/// Builds a Surface_mesh from the soup and calls write_scalar_ply (values in mesh order).
void write_scalar_from_soup(const std::string& path, const Points& points, const Faces& faces,
                            const std::vector<double>& values,
                            const tapeline::ScalarPlyOptions& options = {});

/// A point set as read_point_set (core/point_io.h) returns it, in plain types.
struct PointSetView {
    std::string file, format;
    std::size_t dimension = 0;
    std::vector<double> coordinates, normals;
};
/// read_point_set (throws as the library does).
PointSetView read_points(const std::string& path);

/// A fresh empty directory under the system temporary directory, named after the test.
std::string temp_dir(const std::string& name);
/// Writes bytes to a file (test inputs, possibly broken on purpose).
void write_bytes(const std::string& path, const std::string& bytes);
bool file_exists(const std::string& path);

}  // namespace tapeline_test
