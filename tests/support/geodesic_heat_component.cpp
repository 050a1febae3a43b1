// The only translation unit that instantiates CGAL Heat_method_3 (Direct and
// Intrinsic_Delaunay, on the per-component Surface_mesh copies made by HeatDistanceSolver).
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>

#include <tapeline/geodesic/heat.h>

template class tapeline::geodesic::internal::HeatComponent<tapeline_test::geodesic::cgal::Kernel>;
