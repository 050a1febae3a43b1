// The main public algorithms run on one mesh type: exact MMP distances and path, heat, Dijkstra,
// fast marching, curvature-flow distances (gcf-window) and the two-point flow, unfolding. One
// source file per mesh type instantiates run_algorithms: CGAL::Surface_mesh
// (generic_surface_mesh.cpp, the reference), CGAL::Polyhedron_3 (generic_polyhedron.cpp) and the
// minimal mesh of minimal_mesh.h (generic_minimal.cpp); main.cpp compares the results.
#pragma once

#include <tapeline/surfaces/analytic_surface_types.h>

#include <cstddef>
#include <vector>

namespace tapeline_test::generic {

struct Results {
    std::vector<double> mmp, heat, dijkstra, fmm, gcf;  // per vertex, in the order of vertices(tm)
    double mmp_path = 0, gcf_path = 0, unfolded = 0;
};

/// Everything from vertex `source` (and paths to vertex `target`) on the mesh of `spec`.
Results on_surface_mesh(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target);
Results on_polyhedron(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target);
Results on_minimal_mesh(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target);

}  // namespace tapeline_test::generic

#ifdef TAPELINE_GENERIC_INSTANTIATE
#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/dijkstra.h>
#include <tapeline/geodesic/exact_mmp.h>
#include <tapeline/geodesic/fast_marching.h>
#include <tapeline/geodesic/heat.h>
#include <tapeline/geodesic/unfold.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <iterator>

namespace tapeline_test::generic {

template <class Mesh>
Results run_algorithms(const Mesh& tm, std::size_t source, std::size_t target) {
    namespace tg = tapeline::geodesic;
    const auto s = *std::next(vertices(tm).begin(), static_cast<std::ptrdiff_t>(source));
    const auto t = *std::next(vertices(tm).begin(), static_cast<std::ptrdiff_t>(target));
    const auto index = CGAL::get_initialized_vertex_index_map(tm);
    const std::size_t n = num_vertices(tm);
    Results r;
    auto field = [&](std::vector<double>& out) {
        out.assign(n, 0.0);
        return boost::make_iterator_property_map(out.begin(), index);
    };
    tg::exact_mmp_distances(tm, s, field(r.mmp));
    r.mmp_path =
        tg::exact_mmp_path(tm, tg::SurfacePoint<Mesh>(s), tg::SurfacePoint<Mesh>(t)).length;
    tg::heat_distances(tm, s, field(r.heat));
    tg::dijkstra_distances(tm, s, field(r.dijkstra));
    tg::fast_marching_distances(tm, s, field(r.fmm));
    tg::CurvatureFlowDistanceOptions gcf;
    gcf.window = 8;
    tg::gcf_distances(tm, s, field(r.gcf), gcf);
    const auto path = tg::geodesic_path(tm, tg::SurfacePoint<Mesh>(s), tg::SurfacePoint<Mesh>(t));
    r.gcf_path = path.on_mesh.length;
    r.unfolded = tg::unfold_path(tm, path.on_mesh.points).unfolded_length;
    return r;
}

}  // namespace tapeline_test::generic
#endif
