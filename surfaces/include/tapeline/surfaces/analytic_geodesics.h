// Exact smooth geodesic distances on the analytic test surfaces: the truth every geodesic test and
// benchmark measures against.
//
//   sphere (icosphere, uvsphere)   great-circle angle atan2(|p x q|, p.q) (accurate for tiny and
//                                  near-antipodal angles, unlike acos)
//   ellipsoid of revolution        C. F. F. Karney, "Geodesics on an arbitrary ellipsoid of
//                                  revolution", arXiv:2208.00492 (2022), via
//                                  GeographicLib::GeodesicExact, valid for any flattening
//                                  (prolate too) in b/a in [0.01, 100]
//   open cylinder                  the unrolled (developed) distance sqrt((R dtheta)^2 + dz^2),
//                                  |dtheta| <= pi: the cylinder is developable and convex in z
//   triaxial ellipsoid, torus      no truth: available() is false
//
// No CGAL here: include this from anything that needs the truth only.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/surfaces/analytic_surface_types.h>

#include <GeographicLib/GeodesicExact.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace tapeline {

/// Exact geodesic distance between points lying on the analytic surface of a SurfaceSpec.
/// Immutable after construction; operator() is const and safe to call from several threads.
class AnalyticGeodesicDistance {
public:
    /// Chooses the method for `spec` (see available()).
    ///
    /// \throws InvalidInput when a field of `spec` is out of range.
    explicit AnalyticGeodesicDistance(const SurfaceSpec& spec);

    /// False for the torus, a triaxial ellipsoid, and an ellipsoid of revolution whose axis ratio
    /// lies outside GeographicLib's accurate range [0.01, 100].
    bool available() const { return method_ != Method::none; }
    /// "great circle", "GeographicLib GeodesicExact (a=1, f=0.7, axis=z)", "unrolled cylinder
    /// (R=1)" or "none (...)" with the reason.
    std::string description() const { return description_; }

    /// Exact smooth geodesic distance between p and q, both on the surface (not checked: a point
    /// off the surface is treated as its projection along the method's coordinates).
    /// Throws std::logic_error if !available().
    ///
    /// \throws std::logic_error when !available(): a programming error, not an input error.
    double operator()(const std::array<double, 3>& p, const std::array<double, 3>& q) const;

    /// For an ellipsoid of revolution: index (0 = x, 1 = y, 2 = z) of the symmetry axis, else -1.
    int symmetry_axis() const { return axis_; }

private:
    enum class Method { none, sphere, ellipsoid, cylinder };
    // Geodetic latitude and longitude in degrees in the frame whose z is the symmetry axis.
    void lat_lon(const std::array<double, 3>& p, double& lat, double& lon) const;

    Method method_ = Method::none;
    double scale_ = 1;       // sphere and cylinder radius
    double equatorial_ = 1;  // ellipsoid of revolution
    double polar_ = 1;
    int axis_ = -1;
    std::shared_ptr<const GeographicLib::GeodesicExact> geodesic_;
    std::string description_ = "none";
};

// -------------------------------------------------------------------------------------------------

inline AnalyticGeodesicDistance::AnalyticGeodesicDistance(const SurfaceSpec& spec) {
    spec.validate();
    char buf[160];
    switch (spec.kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::uvsphere:
            method_ = Method::sphere;
            scale_ = 1;
            description_ = "great circle";
            break;
        case SurfaceKind::cylinder:
            method_ = Method::cylinder;
            scale_ = spec.radius;
            description_ = "unrolled cylinder (R=" + internal::format_number(spec.radius) + ")";
            break;
        case SurfaceKind::torus:
            description_ = "none (no closed-form geodesic distance on a torus)";
            break;
        case SurfaceKind::ellipsoid: {
            // Exact equality: an ellipsoid whose axes differ by one ulp is triaxial, and the
            // caller should know that this truth is not for it.
            const double a = spec.a, b = spec.b, c = spec.c;
            if (a == b) {
                axis_ = 2, equatorial_ = a, polar_ = c;
            } else if (a == c) {
                axis_ = 1, equatorial_ = a, polar_ = b;
            } else if (b == c) {
                axis_ = 0, equatorial_ = b, polar_ = a;
            } else {
                description_ = "none (triaxial ellipsoid)";
                break;
            }
            const double ratio = polar_ / equatorial_;
            if (!(ratio >= 0.01 && ratio <= 100)) {
                axis_ = -1;
                description_ = "none (axis ratio outside GeographicLib's range [0.01, 100])";
                break;
            }
            const double f = (equatorial_ - polar_) / equatorial_;
            geodesic_ = std::make_shared<const GeographicLib::GeodesicExact>(equatorial_, f);
            method_ = Method::ellipsoid;
            std::snprintf(buf, sizeof buf,
                          "GeographicLib GeodesicExact (a=%.10g, f=%.10g, axis=%c)", equatorial_, f,
                          "xyz"[axis_]);
            description_ = buf;
            break;
        }
    }
}

