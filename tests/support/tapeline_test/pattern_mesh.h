// Plain facade over the CGAL piece mesher (pattern/meshing.h), compiled once in
// support/pattern_mesh.cpp so that test files do not include CGAL (DESIGN.md §5).
#pragma once

#include <tapeline/pattern/meshing_types.h>
#include <tapeline/pattern/pattern.h>

namespace tapeline_test {

/// tapeline::pattern::mesh_pattern.
tapeline::pattern::PatternMesh mesh_pattern(const tapeline::pattern::Pattern& pattern,
                                            const tapeline::pattern::MeshingOptions& options = {},
                                            tapeline::pattern::MeshingReport* report = nullptr);

}  // namespace tapeline_test
