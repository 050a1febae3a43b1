#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include "surfaces_mesh_summary_impl.h"

namespace tapeline_test {

SurfaceMeshSummary summarize_surface_mesh(const tapeline::SurfaceSpec& spec) {
    using Kernel = CGAL::Simple_cartesian<double>;
    return internal::summarize<CGAL::Surface_mesh<Kernel::Point_3>>(spec);
}

}  // namespace tapeline_test
