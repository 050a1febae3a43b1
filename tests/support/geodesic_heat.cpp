// Heat-method distances for the tests (HeatDistanceSolver on Surface_mesh and Polyhedron_3).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/heat.h>

#include <boost/property_map/property_map.hpp>

// The CGAL Heat_method_3 instantiations live in geodesic_heat_component.cpp (the two halves
// compile in parallel).
extern template class tapeline::geodesic::internal::HeatComponent<
    tapeline_test::geodesic::cgal::Kernel>;

// Explicit instantiation: every member is compiled (and checked) here, once.
template class tapeline::geodesic::HeatDistanceSolver<tapeline_test::geodesic::cgal::SurfaceMesh>;
template class tapeline::geodesic::HeatDistanceSolver<tapeline_test::geodesic::cgal::Polyhedron>;

namespace tapeline_test::geodesic::cgal {

namespace {
template <class Mesh>
std::vector<Field> run_heat(Mesh& tm, const Soup& soup, const std::vector<Sources>& queries,
                            const HeatOptions& options) {
    tapeline::geodesic::HeatDistanceSolver<Mesh> solver(tm, options);
    std::vector<Field> out;
    for (const auto& q : queries) {
        Field f;
        f.d.assign(soup.points.size(), -1.0);
        auto map = boost::make_iterator_property_map(f.d.begin(), get(boost::vertex_index, tm));
        f.report = solver.distances(source_set(tm, soup, q), map);
        out.push_back(std::move(f));
    }
    return out;
}

template <class Mesh>
Field run_one_shot(Mesh& tm, const Soup& soup, const Sources& sources, const HeatOptions& options) {
    Field f;
    f.d.assign(soup.points.size(), -1.0);
    auto map = boost::make_iterator_property_map(f.d.begin(), get(boost::vertex_index, tm));
    f.report = tapeline::geodesic::heat_distances(tm, source_set(tm, soup, sources), map, options);
    return f;
}
}  // namespace

Field heat_field(const Soup& soup, const Sources& sources, MeshKind kind, HeatOptions heat) {
    return with_mesh(soup, kind, [&](auto& tm) { return run_one_shot(tm, soup, sources, heat); });
}

}  // namespace tapeline_test::geodesic::cgal

namespace tapeline_test::geodesic {

std::vector<Field> heat_queries(const Soup& soup, const std::vector<Sources>& queries,
                                HeatOptions heat, MeshKind kind) {
    if (kind == MeshKind::polyhedron) {
        cgal::Polyhedron tm;
        cgal::build(soup, tm);
        return cgal::run_heat(tm, soup, queries, heat);
    }
    cgal::SurfaceMesh tm;
    cgal::build(soup, tm, kind == MeshKind::surface_mesh_with_garbage);
    return cgal::run_heat(tm, soup, queries, heat);
}

}  // namespace tapeline_test::geodesic
