// Shared body of the CGAL mesh checks behind tapeline_test/surfaces.h; included by
// surfaces_surface_mesh.cpp and surfaces_polyhedron.cpp only (one mesh type per translation unit,
// so the two cores compile them in parallel).
#pragma once

#include <tapeline/surfaces/analytic_surfaces.h>
#include <tapeline_test/surfaces.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/helpers.h>

#include <map>
#include <set>

namespace tapeline_test::internal {

template <class TriangleMesh>
SurfaceMeshSummary summarize(const tapeline::SurfaceSpec& spec) {
    using GT = boost::graph_traits<TriangleMesh>;
    TriangleMesh tm;
    tapeline::make_surface_mesh(spec, tm);
    const tapeline::SurfaceSoup soup = tapeline::generate_surface(spec);

    SurfaceMeshSummary s;
    s.vertices = num_vertices(tm);
    s.edges = num_edges(tm);
    s.faces = num_faces(tm);
    s.valid = CGAL::is_valid_polygon_mesh(tm);
    s.triangle_mesh = CGAL::is_triangle_mesh(tm);
    s.closed = CGAL::is_closed(tm);
    s.euler_characteristic = static_cast<long long>(s.vertices) - static_cast<long long>(s.edges) +
                             static_cast<long long>(s.faces);

    std::set<typename GT::halfedge_descriptor> seen;
    for (auto h : halfedges(tm)) {
        if (!CGAL::is_border(h, tm))
            continue;
        ++s.border_halfedges;
        if (seen.count(h))
            continue;
        ++s.boundary_loops;
        auto g = h;
        do {
            seen.insert(g);
            g = next(g, tm);
        } while (g != h);
    }

    auto vpm = get(CGAL::vertex_point, tm);
    std::map<typename GT::vertex_descriptor, std::size_t> index;
    s.vertex_order_kept = s.vertices == soup.points.size();
    std::size_t i = 0;
    for (auto v : vertices(tm)) {
        index[v] = i;
        const auto& p = get(vpm, v);
        if (i < soup.points.size() && (p.x() != soup.points[i][0] || p.y() != soup.points[i][1] ||
                                       p.z() != soup.points[i][2]))
            s.vertex_order_kept = false;
        ++i;
    }
    s.face_order_kept = s.faces == soup.triangles.size();
    std::size_t j = 0;
    for (auto f : faces(tm)) {
        auto h = halfedge(f, tm);
        std::size_t a = index[target(prev(h, tm), tm)], b = index[target(h, tm)],
                    c = index[target(next(h, tm), tm)];
        bool same = false;
        if (j < soup.triangles.size()) {
            const auto& t = soup.triangles[j];
            for (int r = 0; r < 3; ++r)
                same = same || (t[r] == a && t[(r + 1) % 3] == b && t[(r + 2) % 3] == c);
        }
        s.face_order_kept = s.face_order_kept && same;
        const auto& p = get(vpm, source(h, tm));
        const auto& q = get(vpm, target(h, tm));
        const auto& r = get(vpm, target(next(h, tm), tm));
        s.signed_volume +=
            (p.x() * (q.y() * r.z() - q.z() * r.y()) - p.y() * (q.x() * r.z() - q.z() * r.x()) +
             p.z() * (q.x() * r.y() - q.y() * r.x())) /
            6.0;
        ++j;
    }
    if (s.closed && s.triangle_mesh)
        s.outward_oriented = CGAL::Polygon_mesh_processing::is_outward_oriented(tm);
    return s;
}

}  // namespace tapeline_test::internal
