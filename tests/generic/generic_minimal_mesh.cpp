// The algorithms on a mesh type that models the concepts and nothing more (minimal_mesh.h).
#define TAPELINE_GENERIC_INSTANTIATE
#include "minimal_mesh.h"
#include "run_algorithms.h"

namespace tapeline_test::generic {

Results on_minimal_mesh(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target) {
    const tapeline::SurfaceSoup soup = tapeline::generate_surface(spec);
    std::vector<minimal::Point> points;
    for (const auto& p : soup.points) {
        points.emplace_back(p[0], p[1], p[2]);
    }
    const minimal::Mesh tm(std::move(points), soup.triangles);
    return run_algorithms(tm, source, target);
}

}  // namespace tapeline_test::generic
