// Geodesic curvature flow paths for the tests: the only translation unit that instantiates
// curvature_flow.h (for Surface_mesh and Polyhedron_3 with ids).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/gcf.h>
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/curvature_flow.h>

#include <chrono>
#include <type_traits>
#include <utility>
#include <vector>

// Explicit instantiation: every member is compiled (and checked) here, once.
template class tapeline::geodesic::GeodesicPathSolver<tapeline_test::geodesic::cgal::SurfaceMesh>;
template class tapeline::geodesic::GeodesicPathSolver<tapeline_test::geodesic::cgal::Polyhedron>;

namespace tapeline_test::geodesic {

namespace {

namespace tg = tapeline::geodesic;

template <class Path>
PathResult convert(const Path& path) {
    PathResult r;
    for (const auto& p : path.points)
        r.points.push_back(cgal::to_vec3(p));
    r.length = path.length;
    r.distance = path.length;
    return r;
}

template <class Flow>
GcfResult convert_all(const Flow& flow) {
    return {convert(flow.smooth), convert(flow.on_mesh), flow.report};
}

}  // namespace

GcfResult gcf_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                   const CurvatureFlowOptions& options, MeshKind kind) {
    return cgal::with_mesh(soup, kind, [&](auto& tm) {
        return convert_all(tg::geodesic_path(tm, cgal::surface_point(tm, soup, from),
                                             cgal::surface_point(tm, soup, to), options));
    });
}

GcfResult gcf_path_with_named_parameters(const Soup& soup, const SurfacePoint& from,
                                         const SurfacePoint& to) {
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm);
    return convert_all(
        tg::geodesic_path(tm, cgal::surface_point(tm, soup, from),
                          cgal::surface_point(tm, soup, to), CurvatureFlowOptions{},
                          CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, tm))
                              .vertex_index_map(get(boost::vertex_index, tm))
                              .face_index_map(get(boost::face_index, tm))
                              .geom_traits(cgal::Kernel())));
}

GcfResult gcf_path_from_polyline(const Soup& soup, const std::vector<Vec3>& initial,
                                 const CurvatureFlowOptions& options, MeshKind kind) {
    std::vector<cgal::Kernel::Point_3> pts;
    for (const auto& p : initial)
        pts.emplace_back(p[0], p[1], p[2]);
    return cgal::with_mesh(
        soup, kind, [&](auto& tm) { return convert_all(tg::geodesic_path(tm, pts, options)); });
}

GcfQueries gcf_paths(const Soup& soup,
                     const std::vector<std::pair<SurfacePoint, SurfacePoint>>& pairs,
                     const CurvatureFlowOptions& options, MeshKind kind) {
    return cgal::with_mesh(soup, kind, [&](auto& tm) {
        using Mesh = std::decay_t<decltype(tm)>;
        GcfQueries out;
        const auto t0 = std::chrono::steady_clock::now();
        const tg::GeodesicPathSolver<Mesh> solver(tm);
        out.prepare_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (const auto& [from, to] : pairs)
            out.paths.push_back(convert_all(solver.path(
                cgal::surface_point(tm, soup, from), cgal::surface_point(tm, soup, to), options)));
        return out;
    });
}

GcfQueries gcf_paths_parallel(const Soup& soup,
                              const std::vector<std::pair<SurfacePoint, SurfacePoint>>& pairs,
                              const CurvatureFlowOptions& options, double* seconds) {
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm);
    using Solver = tg::GeodesicPathSolver<cgal::SurfaceMesh>;
    GcfQueries out;
    const auto t0 = std::chrono::steady_clock::now();
    const Solver solver(tm);
    const auto t1 = std::chrono::steady_clock::now();
    out.prepare_seconds = std::chrono::duration<double>(t1 - t0).count();
    std::vector<Solver::PointPair> query;
    for (const auto& [from, to] : pairs)
        query.emplace_back(cgal::surface_point(tm, soup, from), cgal::surface_point(tm, soup, to));
    const auto t2 = std::chrono::steady_clock::now();
    for (const auto& r : solver.paths(query, options))
        out.paths.push_back(convert_all(r));
    if (seconds)
        *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
    return out;
}

GcfField gcf_distances(const Soup& soup, std::size_t source,
                       const CurvatureFlowDistanceOptions& options, MeshKind kind) {
    return cgal::with_mesh(soup, kind, [&](auto& tm) {
        GcfField out;
        out.d.assign(soup.points.size(), -1.0);
        auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
        out.report = tg::gcf_distances(tm, cgal::vertex_at(tm, source), map, options);
        return out;
    });
}

std::vector<double> steiner_distances(const Soup& soup, std::size_t source, unsigned per_edge,
                                      unsigned near_per_edge, double near_radius) {
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm);
    const tg::internal::GcfSetup<cgal::SurfaceMesh, CGAL::parameters::Default_named_parameters>
        setup(tm, CGAL::parameters::default_values());
    const auto& index = setup.index();
    const auto from = static_cast<std::uint32_t>(index.index(cgal::vertex_at(tm, source)));
    const tg::internal::gcf::SteinerTree graph(setup.mesh(), from, per_edge, near_per_edge,
                                               near_radius * setup.mesh().mean_edge);
    std::vector<double> d(soup.points.size());
    for (std::size_t v = 0; v < d.size(); ++v)
        d[v] = graph.distance(static_cast<std::uint32_t>(index.index(cgal::vertex_at(tm, v))));
    return d;
}

}  // namespace tapeline_test::geodesic
