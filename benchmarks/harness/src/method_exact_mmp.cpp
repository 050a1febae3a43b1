#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/exact_mmp.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <thread>

namespace tapeline::bench {

std::vector<std::vector<double>> exact_mmp_matrix(const Mesh& mesh,
                                                  const std::vector<Vertex>& sources,
                                                  unsigned threads) {
#ifdef CGAL_LINKED_WITH_TBB
    // The rows run in TBB's arena: bound it to `threads` (0: every hardware thread).
    const tbb::global_control control(
        tbb::global_control::max_allowed_parallelism,
        std::max(1u, threads ? threads : std::thread::hardware_concurrency()));
#endif
    std::vector<geodesic::SurfacePoint<Mesh>> points(sources.begin(), sources.end());
    return geodesic::exact_mmp_distance_matrix(mesh, points, {}, CGAL::parameters::default_values(),
                                               threads);
}

}  // namespace tapeline::bench

namespace tapeline::bench::internal {

MethodResult run_exact_mmp(const Mesh& mesh, const Sources& sources) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    result.report =
        geodesic::exact_mmp_distances(mesh, sources, CGAL::make_property_map(result.distances));
    return result;
}

}  // namespace tapeline::bench::internal
