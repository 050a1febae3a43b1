// The algorithms on a hand-written mesh type that models the documented concepts and little more
// (minimal_mesh.h), copied element for element from the Surface_mesh of the reference.
#define TAPELINE_GENERIC_INSTANTIATE
#include "minimal_mesh.h"
#include "run_algorithms.h"

#include <tapeline/surfaces/analytic_surfaces.h>

namespace tapeline_test::generic {

Results on_minimal_mesh(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target) {
    CGAL::Surface_mesh<CGAL::Epick::Point_3> sm;
    tapeline::make_surface_mesh(spec, sm);
    const minimal::Mesh tm = minimal::copy_of(sm);
    return run_algorithms(tm, source, target);
}

}  // namespace tapeline_test::generic
