// Types shared by the command-line tool's translation units.
#pragma once

#include <tapeline/core/mesh_io.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/point_cloud_types.h>
#include <tapeline/geodesic/sources.h>
#include <tapeline/surfaces/analytic_surfaces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <optional>
#include <string>
#include <vector>

namespace tapeline::app {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Sources = geodesic::SourceSet<Mesh>;

/// A mesh as the tool received it: from a file (with the input-order vertex mapping) or generated
/// from an analytic surface spec (identity mapping, exact smooth distances available).
struct InputMesh {
    LoadedMesh<Mesh> loaded;
    std::optional<SurfaceSpec> spec;
    std::string name;    // spec string or file name, as it appears in benchmark lines
    std::string family;  // groups sizes of one surface for scaling fits
    std::string file;    // empty for generated surfaces
};

InputMesh load_input_mesh_file(const std::string& path, bool strict);
InputMesh make_input_surface(const std::string& spec_text, std::uint64_t seed = 1);

/// Distances per mesh vertex (index = Surface_mesh vertex index) and what the method reported.
struct MethodResult {
    std::vector<double> distances;
    geodesic::DistanceReport report;
};

/// Settings of the gcf-points method (the mesh's vertices taken as a point cloud): grid cell (0:
/// automatic), neighbours d, projection ("mls" or "plane") and Gaussian noise added to the points
/// first (sigma as a fraction of the bounding-box diagonal, seeded).
struct PointsMethodOptions {
    double cell = 0;
    std::size_t neighbours = 16;
    std::string projection = "mls";
    double noise = 0;
    std::uint64_t seed = 1;
};

/// The distance methods the tool knows, in the order they are listed in --help.
const std::vector<std::string>& distance_methods();
/// Runs `method` ("exact-mmp", "exact-cgal", "heat", "heat-idt", "dijkstra"); throws InvalidInput
/// for an unknown name or a source the method cannot take.
/// `window` is the window of gcf-window (samples flowed per vertex) unless the name carries one
/// ("gcf-window:16").
MethodResult run_distance_method(const std::string& method, const Mesh& mesh,
                                 const Sources& sources, std::size_t window = 8,
                                 const PointsMethodOptions& points = {});

/// A method name as given ("gcf-window:16", "gcf-exact/faces", "gcf-window:8/faces/raw"): the
/// method, its window, whether a curvature-flow method reports the length of its samples on the
/// faces (like for like with exact polyhedral) instead of the Phong-lifted length (towards the
/// smooth surface), and whether the on-face field gets its repair pass (not with "/raw"; see
/// CurvatureFlowDistanceOptions::repair_tolerance).
struct MethodName {
    std::string base;
    std::size_t window;
    bool on_faces;
    bool repair;
};
/// Splits "gcf-window:W" / "gcf-window-thesis:W" and a trailing "/faces" or "/faces/raw" on gcf-*
/// methods; other names are returned whole with `window`. InvalidInput for a ':W' or '/faces' on
/// another method, a '/raw' without '/faces' or a W that is not a positive integer.
MethodName parse_method_name(const std::string& text, std::size_t window);

// One entry point per method family, each in its own translation unit (compile in parallel).
MethodResult run_exact_cgal(const Mesh& mesh, const Sources& sources);
MethodResult run_exact_mmp(const Mesh& mesh, const Sources& sources);
MethodResult run_heat(const Mesh& mesh, const Sources& sources, bool intrinsic_delaunay);
MethodResult run_dijkstra(const Mesh& mesh, const Sources& sources);
/// gcf-exact (window 0), gcf-window (field anchor) or, with `thesis_anchor`, gcf-window-thesis
/// (the thesis' prefix rule).
MethodResult run_gcf(const Mesh& mesh, const Sources& sources, std::size_t window,
                     bool thesis_anchor, bool on_faces, bool repair);

/// gcf-points: the vertices of `mesh` as a point cloud (optionally with noise), distances by the
/// point-cloud flow (geodesic/point_cloud.h) from the one vertex source.
MethodResult run_gcf_points(const Mesh& mesh, const Sources& sources, std::size_t window,
                            const PointsMethodOptions& points);

/// Distances on a point set read from a file (.xyz, .csv, .ply): one per point, in file order.
struct PointCloudRun {
    std::vector<double> distances;
    geodesic::PointCloudDistanceReport report;
};
PointCloudRun run_point_cloud_file(const std::string& path, std::size_t source, std::size_t window,
                                   const PointsMethodOptions& points);

/// Peak and current resident set size of this process, in bytes (0 when unknown).
std::size_t current_rss_bytes();

}  // namespace tapeline::app
