// Dijkstra distances for the tests (Boost.Graph on Surface_mesh and Polyhedron_3 with ids).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/dijkstra.h>

#include <boost/property_map/property_map.hpp>

namespace tapeline_test::geodesic::cgal {

namespace {
template <class Mesh>
Field run_dijkstra(Mesh& tm, const Soup& soup, const Sources& sources) {
    Field out;
    out.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(out.d.begin(), get(boost::vertex_index, tm));
    out.report = tapeline::geodesic::dijkstra_distances(tm, source_set(tm, soup, sources), map);
    return out;
}
}  // namespace

Field dijkstra_field(const Soup& soup, const Sources& sources, MeshKind kind) {
    return with_mesh(soup, kind, [&](auto& tm) { return run_dijkstra(tm, soup, sources); });
}

}  // namespace tapeline_test::geodesic::cgal
