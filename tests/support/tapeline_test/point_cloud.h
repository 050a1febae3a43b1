// Test facade for geodesics on point sets (point_cloud.h, DESIGN.md §5): plain functions compiled
// once in tapeline_test_support_geodesic (support/geodesic_points.cpp); test files include gtest
// and this. A cloud is a flat coordinate array of any dimension.
#pragma once

#include <tapeline/geodesic/point_cloud_types.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::PointCloudDistanceOptions;
using tapeline::geodesic::PointCloudDistanceReport;
using tapeline::geodesic::PointCloudKnn;
using tapeline::geodesic::PointCloudProjection;

struct Cloud {
    std::size_t dim = 3;
    std::vector<double> xyz;  ///< point i is [dim i, dim i + dim)
    std::size_t size() const { return dim ? xyz.size() / dim : 0; }
    const double* at(std::size_t i) const { return xyz.data() + dim * i; }
};

/// How the points are handed to the library (each a PointRange + point_map).
enum class CloudInput {
    point_3,      ///< std::vector<Epick::Point_3>, identity point map (dim 3 only)
    point_d,      ///< std::vector<Epick_d<Dynamic_dimension_tag>::Point_d>
    array_pairs,  ///< std::vector<std::pair<std::vector<double>, int>>, First_of_pair map
    automatic,    ///< point_3 for dim 3, point_d otherwise
};

struct CloudField {
    std::vector<double> d;  ///< per point
    PointCloudDistanceReport report;
};

/// The one-shot gcf_point_cloud_distances.
CloudField cloud_distances(const Cloud& cloud, std::size_t source,
                           const PointCloudDistanceOptions& options = {},
                           CloudInput input = CloudInput::automatic);

/// Same with a normal_map (dim 3: std::pair<Point_3, Vector_3>, First/Second_of_pair maps).
CloudField cloud_distances_with_normals(const Cloud& cloud, const std::vector<double>& normals,
                                        std::size_t source,
                                        const PointCloudDistanceOptions& options = {});

/// One PointCloudGeodesicSolver, several sources; prepare_seconds is its construction.
std::vector<CloudField> cloud_distances_many(const Cloud& cloud,
                                             const std::vector<std::size_t>& sources,
                                             const PointCloudDistanceOptions& options,
                                             double* prepare_seconds = nullptr);

struct CloudPath {
    std::vector<double> xyz;  ///< dim per sample
    double length = 0;
    std::string status;
    PointCloudDistanceReport report;
};
/// The one-shot gcf_point_cloud_path.
CloudPath cloud_path(const Cloud& cloud, std::size_t from, std::size_t to,
                     const PointCloudDistanceOptions& options = {});

// --- sample sets ---------------------------------------------------------------------------------

/// n points uniformly on the unit sphere (seeded).
Cloud random_sphere(std::size_t n, std::uint64_t seed);
/// The same sphere embedded isometrically in R^D (x, y, z, 0, ..., 0) times a seeded random
/// orthogonal D x D matrix (QR of a Gaussian matrix).
Cloud embed(const Cloud& cloud3, std::size_t dim, std::uint64_t seed);
/// Swiss roll (t cos t, h, t sin t), t in [1.5 pi, 4.5 pi], h in [0, height], uniform in the
/// unrolled plane (arc length s(t), h); `plane` receives (s, h) per point.
Cloud swiss_roll(std::size_t n, double height, std::uint64_t seed, std::vector<double>& plane);
/// Gaussian noise of sigma = fraction * bounding-box diagonal on every coordinate (seeded).
Cloud with_noise(const Cloud& cloud, double fraction, std::uint64_t seed);
/// The vertices of a mesh soup as a cloud.
Cloud cloud_of(const std::vector<std::array<double, 3>>& points);

}  // namespace tapeline_test::geodesic
