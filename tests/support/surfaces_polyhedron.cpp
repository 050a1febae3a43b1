#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include "surfaces_mesh_summary_impl.h"

namespace tapeline_test {

SurfaceMeshSummary summarize_polyhedron(const tapeline::SurfaceSpec& spec) {
    using Kernel = CGAL::Simple_cartesian<double>;
    return internal::summarize<CGAL::Polyhedron_3<Kernel>>(spec);
}

}  // namespace tapeline_test
