// Test facade for the exact MMP window propagation (DESIGN.md §5): plain functions compiled once
// in tapeline_test_support_geodesic (support/geodesic_mmp*.cpp); test files include gtest and this.
// Meshes, sources and surface points are the plain types of tapeline_test/geodesic.h (soup
// numbering, barycentric coordinates over the soup corners).
#pragma once

#include <tapeline/geodesic/exact_mmp_types.h>
#include <tapeline_test/geodesic.h>

#include <cstddef>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::ExactMmpOptions;
using tapeline::geodesic::ExactMmpReport;

struct MmpField {
    std::vector<double> d;  ///< per soup vertex
    ExactMmpReport report;
};

/// The one-shot free function exact_mmp_distances.
MmpField mmp_distances(const Soup& soup, const Sources& sources,
                       MeshKind kind = MeshKind::surface_mesh, const ExactMmpOptions& options = {});

/// Same, with every named parameter spelled out (vertex_point_map, vertex_index_map,
/// face_index_map, geom_traits) on a Surface_mesh.
MmpField mmp_distances_with_named_parameters(const Soup& soup, const Sources& sources);

/// ExactMmpSolver built once, queried at several targets (path_to and distance_to); `field`
/// receives solver.distances().
std::vector<PathResult> mmp_paths(const Soup& soup, const Sources& sources,
                                  const std::vector<SurfacePoint>& targets,
                                  MeshKind kind = MeshKind::surface_mesh,
                                  const ExactMmpOptions& options = {}, MmpField* field = nullptr);

/// The free function exact_mmp_path.
PathResult mmp_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                    MeshKind kind = MeshKind::surface_mesh);

/// exact_mmp_distance_matrix: row s = distances from sources[s] (per soup vertex).
std::vector<std::vector<double>> mmp_matrix(const Soup& soup,
                                            const std::vector<SurfacePoint>& sources,
                                            MeshKind kind = MeshKind::surface_mesh,
                                            const ExactMmpOptions& options = {},
                                            unsigned threads = 0);

}  // namespace tapeline_test::geodesic
