// Test facade for unfolding path strips (unfold.h): plain functions compiled once in
// tapeline_test_support_geodesic (support/geodesic_unfold.cpp); test files include gtest and this.
// Face and vertex indices in the results are soup polygon and point indices.
#pragma once

#include <tapeline/geodesic/unfold_types.h>
#include <tapeline_test/geodesic.h>

#include <string>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::UnfoldedFace;
using tapeline::geodesic::UnfoldedPath;
using tapeline::geodesic::UnfoldOptions;

/// The free function unfold_path on the mesh built from `soup`.
UnfoldedPath unfold(const Soup& soup, const std::vector<Vec3>& path,
                    const UnfoldOptions& options = {}, MeshKind kind = MeshKind::surface_mesh);

/// write_unfold_svg into a string.
std::string unfold_svg(const UnfoldedPath& u, const std::string& title);

}  // namespace tapeline_test::geodesic
