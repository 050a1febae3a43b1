// The reference: the algorithms on CGAL::Surface_mesh.
#define TAPELINE_GENERIC_INSTANTIATE
#include "run_algorithms.h"

#include <tapeline/surfaces/analytic_surfaces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tapeline_test::generic {

Results on_surface_mesh(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target) {
    CGAL::Surface_mesh<CGAL::Epick::Point_3> tm;
    tapeline::make_surface_mesh(spec, tm);
    return run_algorithms(tm, source, target);
}

}  // namespace tapeline_test::generic
