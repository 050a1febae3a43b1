// The named geodesic distance methods ("exact-mmp", "heat-idt", "gcf-window:16/faces", ...): one
// table that `tapeline geodesic distances` and `tapeline bench geodesic` both run from, so that a
// method means the same options in a single run and in a benchmark, and the options logged with a
// benchmark line are the ones the run used.
#pragma once

#include <tapeline/bench/surfaces.h>
#include <tapeline/core/mesh_io_types.h>
#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/point_cloud_types.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Sources = geodesic::SourceSet<Mesh>;

/// A mesh as received: from a file (with the input-order vertex mapping) or generated from an
/// analytic surface spec (identity mapping, exact smooth distances available).
struct InputMesh {
    LoadedMesh<Mesh> loaded;
    std::optional<SurfaceSpec> spec;
    std::string name;    // spec string or file name, as it appears in benchmark lines
    std::string family;  // groups sizes of one surface for scaling fits
    std::string file;    // empty for generated surfaces
};

InputMesh load_input_mesh_file(const std::string& path, bool strict);
InputMesh make_input_surface(const std::string& spec_text, std::uint64_t seed = 1);

/// The vertex positions of `mesh`, by vertex index (for the analytic distances of surfaces.h).
std::vector<std::array<double, 3>> mesh_points(const Mesh& mesh);

/// Distances per mesh vertex (index = Surface_mesh vertex index) and what the method reported
/// (the part every method's report shares).
struct MethodResult {
    std::vector<double> distances;
    geodesic::DistanceReport report;
    /// Figures of the method's own report that the benchmark line carries (gcf-exact and
    /// gcf-window: epsilon, max_faces and error_bound, the terms of the thesis' O(epsilon m)
    /// bound); an empty object for the others.
    nlohmann::json extra = nlohmann::json::object();
};

/// The window of gcf-window and gcf-points when the method name carries none: the library's
/// windowed default (PointCloudDistanceOptions::window). CurvatureFlowDistanceOptions::window
/// defaults to 0, Algorithm 1, which is the method gcf-exact.
inline std::size_t default_window() {
    return geodesic::PointCloudDistanceOptions{}.window;
}

/// What a run may set beyond the method name: the window of gcf-window and gcf-points when the
/// name carries none, the point-cloud options of gcf-points (cell_size, neighbours, projection;
/// its window comes from the name), and for gcf-points Gaussian noise added to the points first
/// (sigma as a fraction of the bounding-box diagonal, seeded).
struct MethodSettings {
    std::size_t window = default_window();
    geodesic::PointCloudDistanceOptions points;
    double noise = 0;
    std::uint64_t seed = 1;
};

/// "mls" or "plane"; InvalidInput naming `option` otherwise.
geodesic::PointCloudProjection parse_projection(const std::string& text, const std::string& option);

/// The distance methods, in the order they are listed in --help.
const std::vector<std::string>& distance_methods();

/// A method name as given ("gcf-window:16", "gcf-exact/faces", "gcf-window:8/faces/raw",
/// "gcf-window:8/faces/steps:200"): the method, its window, whether a curvature-flow method
/// reports the length of its samples on the faces (like for like with exact polyhedral) instead
/// of the Phong-lifted length (towards the smooth surface), whether the on-face field gets its
/// repair pass (not with "/raw"; see CurvatureFlowDistanceOptions::repair_tolerance), and the
/// flow steps of one window ("/steps:N", CurvatureFlowDistanceOptions::window_max_iterations;
/// 0: the library's default).
struct MethodName {
    std::string base;
    std::size_t window;
    bool on_faces;
    bool repair;
    std::size_t window_steps = 0;
};
/// Splits "gcf-window:W" / "gcf-window-thesis:W", a trailing "/steps:N" on those, and a trailing
/// "/faces" or "/faces/raw" on gcf-* methods; other names are returned whole with `window`.
/// InvalidInput for a ':W', '/steps:N' or '/faces' on another method, a '/raw' without '/faces'
/// or a W or N that is not a positive integer.
MethodName parse_method_name(const std::string& text, std::size_t window = default_window());

/// InvalidInput naming `option` unless `method` names a known method.
void check_method_name(const std::string& option, const std::string& method);

/// Runs `method`; throws InvalidInput for an unknown name or a source the method cannot take.
MethodResult run_distance_method(const std::string& method, const Mesh& mesh,
                                 const Sources& sources, const MethodSettings& settings = {});

/// The options `method` runs with under `settings`, as the library's JSON writers write them
/// (plus "noise" for gcf-points: the points are perturbed before the library sees them).
nlohmann::json method_options_json(const std::string& method, const MethodSettings& settings = {});

/// Distances on a point set read from a file (.xyz, .csv, .ply): one per point, in file order.
struct PointCloudRun {
    std::vector<double> distances;
    geodesic::PointCloudDistanceReport report;
};
PointCloudRun run_point_cloud_file(const std::string& path, std::size_t source,
                                   const geodesic::PointCloudDistanceOptions& options);

/// Exact distances from every source to every vertex (row s: sources[s]; indexed by vertex
/// index, +infinity where unreachable): geodesic::exact_mmp_distance_matrix, one propagation per
/// row, the rows on `threads` threads (0: every hardware thread).
std::vector<std::vector<double>> exact_mmp_matrix(const Mesh& mesh,
                                                  const std::vector<Vertex>& sources,
                                                  unsigned threads);

/// Current resident set size of this process, in bytes (0 when unknown).
std::size_t current_rss_bytes();

namespace internal {
// One entry point per method family, each in its own translation unit (compiled in parallel).
MethodResult run_exact_cgal(const Mesh& mesh, const Sources& sources);
MethodResult run_exact_mmp(const Mesh& mesh, const Sources& sources);
MethodResult run_heat(const Mesh& mesh, const Sources& sources, const geodesic::HeatOptions& o);
MethodResult run_dijkstra(const Mesh& mesh, const Sources& sources);
MethodResult run_fmm(const Mesh& mesh, const Sources& sources,
                     const geodesic::FastMarchingOptions& options);
MethodResult run_gcf(const Mesh& mesh, const Sources& sources,
                     const geodesic::CurvatureFlowDistanceOptions& options);
/// gcf-points: the vertices of `mesh` as a point cloud (with noise when settings.noise > 0).
MethodResult run_gcf_points(const Mesh& mesh, const Sources& sources,
                            const geodesic::PointCloudDistanceOptions& options, double noise,
                            std::uint64_t seed);
}  // namespace internal

}  // namespace tapeline::bench
