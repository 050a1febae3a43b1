// Test facade for geodesic paths by geodesic curvature flow (DESIGN.md §5): plain functions
// compiled once in tapeline_test_support_geodesic (support/geodesic_gcf.cpp); test files include
// gtest and this. Meshes and surface points are the plain types of tapeline_test/geodesic.h.
#pragma once

#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline_test/geodesic.h>

#include <utility>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::CeresLinearSolver;
using tapeline::geodesic::CurvatureFlowDistanceOptions;
using tapeline::geodesic::CurvatureFlowDistanceReport;
using tapeline::geodesic::CurvatureFlowOptions;
using tapeline::geodesic::CurvatureFlowReport;
using tapeline::geodesic::CurvatureFlowSolver;
using tapeline::geodesic::WindowAnchor;

struct GcfResult {
    PathResult smooth;   ///< samples lifted towards the smooth surface (distance = length)
    PathResult on_mesh;  ///< path traced on the faces (distance = length)
    CurvatureFlowReport report;
};

/// The free function geodesic_path (curvature flow) between two surface points.
GcfResult gcf_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                   const CurvatureFlowOptions& options = {},
                   MeshKind kind = MeshKind::surface_mesh);

/// Same, with every named parameter spelled out (vertex_point_map, vertex_index_map,
/// face_index_map, geom_traits) on a Surface_mesh.
GcfResult gcf_path_with_named_parameters(const Soup& soup, const SurfacePoint& from,
                                         const SurfacePoint& to);

/// The geodesic_path overload started from a caller-given polyline.
GcfResult gcf_path_from_polyline(const Soup& soup, const std::vector<Vec3>& initial,
                                 const CurvatureFlowOptions& options = {},
                                 MeshKind kind = MeshKind::surface_mesh);

/// One GeodesicPathSolver built once (prepare_seconds), queried for every pair.
struct GcfQueries {
    double prepare_seconds = 0;
    std::vector<GcfResult> paths;
};
GcfQueries gcf_paths(const Soup& soup,
                     const std::vector<std::pair<SurfacePoint, SurfacePoint>>& pairs,
                     const CurvatureFlowOptions& options = {},
                     MeshKind kind = MeshKind::surface_mesh);

/// The same pairs through GeodesicPathSolver::paths (in parallel with TBB); prepare_seconds is
/// the solver construction, and `seconds` (if given) the wall time of the paths() call.
GcfQueries gcf_paths_parallel(const Soup& soup,
                              const std::vector<std::pair<SurfacePoint, SurfacePoint>>& pairs,
                              const CurvatureFlowOptions& options = {}, double* seconds = nullptr);

/// Whether the Ceres flow-step solver (tapeline::geodesic_ceres) is built into the tests; linking
/// this function also registers it, so CurvatureFlowSolver::ceres can be used.
bool gcf_ceres_available();
/// Registers (true) or removes (false) the Ceres solver, to test the message when it is missing.
void gcf_ceres_register(bool on);

struct GcfField {
    std::vector<double> d;  ///< per soup vertex
    CurvatureFlowDistanceReport report;
};

/// The free function gcf_distances from soup vertex `source`.
GcfField gcf_distances(const Soup& soup, std::size_t source,
                       const CurvatureFlowDistanceOptions& options = {},
                       MeshKind kind = MeshKind::surface_mesh);

/// Distances from soup vertex `source` over the repair pass's Steiner graph
/// (internal/gcf_steiner.h): per_edge points inside every edge, near_per_edge inside those with
/// an end within near_radius mean edge lengths of the source. Per soup vertex.
std::vector<double> steiner_distances(const Soup& soup, std::size_t source, unsigned per_edge,
                                      unsigned near_per_edge = 0, double near_radius = 0);

}  // namespace tapeline_test::geodesic
