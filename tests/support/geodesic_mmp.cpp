// Exact MMP distances, paths and matrices for the tests: the only translation unit that
// instantiates exact_mmp.h (for Surface_mesh and Polyhedron_3 with ids).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>
#include <tapeline_test/mmp.h>

#include <tapeline/geodesic/exact_mmp.h>

#include <boost/property_map/property_map.hpp>

#include <type_traits>
#include <variant>

// Explicit instantiation: every member is compiled (and checked) here, once.
template class tapeline::geodesic::ExactMmpSolver<tapeline_test::geodesic::cgal::SurfaceMesh>;
template class tapeline::geodesic::ExactMmpSolver<tapeline_test::geodesic::cgal::Polyhedron>;
static_assert(std::is_move_constructible_v<
                  tapeline::geodesic::ExactMmpSolver<tapeline_test::geodesic::cgal::SurfaceMesh>>,
              "solvers can be kept in containers");

namespace tapeline_test::geodesic {

namespace {

namespace tg = tapeline::geodesic;

template <class Mesh>
MmpField run_mmp(Mesh& tm, const Soup& soup, const Sources& sources,
                 const ExactMmpOptions& options) {
    MmpField out;
    out.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
    out.report = tg::exact_mmp_distances(tm, cgal::source_set(tm, soup, sources), map, options);
    return out;
}

template <class Mesh>
std::vector<PathResult> paths(Mesh& tm, const Soup& soup, const Sources& sources,
                              const std::vector<SurfacePoint>& targets,
                              const ExactMmpOptions& options, MmpField* field) {
    const tg::ExactMmpSolver<Mesh> solver(tm, cgal::source_set(tm, soup, sources), options);
    if (field) {
        field->d.assign(soup.points.size(), -1.0);
        auto map =
            boost::make_iterator_property_map(field->d.begin(), get(boost::vertex_index, tm));
        field->report = solver.distances(map);
    }
    std::vector<PathResult> out;
    for (const auto& t : targets) {
        const auto target = cgal::surface_point(tm, soup, t);
        const auto path = solver.path_to(target);
        PathResult r;
        for (const auto& p : path.points)
            r.points.push_back(cgal::to_vec3(p));
        r.length = path.length;
        r.distance = solver.distance_to(target);
        out.push_back(std::move(r));
    }
    return out;
}

template <class Mesh>
std::vector<std::vector<double>> matrix(Mesh& tm, const Soup& soup,
                                        const std::vector<SurfacePoint>& sources,
                                        const ExactMmpOptions& options, unsigned threads) {
    std::vector<tg::SurfacePoint<Mesh>> pts;
    for (const auto& s : sources)
        pts.push_back(cgal::surface_point(tm, soup, s));
    // Rows are indexed by the vertex index map, which is the soup numbering for both kinds.
    return tg::exact_mmp_distance_matrix(tm, pts, options, CGAL::parameters::default_values(),
                                         threads);
}

}  // namespace

MmpField mmp_distances(const Soup& soup, const Sources& sources, MeshKind kind,
                       const ExactMmpOptions& options) {
    return cgal::with_mesh(soup, kind,
                           [&](auto& tm) { return run_mmp(tm, soup, sources, options); });
}

MmpField mmp_distances_with_named_parameters(const Soup& soup, const Sources& sources) {
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm);
    MmpField out;
    out.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
    out.report =
        tg::exact_mmp_distances(tm, cgal::source_set(tm, soup, sources), map, ExactMmpOptions{},
                                CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, tm))
                                    .vertex_index_map(get(boost::vertex_index, tm))
                                    .face_index_map(get(boost::face_index, tm))
                                    .geom_traits(cgal::Kernel()));
    return out;
}

std::vector<PathResult> mmp_paths(const Soup& soup, const Sources& sources,
                                  const std::vector<SurfacePoint>& targets, MeshKind kind,
                                  const ExactMmpOptions& options, MmpField* field) {
    return cgal::with_mesh(
        soup, kind, [&](auto& tm) { return paths(tm, soup, sources, targets, options, field); });
}

PathResult mmp_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                    MeshKind kind) {
    return cgal::with_mesh(soup, kind, [&](auto& tm) {
        const auto path = tg::exact_mmp_path(tm, cgal::surface_point(tm, soup, from),
                                             cgal::surface_point(tm, soup, to));
        PathResult r;
        for (const auto& p : path.points)
            r.points.push_back(cgal::to_vec3(p));
        r.length = path.length;
        r.distance = path.length;
        return r;
    });
}

std::vector<std::vector<double>> mmp_matrix(const Soup& soup,
                                            const std::vector<SurfacePoint>& sources, MeshKind kind,
                                            const ExactMmpOptions& options, unsigned threads) {
    return cgal::with_mesh(soup, kind,
                           [&](auto& tm) { return matrix(tm, soup, sources, options, threads); });
}

}  // namespace tapeline_test::geodesic
