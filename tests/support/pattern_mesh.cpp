// The CGAL instantiation of the piece mesher, behind tapeline_test/pattern_mesh.h.
#include <tapeline/pattern/meshing.h>
#include <tapeline_test/pattern_mesh.h>

namespace tapeline_test {

tapeline::pattern::PatternMesh mesh_pattern(const tapeline::pattern::Pattern& pattern,
                                            const tapeline::pattern::MeshingOptions& options,
                                            tapeline::pattern::MeshingReport* report) {
    return tapeline::pattern::mesh_pattern(pattern, options, report);
}

}  // namespace tapeline_test
