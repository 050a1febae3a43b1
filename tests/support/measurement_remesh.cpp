// Re-meshed bodies (tapeline_test/measurement_remesh.h).
#include <tapeline/core/remesh.h>
#include <tapeline_test/measurement_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tapeline_test::measurement {
namespace {

using RemeshMesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

RemeshMesh mesh_of(const Soup& soup) {
    RemeshMesh m;
    std::vector<RemeshMesh::Vertex_index> v;
    v.reserve(soup.points.size());
    for (const auto& p : soup.points) {
        v.push_back(m.add_vertex({p[0], p[1], p[2]}));
    }
    for (const auto& t : soup.triangles) {
        m.add_face(v[t[0]], v[t[1]], v[t[2]]);
    }
    return m;
}

Soup soup_of(const RemeshMesh& m) {
    Soup s;
    for (const auto v : m.vertices()) {
        const auto& p = m.point(v);
        s.points.push_back({p.x(), p.y(), p.z()});
    }
    for (const auto f : m.faces()) {
        std::array<std::uint32_t, 3> t{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
            t[static_cast<std::size_t>(k++)] = static_cast<std::uint32_t>(v);
        }
        s.triangles.push_back(t);
    }
    return s;
}

}  // namespace

Soup remeshed_soup(const Soup& soup, double edge) {
    RemeshMesh m = mesh_of(soup);
    tapeline::remesh_isotropic(m, edge, 3, "remeshed soup");
    return soup_of(m);
}

Soup simplified_soup(const Soup& soup, std::size_t vertices) {
    RemeshMesh m = mesh_of(soup);
    tapeline::simplify_to_vertices(m, vertices, "simplified soup");
    return soup_of(m);
}

}  // namespace tapeline_test::measurement
