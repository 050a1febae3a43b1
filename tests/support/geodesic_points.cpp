// Geodesics on point sets for the tests: the only translation unit that instantiates
// point_cloud.h (Epick Point_3, Epick_d Point_d, pairs of coordinate vectors with maps).
#include <tapeline_test/point_cloud.h>

#include <tapeline/geodesic/point_cloud.h>

#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <random>
#include <utility>

namespace tapeline_test::geodesic {

namespace {

namespace tg = tapeline::geodesic;
using K3 = CGAL::Exact_predicates_inexact_constructions_kernel;
using KD = CGAL::Epick_d<CGAL::Dynamic_dimension_tag>;

template <class Run>
auto with_points(const Cloud& cloud, CloudInput input, Run&& run) {
    if (input == CloudInput::automatic)
        input = cloud.dim == 3 ? CloudInput::point_3 : CloudInput::point_d;
    if (input == CloudInput::point_3) {
        std::vector<K3::Point_3> pts;
        for (std::size_t i = 0; i < cloud.size(); ++i)
            pts.emplace_back(cloud.at(i)[0], cloud.at(i)[1], cloud.at(i)[2]);
        return run(pts, CGAL::parameters::default_values());
    }
    if (input == CloudInput::point_d) {
        std::vector<KD::Point_d> pts;
        for (std::size_t i = 0; i < cloud.size(); ++i)
            pts.emplace_back(static_cast<int>(cloud.dim), cloud.at(i), cloud.at(i) + cloud.dim);
        return run(pts, CGAL::parameters::default_values());
    }
    using Item = std::pair<std::vector<double>, int>;
    std::vector<Item> pts;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        pts.emplace_back(std::vector<double>(cloud.at(i), cloud.at(i) + cloud.dim), 0);
    return run(pts, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>()));
}

double normal01(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    return g(rng);
}

}  // namespace

CloudField cloud_distances(const Cloud& cloud, std::size_t source,
                           const PointCloudDistanceOptions& options, CloudInput input) {
    return with_points(cloud, input, [&](const auto& pts, const auto& np) {
        CloudField f;
        f.d.assign(pts.size(), -1.0);
        f.report =
            tg::gcf_point_cloud_distances(pts, source, CGAL::make_property_map(f.d), options, np);
        return f;
    });
}

CloudField cloud_distances_with_normals(const Cloud& cloud, const std::vector<double>& normals,
                                        std::size_t source,
                                        const PointCloudDistanceOptions& options) {
    using Item = std::pair<K3::Point_3, K3::Vector_3>;
    std::vector<Item> pts;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        pts.emplace_back(K3::Point_3(cloud.at(i)[0], cloud.at(i)[1], cloud.at(i)[2]),
                         K3::Vector_3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]));
    CloudField f;
    f.d.assign(pts.size(), -1.0);
    f.report = tg::gcf_point_cloud_distances(
        pts, source, CGAL::make_property_map(f.d), options,
        CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>())
            .normal_map(CGAL::Second_of_pair_property_map<Item>()));
    return f;
}

std::vector<CloudField> cloud_distances_many(const Cloud& cloud,
                                             const std::vector<std::size_t>& sources,
                                             const PointCloudDistanceOptions& options,
                                             double* prepare_seconds) {
    return with_points(cloud, CloudInput::automatic, [&](const auto& pts, const auto& np) {
        using Range = std::decay_t<decltype(pts)>;
        using NP = std::decay_t<decltype(np)>;
        const auto t0 = std::chrono::steady_clock::now();
        const tg::PointCloudGeodesicSolver<Range, NP> solver(pts, options, np);
        if (prepare_seconds)
            *prepare_seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::vector<CloudField> out;
        for (std::size_t s : sources) {
            CloudField f;
            f.d.assign(pts.size(), -1.0);
            f.report = solver.distances(s, CGAL::make_property_map(f.d));
            out.push_back(std::move(f));
        }
        return out;
    });
}

