// Instantiates the mesh loader for the mesh types the tests use and flattens the result into
// plain types (tapeline_test/io.h).
#include <tapeline/core/mesh_io.h>
#include <tapeline_test/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

namespace tapeline_test {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
using SimpleMesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Epick>;

template <class TriangleMesh>
LoadedView view_of(const tapeline::LoadedMesh<TriangleMesh>& loaded) {
    const TriangleMesh& tm = loaded.mesh;
    LoadedView view;
    view.report = loaded.report;
    view.valid_polygon_mesh = CGAL::is_valid_polygon_mesh(tm);
    view.triangle_mesh = CGAL::is_triangle_mesh(tm);
    view.closed = CGAL::is_closed(tm);
    view.input_index = loaded.input_index;
    view.face_input_index = loaded.face_input_index;
    view.input_vertex_count = loaded.input_vertex_count;
    auto vpm = get(CGAL::vertex_point, tm);
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    std::vector<double> x;
    for (std::size_t k = 0; k < loaded.vertices.size(); ++k) {
        const auto& p = get(vpm, loaded.vertices[k]);
        put(index, loaded.vertices[k], k);
        view.points.push_back(
            {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
        x.push_back(CGAL::to_double(p.x()));
    }
    for (auto f : faces(tm)) {
        std::array<std::size_t, 3> t{};
        int k = 0;
        for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
            if (k < 3) {
                t[k] = get(index, target(h, tm));
            }
            ++k;
        }
        view.triangles.push_back(t);
        const auto& a = view.points[t[0]];
        const auto& b = view.points[t[1]];
        const auto& c = view.points[t[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        view.area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    for (std::size_t i = 0; i < loaded.input_vertex_count; ++i) {
        std::vector<std::size_t> positions;
        for (auto v : loaded.mesh_vertices_of(i)) {
            positions.push_back(get(index, v));
        }
        view.copies.push_back(std::move(positions));
    }
    view.x_in_input_order = loaded.to_input_order(x);
    return view;
}

template <class TriangleMesh>
LoadedView load_as(const std::string& path, const tapeline::MeshLoadOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<TriangleMesh>(path, options);
    return view_of(loaded);
}

template <class TriangleMesh>
LoadedView soup_as(const Points& points, const Faces& faces, const std::string& name,
                   const tapeline::MeshLoadOptions& options) {
    const auto loaded =
        tapeline::triangle_mesh_from_soup<TriangleMesh>(points, faces, name, options);
    return view_of(loaded);
}

}  // namespace

LoadedView load(const std::string& path, const tapeline::MeshLoadOptions& options, MeshKind kind) {
    switch (kind) {
        case MeshKind::surface_mesh_simple:
            return load_as<SimpleMesh>(path, options);
        case MeshKind::polyhedron:
            return load_as<Polyhedron>(path, options);
        case MeshKind::surface_mesh:
            break;
    }
    return load_as<SurfaceMesh>(path, options);
}

LoadedView load_soup(const Points& points, const Faces& faces, const std::string& name,
                     const tapeline::MeshLoadOptions& options, MeshKind kind) {
    switch (kind) {
        case MeshKind::surface_mesh_simple:
            return soup_as<SimpleMesh>(points, faces, name, options);
        case MeshKind::polyhedron:
            return soup_as<Polyhedron>(points, faces, name, options);
        case MeshKind::surface_mesh:
            break;
    }
    return soup_as<SurfaceMesh>(points, faces, name, options);
}

std::size_t count_mesh_vertices_of(const std::string& path, std::size_t input_vertex) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    return loaded.mesh_vertices_of(input_vertex).size();
}

tapeline::PolygonSoup read_soup(const std::string& path) {
    return tapeline::read_polygon_soup(path);
}

}  // namespace tapeline_test
