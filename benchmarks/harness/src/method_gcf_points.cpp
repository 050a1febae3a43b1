// `gcf-points`: geodesic distances on point sets by curvature flow (geodesic/point_cloud.h, the
// thesis' Algorithm 3), on a mesh's vertices (the benchmark method, optionally with seeded
// Gaussian noise) or on a point-set file (.xyz, .csv, .ply).
#include <tapeline/bench/methods.h>

#include <tapeline/core/errors.h>
#include <tapeline/core/point_io.h>
#include <tapeline/geodesic/point_cloud.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace tapeline::bench {

namespace internal {

MethodResult run_gcf_points(const Mesh& mesh, const Sources& sources,
                            const geodesic::PointCloudDistanceOptions& options, double noise,
                            std::uint64_t seed) {
    if (sources.vertices.size() != 1 || !sources.locations.empty()) {
        throw InvalidInput("gcf-points takes exactly one vertex source (a point of the cloud)");
    }
    if (!(noise >= 0) || !std::isfinite(noise)) {
        throw InvalidInput(
            "--noise must be finite and >= 0 (a fraction of the bounding-box "
            "diagonal)");
    }
    std::vector<std::array<double, 3>> xyz;
    xyz.reserve(num_vertices(mesh));
    std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (Vertex v : vertices(mesh)) {
        const Point& p = mesh.point(v);
        xyz.push_back({p.x(), p.y(), p.z()});
        for (int j = 0; j < 3; ++j) {
            lo[j] = std::min(lo[j], xyz.back()[j]);
            hi[j] = std::max(hi[j], xyz.back()[j]);
        }
    }
    if (noise > 0) {
        const double sigma = noise * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) +
                                               (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                               (hi[2] - lo[2]) * (hi[2] - lo[2]));
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> gauss(0.0, sigma);
        for (auto& p : xyz) {
            for (double& c : p) {
                c += gauss(rng);
            }
        }
    }
    MethodResult result;
    result.distances.assign(xyz.size(), 0.0);
    const geodesic::PointCloudDistanceReport r =
        geodesic::gcf_point_cloud_distances(xyz, static_cast<std::size_t>(sources.vertices.front()),
                                            CGAL::make_property_map(result.distances), options);
    result.report = r;
    result.report.faces = num_faces(mesh);
    return result;
}

}  // namespace internal

PointCloudRun run_point_cloud_file(const std::string& path, std::size_t source,
                                   const geodesic::PointCloudDistanceOptions& options) {
    const PointSet set = read_point_set(path);
    if (source >= set.size()) {
        throw InvalidInput("--source " + std::to_string(source) + ": point " +
                           std::to_string(source) + " does not exist (" + path + " has " +
                           std::to_string(set.size()) + " points)");
    }
    std::vector<std::vector<double>> pts(set.size());
    for (std::size_t i = 0; i < set.size(); ++i) {
        pts[i].assign(
            set.coordinates.begin() + static_cast<std::ptrdiff_t>(set.dimension * i),
            set.coordinates.begin() + static_cast<std::ptrdiff_t>(set.dimension * (i + 1)));
    }
    PointCloudRun run;
    run.distances.assign(set.size(), 0.0);
    run.report = geodesic::gcf_point_cloud_distances(
        pts, source, CGAL::make_property_map(run.distances), options);
    return run;
}

}  // namespace tapeline::bench