CloudPath cloud_path(const Cloud& cloud, std::size_t from, std::size_t to,
                     const PointCloudDistanceOptions& options) {
    return with_points(cloud, CloudInput::automatic, [&](const auto& pts, const auto& np) {
        const tg::PointCloudPath p = tg::gcf_point_cloud_path(pts, from, to, options, np);
        CloudPath out;
        out.xyz = p.coordinates;
        out.length = p.length;
        out.status = p.status;
        out.report = p.report;
        return out;
    });
}

Cloud random_sphere(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Cloud c;
    c.dim = 3;
    for (std::size_t i = 0; i < n; ++i) {
        Eigen::Vector3d v;
        do {
            v = {normal01(rng), normal01(rng), normal01(rng)};
        } while (v.norm() < 1e-9);
        v.normalize();
        c.xyz.insert(c.xyz.end(), {v.x(), v.y(), v.z()});
    }
    return c;
}

Cloud embed(const Cloud& cloud3, std::size_t dim, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Eigen::MatrixXd g(static_cast<Eigen::Index>(dim), static_cast<Eigen::Index>(dim));
    for (Eigen::Index i = 0; i < g.rows(); ++i)
        for (Eigen::Index j = 0; j < g.cols(); ++j)
            g(i, j) = normal01(rng);
    const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(g).householderQ();
    Cloud out;
    out.dim = dim;
    for (std::size_t i = 0; i < cloud3.size(); ++i) {
        Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dim));
        for (int j = 0; j < 3; ++j)
            x(j) = cloud3.at(i)[j];
        const Eigen::VectorXd y = q * x;
        out.xyz.insert(out.xyz.end(), y.data(), y.data() + y.size());
    }
    return out;
}

Cloud swiss_roll(std::size_t n, double height, std::uint64_t seed, std::vector<double>& plane) {
    // Arc length of the spiral (t cos t, t sin t): s(t) = (t sqrt(1 + t^2) + asinh t) / 2.
    auto arc = [](double t) { return 0.5 * (t * std::sqrt(1 + t * t) + std::asinh(t)); };
    const double pi = 3.14159265358979323846;
    const double t0 = 1.5 * pi, t1 = 4.5 * pi, s0 = arc(t0), s1 = arc(t1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Cloud c;
    c.dim = 3;
    plane.clear();
    for (std::size_t i = 0; i < n; ++i) {
        const double s = s0 + (s1 - s0) * u01(rng), h = height * u01(rng);
        double lo = t0, hi = t1;  // invert s(t) by bisection
        for (int it = 0; it < 80; ++it) {
            const double mid = 0.5 * (lo + hi);
            (arc(mid) < s ? lo : hi) = mid;
        }
        const double t = 0.5 * (lo + hi);
        c.xyz.insert(c.xyz.end(), {t * std::cos(t), h, t * std::sin(t)});
        plane.insert(plane.end(), {s, h});
    }
    return c;
}

Cloud with_noise(const Cloud& cloud, double fraction, std::uint64_t seed) {
    std::vector<double> lo(cloud.dim, 1e300), hi(cloud.dim, -1e300);
    for (std::size_t i = 0; i < cloud.size(); ++i)
        for (std::size_t j = 0; j < cloud.dim; ++j) {
            lo[j] = std::min(lo[j], cloud.at(i)[j]);
            hi[j] = std::max(hi[j], cloud.at(i)[j]);
        }
    double diag = 0;
    for (std::size_t j = 0; j < cloud.dim; ++j)
        diag += (hi[j] - lo[j]) * (hi[j] - lo[j]);
    const double sigma = fraction * std::sqrt(diag);
    std::mt19937_64 rng(seed);
    Cloud out = cloud;
    for (double& x : out.xyz)
        x += sigma * normal01(rng);
    return out;
}

Cloud cloud_of(const std::vector<std::array<double, 3>>& points) {
    Cloud c;
    c.dim = 3;
    for (const auto& p : points)
        c.xyz.insert(c.xyz.end(), p.begin(), p.end());
    return c;
}

}  // namespace tapeline_test::geodesic
