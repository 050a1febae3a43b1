// Instantiates make_compact_mesh on CGAL::Surface_mesh and CGAL::Polyhedron_3 and reads the same
// facts from CGAL for the tests to compare (tapeline_test/compact_mesh.h).
#include <tapeline/core/compact_mesh.h>
#include <tapeline_test/compact_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

namespace tapeline_test {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class Mesh>
CompactMeshView view_of(const Points& points, const Faces& faces) {
    std::vector<Epick::Point_3> pts;
    for (const auto& p : points)
        pts.emplace_back(p[0], p[1], p[2]);
    Mesh tm;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, faces, tm);
    CompactMeshView view;
    view.mesh = tapeline::make_compact_mesh(tm);
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    for (auto f : CGAL::faces(tm)) {
        std::array<std::size_t, 3> fv{};
        std::array<bool, 3> border{};
        auto h = halfedge(f, tm);
        for (int k = 0; k < 3; ++k, h = next(h, tm)) {
            fv[k] = get(vim, source(h, tm));
            border[k] = is_border(opposite(h, tm), tm);
        }
        view.face_vertices.push_back(fv);
        view.border.push_back(border);
    }
    view.neighbours.resize(num_vertices(tm));
    for (auto v : CGAL::vertices(tm))
        if (halfedge(v, tm) != boost::graph_traits<Mesh>::null_halfedge())
            for (auto h : CGAL::halfedges_around_target(v, tm))
                view.neighbours[get(vim, v)].push_back(get(vim, source(h, tm)));
    return view;
}

}  // namespace

CompactMeshView compact_mesh_of(const Points& points, const Faces& faces, MeshKind kind) {
    if (kind == MeshKind::polyhedron)
        return view_of<CGAL::Polyhedron_3<Epick>>(points, faces);
    return view_of<CGAL::Surface_mesh<Epick::Point_3>>(points, faces);
}

}  // namespace tapeline_test