inline void AnalyticGeodesicDistance::lat_lon(const std::array<double, 3>& p, double& lat,
                                              double& lon) const {
    // Cyclic permutation taking the symmetry axis to z (keeps handedness).
    const double u = p[(axis_ + 1) % 3], v = p[(axis_ + 2) % 3], w = p[axis_];
    const double rho = std::hypot(u, v);
    const double to_degrees = 180.0 / 3.14159265358979323846;
    // Geodetic latitude: direction of the normal (rho / a^2, w / b^2).
    lat = std::atan2(w / (polar_ * polar_), rho / (equatorial_ * equatorial_)) * to_degrees;
    lon = std::atan2(v, u) * to_degrees;
}

inline double AnalyticGeodesicDistance::operator()(const std::array<double, 3>& p,
                                                   const std::array<double, 3>& q) const {
    switch (method_) {
        case Method::sphere: {
            using namespace internal;
            return scale_ * std::atan2(norm(cross(p, q)), dot(p, q));
        }
        case Method::cylinder: {
            const double dtheta =
                std::atan2(p[0] * q[1] - p[1] * q[0], p[0] * q[0] + p[1] * q[1]);  // (-pi, pi]
            return std::hypot(scale_ * dtheta, q[2] - p[2]);
        }
        case Method::ellipsoid: {
            double lat1, lon1, lat2, lon2, s12 = 0;
            lat_lon(p, lat1, lon1);
            lat_lon(q, lat2, lon2);
            geodesic_->Inverse(lat1, lon1, lat2, lon2, s12);
            return s12;
        }
        case Method::none:
            break;
    }
    throw std::logic_error("AnalyticGeodesicDistance: no analytic geodesic distance: " +
                           description_);
}

/// Distances from points[source] to every point (size of points); an empty vector if the surface
/// has no truth. Throws InvalidInput if source is out of range. `threads` = 0 uses
/// std::thread::hardware_concurrency(); the result is the same for any thread count.
///
/// \throws InvalidInput when `source` is out of range or a field of `spec` is.
inline std::vector<double> analytic_distances(const SurfaceSpec& spec,
                                              const std::vector<std::array<double, 3>>& points,
                                              std::size_t source, unsigned threads = 0) {
    if (source >= points.size())
        throw InvalidInput("analytic_distances(" + spec.to_string() + "): source " +
                           std::to_string(source) + " out of range (" +
                           std::to_string(points.size()) + " points)");
    const AnalyticGeodesicDistance distance(spec);
    if (!distance.available())
        return {};
    std::vector<double> out(points.size());
    const std::array<double, 3> s = points[source];
    auto run = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            out[i] = distance(s, points[i]);
    };
    // GeodesicExact costs ~10 us per pair, so threads pay off on large meshes; each entry is
    // computed independently, so the result does not depend on the thread count.
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t min_chunk =
        distance.description().rfind("GeographicLib", 0) == 0 ? 2000 : 200000;
    threads = static_cast<unsigned>(
        std::min<std::size_t>(threads, std::max<std::size_t>(1, points.size() / min_chunk)));
    // Chunk t is [n t / T, n (t + 1) / T); the calling thread takes chunk 0, and whatever could
    // not be handed out if the system refuses a thread.
    const std::size_t n = points.size();
    std::vector<std::thread> pool;
    try {
        for (unsigned t = 1; t < threads; ++t)
            pool.emplace_back(run, n * t / threads, n * (t + 1) / threads);
    } catch (const std::system_error&) {
        run(n * (pool.size() + 1) / threads, n);
    }
    run(0, n / threads);
    for (auto& th : pool)
        th.join();
    out[source] = 0;
    return out;
}

}  // namespace tapeline
