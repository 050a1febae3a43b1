// The algorithms on CGAL::Polyhedron_3 without vertex or face ids (index maps come from CGAL's
// dynamic property maps).
#define TAPELINE_GENERIC_INSTANTIATE
#include "run_algorithms.h"

#include <tapeline/surfaces/analytic_surfaces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

namespace tapeline_test::generic {

Results on_polyhedron(const tapeline::SurfaceSpec& spec, std::size_t source, std::size_t target) {
    CGAL::Polyhedron_3<CGAL::Epick> tm;
    tapeline::make_surface_mesh(spec, tm);
    return run_algorithms(tm, source, target);
}

}  // namespace tapeline_test::generic
