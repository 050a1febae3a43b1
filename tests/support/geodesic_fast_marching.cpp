// Fast marching distances for the tests: the only translation unit of the suite that
// instantiates fast_marching.h (for Surface_mesh and Polyhedron_3 with ids).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/fast_marching.h>
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/fast_marching.h>

#include <boost/property_map/property_map.hpp>

// Explicit instantiation: every member is compiled (and checked) here, once.
template class tapeline::geodesic::FastMarchingSolver<tapeline_test::geodesic::cgal::SurfaceMesh>;
template class tapeline::geodesic::FastMarchingSolver<tapeline_test::geodesic::cgal::Polyhedron>;

namespace tapeline_test::geodesic {

namespace {

template <class Mesh>
FastMarchingField run_fast_marching(Mesh& tm, const Soup& soup, const Sources& sources,
                                    const FastMarchingOptions& options) {
    FastMarchingField out;
    out.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
    out.report = tapeline::geodesic::fast_marching_distances(
        tm, cgal::source_set(tm, soup, sources), map, options);
    return out;
}

}  // namespace

FastMarchingField fast_marching(const Soup& soup, const Sources& sources,
                                const FastMarchingOptions& options, MeshKind kind) {
    return cgal::with_mesh(soup, kind,
                           [&](auto& tm) { return run_fast_marching(tm, soup, sources, options); });
}

std::vector<FastMarchingField> fast_marching_queries(const Soup& soup,
                                                     const std::vector<Sources>& queries,
                                                     const FastMarchingOptions& options) {
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm);
    const tapeline::geodesic::FastMarchingSolver<cgal::SurfaceMesh> solver(tm, options);
    std::vector<FastMarchingField> out;
    for (const Sources& q : queries) {
        FastMarchingField f;
        f.d.assign(soup.points.size(), -1.0);
        auto map = boost::make_iterator_property_map(f.d.begin(), get(boost::vertex_index, tm));
        f.report = solver.distances(cgal::source_set(tm, soup, q), map);
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace tapeline_test::geodesic
