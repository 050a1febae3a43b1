// Exact CGAL distances and paths for the tests: the only translation unit that instantiates
// Surface_mesh_shortest_path (for Surface_mesh and Polyhedron_3 with ids).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/exact_cgal.h>

#include <boost/property_map/property_map.hpp>

// Explicit instantiation: every member is compiled (and checked) here, once.
template class tapeline::geodesic::ExactCgalSolver<tapeline_test::geodesic::cgal::SurfaceMesh>;
template class tapeline::geodesic::ExactCgalSolver<tapeline_test::geodesic::cgal::Polyhedron>;

namespace tapeline_test::geodesic::cgal {

namespace {

template <class Mesh>
Field run_exact_cgal(Mesh& tm, const Soup& soup, const Sources& sources) {
    Field out;
    out.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
    out.report = tapeline::geodesic::exact_cgal_distances(tm, source_set(tm, soup, sources), map);
    return out;
}

template <class Mesh>
std::vector<PathResult> paths(Mesh& tm, const Soup& soup, const Sources& sources,
                              const std::vector<SurfacePoint>& targets) {
    tapeline::geodesic::ExactCgalSolver<Mesh> solver(tm, source_set(tm, soup, sources));
    std::vector<PathResult> out;
    for (const auto& t : targets) {
        const auto target = surface_point(tm, soup, t);
        const auto path = solver.path_to(target);
        PathResult r;
        for (const auto& p : path.points)
            r.points.push_back(to_vec3(p));
        r.length = path.length;
        r.distance = solver.distance_to(target);
        out.push_back(std::move(r));
    }
    return out;
}

template <class Mesh>
PathResult one_path(Mesh& tm, const Soup& soup, const SurfacePoint& from, const SurfacePoint& to) {
    const auto path = tapeline::geodesic::exact_cgal_path(tm, surface_point(tm, soup, from),
                                                          surface_point(tm, soup, to));
    PathResult r;
    for (const auto& p : path.points)
        r.points.push_back(to_vec3(p));
    r.length = path.length;
    r.distance = path.length;
    return r;
}

}  // namespace

Field exact_field(const Soup& soup, const Sources& sources, MeshKind kind) {
    return with_mesh(soup, kind, [&](auto& tm) { return run_exact_cgal(tm, soup, sources); });
}

}  // namespace tapeline_test::geodesic::cgal

namespace tapeline_test::geodesic {

std::vector<PathResult> exact_paths(const Soup& soup, const Sources& sources,
                                    const std::vector<SurfacePoint>& targets, MeshKind kind) {
    if (kind == MeshKind::polyhedron) {
        cgal::Polyhedron tm;
        cgal::build(soup, tm);
        return cgal::paths(tm, soup, sources, targets);
    }
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm, kind == MeshKind::surface_mesh_with_garbage);
    return cgal::paths(tm, soup, sources, targets);
}

PathResult exact_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                      MeshKind kind) {
    if (kind == MeshKind::polyhedron) {
        cgal::Polyhedron tm;
        cgal::build(soup, tm);
        return cgal::one_path(tm, soup, from, to);
    }
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm, kind == MeshKind::surface_mesh_with_garbage);
    return cgal::one_path(tm, soup, from, to);
}

}  // namespace tapeline_test::geodesic
