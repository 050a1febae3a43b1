// The `fmm` distance method: fast marching with obtuse corners split by unfolding (Kimmel and
// Sethian 1998), and `fmm-no-unfold`, the same without the split (to measure what it brings).
#include <tapeline/bench/methods.h>

#include <tapeline/geodesic/fast_marching.h>

namespace tapeline::bench::internal {

MethodResult run_fmm(const Mesh& mesh, const Sources& sources,
                     const geodesic::FastMarchingOptions& options) {
    MethodResult result;
    result.distances.assign(num_vertices(mesh), 0.0);
    const geodesic::FastMarchingReport r = geodesic::fast_marching_distances(
        mesh, sources, CGAL::make_property_map(result.distances), options);
    result.report = r;
    result.extra = {{"obtuse_corners", r.obtuse_corners},
                    {"virtual_edges", r.virtual_edges},
                    {"unsplit_obtuse", r.unsplit_obtuse}};
    return result;
}

}  // namespace tapeline::bench::internal
