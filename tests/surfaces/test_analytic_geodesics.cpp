// Exact smooth geodesic distances on the analytic surfaces, checked against independent
// computations (quadrature of meridian arcs, great circles, a separate cylinder parametrisation)
// and metric invariants.
#include <tapeline/surfaces/analytic_geodesics.h>
#include <tapeline_test/surfaces.h>

#include <gtest/gtest.h>
#include <tapeline_test/plain_vec3.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using tapeline::AnalyticGeodesicDistance;
using tapeline::SurfaceSpec;
using Vec3 = std::array<double, 3>;

namespace {

using tapeline_test::plain::norm;
using tapeline_test::plain::pi;

double chord(const Vec3& p, const Vec3& q) {
    return norm({p[0] - q[0], p[1] - q[1], p[2] - q[2]});
}

// Meridian arc of the ellipse (a cos t, b sin t) from t0 to t1: composite Simpson with n panels.
// The integrand is analytic, so n = 20000 gives ~1e-16 relative error for b/a in [0.3, 3].
double meridian_arc(double a, double b, double t0, double t1, int n = 20000) {
    auto f = [&](double t) { return std::hypot(a * std::sin(t), b * std::cos(t)); };
    double h = (t1 - t0) / n, s = f(t0) + f(t1);
    for (int i = 1; i < n; ++i)
        s += f(t0 + i * h) * (i % 2 ? 4 : 2);
    return s * h / 3;
}

// Point on the ellipsoid with semi-axes (a, b, c) from parametric angles (t = latitude-like,
// l = longitude-like).
Vec3 on_ellipsoid(const SurfaceSpec& s, double t, double l) {
    return {s.a * std::cos(t) * std::cos(l), s.b * std::cos(t) * std::sin(l), s.c * std::sin(t)};
}

std::vector<Vec3> random_points(const SurfaceSpec& s, int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
    std::vector<Vec3> out;
    for (int i = 0; i < n; ++i) {
        double t = std::asin(2 * u() - 1), l = 2 * pi * u();
        switch (s.kind) {
            case tapeline::SurfaceKind::cylinder:
                out.push_back(
                    {s.radius * std::cos(l), s.radius * std::sin(l), s.height * (u() - 0.5)});
                break;
            case tapeline::SurfaceKind::ellipsoid:
                out.push_back(on_ellipsoid(s, t, l));
                break;
            default:
                out.push_back({std::cos(t) * std::cos(l), std::cos(t) * std::sin(l), std::sin(t)});
        }
    }
    return out;
}

const std::vector<std::string> kWithTruth = {
    "icosphere:2",         "uvsphere:8,16",           "ellipsoid:1,1,0.3:2",
    "ellipsoid:1,1,0.9:2", "ellipsoid:0.5,0.5,1.5:2", "ellipsoid:2,2,2:1",
    "ellipsoid:1,0.3,1:1", "ellipsoid:0.4,1,1:1",     "cylinder:1,2:8,2",
    "cylinder:0.5,5:8,2"};

}  // namespace

// ---- sphere
// ---------------------------------------------------------------------------------------

// Tolerance a few ulps of pi: atan2(|p x q|, p.q) is well conditioned at 0 and pi, where acos
// would lose half the digits.
TEST(AnalyticGeodesics, SphereGreatCircle) {
    AnalyticGeodesicDistance d(SurfaceSpec::parse("icosphere:3"));
    ASSERT_TRUE(d.available());
    EXPECT_EQ(d.description(), "great circle");
    EXPECT_NEAR(d({1, 0, 0}, {-1, 0, 0}), pi, 4e-16);
    EXPECT_NEAR(d({0, 0, 1}, {0, 0, -1}), pi, 4e-16);
    EXPECT_NEAR(d({1, 0, 0}, {0, 1, 0}), pi / 2, 4e-16);
    for (double t : {1e-9, 1e-6, 0.1, 1.0, 3.0, pi - 1e-7})
        EXPECT_NEAR(d({1, 0, 0}, {std::cos(t), std::sin(t), 0}), t, 4e-16 * std::max(1.0, t)) << t;
    for (const Vec3& p : random_points(SurfaceSpec::parse("icosphere:1"), 50, 3))
        EXPECT_NEAR(d(p, {-p[0], -p[1], -p[2]}), pi, 1e-15);
    EXPECT_EQ(d({0.6, 0.8, 0}, {0.6, 0.8, 0}), 0.0);
}

TEST(AnalyticGeodesics, IcosphereVertexDistances) {
    SurfaceSpec spec = SurfaceSpec::parse("icosphere:3");
    tapeline::SurfaceSoup soup = tapeline::generate_surface(spec);
    std::vector<double> dist = tapeline::analytic_distances(spec, soup.points, 0);
    ASSERT_EQ(dist.size(), soup.points.size());
    EXPECT_EQ(dist[0], 0.0);
    double farthest = 0;
    for (std::size_t i = 0; i < dist.size(); ++i) {
        EXPECT_GE(dist[i], chord(soup.points[0], soup.points[i]) * (1 - 1e-15));
        farthest = std::max(farthest, dist[i]);
    }
    // The icosphere is centrally symmetric, so the antipode of vertex 0 is a vertex.
    EXPECT_NEAR(farthest, pi, 1e-15);
    EXPECT_THROW(tapeline::analytic_distances(spec, soup.points, soup.points.size()),
                 tapeline::InvalidInput);
}

// ---- ellipsoid of revolution (GeographicLib) --------------------------------------------------

// Pole to equator and equator to a point on the same meridian: the meridian arc is the shortest
// path on any surface of revolution (arc length along the meridian has unit gradient), so
// GeographicLib must match the quadrature. Tolerance 1e-12 relative: GeodesicExact is accurate to
// ~1e-14 relative for b/a in [0.3, 3] (its documented error table) and Simpson to ~1e-16; a wrong
// latitude (geocentric or parametric instead of geodetic) is off by ~1e-2.
TEST(AnalyticGeodesics, EllipsoidMeridianArcsMatchQuadrature) {
    for (const std::string& text : {"ellipsoid:1,1,0.3:1", "ellipsoid:1,1,0.9:1",
                                    "ellipsoid:0.5,0.5,1.5:1", "ellipsoid:2,2,0.7:1"}) {
        SCOPED_TRACE(text);
        SurfaceSpec s = SurfaceSpec::parse(text);
        AnalyticGeodesicDistance d(s);
        ASSERT_TRUE(d.available());
        EXPECT_EQ(d.symmetry_axis(), 2);
        double quarter = meridian_arc(s.a, s.c, 0, pi / 2);
        EXPECT_NEAR(d({s.a, 0, 0}, {0, 0, s.c}), quarter, 1e-12 * quarter);
        EXPECT_NEAR(d({0, s.a, 0}, {0, 0, -s.c}), quarter, 1e-12 * quarter);
        for (double t : {0.1, 0.5, 1.0, 1.4}) {
            for (double l : {0.0, 2.0, -2.9}) {
                double arc = meridian_arc(s.a, s.c, 0, t);
                EXPECT_NEAR(d(on_ellipsoid(s, 0, l), on_ellipsoid(s, t, l)), arc, 1e-12 * arc)
                    << t << " " << l;
                double arc2 = meridian_arc(s.a, s.c, -0.3, t);
                EXPECT_NEAR(d(on_ellipsoid(s, -0.3, l), on_ellipsoid(s, t, l)), arc2, 1e-12 * arc2)
                    << t << " " << l;
            }
        }
    }
}

// On an oblate ellipsoid the equator is the shortest path for longitude differences up to
// (1 - f) pi; beyond that geodesics leave the equator (checked: shorter than a * dlambda).
TEST(AnalyticGeodesics, OblateEquatorialArcs) {
    struct Case {
        const char* spec;
        double f, dlambda;
    };
    for (Case c : {Case{"ellipsoid:1,1,0.3:1", 0.7, 0.3}, Case{"ellipsoid:1,1,0.3:1", 0.7, 0.9},
                   Case{"ellipsoid:2,2,1.8:1", 0.1, 2.5}}) {
        SurfaceSpec s = SurfaceSpec::parse(c.spec);
        ASSERT_LT(c.dlambda, (1 - c.f) * pi);
        AnalyticGeodesicDistance d(s);
        double expected = s.a * c.dlambda;
        EXPECT_NEAR(d({s.a, 0, 0}, {s.a * std::cos(c.dlambda), s.a * std::sin(c.dlambda), 0}),
                    expected, 1e-12 * expected)
            << c.spec << " " << c.dlambda;
    }
    AnalyticGeodesicDistance d(SurfaceSpec::parse("ellipsoid:1,1,0.3:1"));
    EXPECT_LT(d({1, 0, 0}, {-1, 0, 0}), pi * (1 - 1e-3));  // over the pole: 2 x quarter meridian
    EXPECT_NEAR(d({1, 0, 0}, {-1, 0, 0}), 2 * meridian_arc(1, 0.3, 0, pi / 2), 1e-12);
}

TEST(AnalyticGeodesics, DescriptionNamesMethodAndFlattening) {
    EXPECT_EQ(AnalyticGeodesicDistance(SurfaceSpec::parse("ellipsoid:1,1,0.3:1")).description(),
              "GeographicLib GeodesicExact (a=1, f=0.7, axis=z)");
    EXPECT_EQ(AnalyticGeodesicDistance(SurfaceSpec::parse("ellipsoid:1,2,1:1")).description(),
              "GeographicLib GeodesicExact (a=1, f=-1, axis=y)");
    EXPECT_EQ(AnalyticGeodesicDistance(SurfaceSpec::parse("cylinder:1,2:8,2")).description(),
              "unrolled cylinder (R=1)");
}

// Tolerance 1e-12 relative: GeographicLib with f = 0 against the great circle, both near ulp-exact.
TEST(AnalyticGeodesics, SphericalEllipsoidMatchesGreatCircle) {
    SurfaceSpec s = SurfaceSpec::parse("ellipsoid:2,2,2:1");
    AnalyticGeodesicDistance d(s);
    ASSERT_TRUE(d.available());
    AnalyticGeodesicDistance sphere(SurfaceSpec::parse("icosphere:1"));
    std::vector<Vec3> pts = random_points(s, 60, 11);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec3 &p = pts[i], &q = pts[i + 1];
        Vec3 pu = {p[0] / 2, p[1] / 2, p[2] / 2}, qu = {q[0] / 2, q[1] / 2, q[2] / 2};
        double expected = 2 * sphere(pu, qu);
        EXPECT_NEAR(d(p, q), expected, 1e-12 * std::max(1.0, expected)) << i;
    }
    EXPECT_NEAR(d({0, 0, 2}, {0, 0, -2}), 2 * pi, 1e-12);
}

// A = C (axis y) and B = C (axis x) are the z-axis ellipsoid with coordinates permuted; the
// distances must agree with the z-axis spec on permuted points.
TEST(AnalyticGeodesics, SymmetryAxisDetectedForEveryPairOfEqualAxes) {
    AnalyticGeodesicDistance z_axis(SurfaceSpec::parse("ellipsoid:1,1,0.3:1"));
    SurfaceSpec sy = SurfaceSpec::parse("ellipsoid:1,0.3,1:1");
    SurfaceSpec sx = SurfaceSpec::parse("ellipsoid:0.3,1,1:1");
    AnalyticGeodesicDistance y_axis(sy), x_axis(sx);
    ASSERT_TRUE(y_axis.available());
    ASSERT_TRUE(x_axis.available());
    EXPECT_EQ(y_axis.symmetry_axis(), 1);
    EXPECT_EQ(x_axis.symmetry_axis(), 0);
    std::vector<Vec3> pts = random_points(SurfaceSpec::parse("ellipsoid:1,1,0.3:1"), 40, 5);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec3 &p = pts[i], &q = pts[i + 1];
        double expected = z_axis(p, q);
        // (x, y, z) on the z-axis ellipsoid -> (x, z, y) on the y-axis one (a reflection:
        // distances do not care), and -> (z, x, y) on the x-axis one.
        EXPECT_NEAR(y_axis({p[0], p[2], p[1]}, {q[0], q[2], q[1]}), expected, 1e-12) << i;
        EXPECT_NEAR(x_axis({p[2], p[0], p[1]}, {q[2], q[0], q[1]}), expected, 1e-12) << i;
    }
    // Pole of the y-axis ellipsoid to its equator: the quarter meridian.
    EXPECT_NEAR(y_axis({0, 0.3, 0}, {0, 0, 1}), meridian_arc(1, 0.3, 0, pi / 2), 1e-12);
    EXPECT_NEAR(x_axis({0.3, 0, 0}, {0, 1, 0}), meridian_arc(1, 0.3, 0, pi / 2), 1e-12);
}

TEST(AnalyticGeodesics, NoTruthForTorusAndTriaxialEllipsoid) {
    for (const std::string& text :
         {"torus:1,0.3:8,4", "ellipsoid:1,0.6,0.3:1", "ellipsoid:1,1,0.005:1"}) {
        SCOPED_TRACE(text);
        SurfaceSpec s = SurfaceSpec::parse(text);
        AnalyticGeodesicDistance d(s);
        EXPECT_FALSE(d.available());
        EXPECT_EQ(d.description().rfind("none", 0), 0u) << d.description();
        EXPECT_THROW(d({1, 0, 0}, {0, 1, 0}), std::logic_error);
        tapeline::SurfaceSoup soup = tapeline::generate_surface(s);
        EXPECT_TRUE(tapeline::analytic_distances(s, soup.points, 0).empty());
    }
    EXPECT_EQ(AnalyticGeodesicDistance(SurfaceSpec::parse("ellipsoid:1,0.6,0.3:1")).description(),
              "none (triaxial ellipsoid)");
}

// ---- cylinder
// ------------------------------------------------------------------------------------

// Independent parametrisation: angles taken from the generator, not from the points, and the
// angular difference wrapped with fmod. Tolerance 1e-13 relative (a few ulps of the angles).
TEST(AnalyticGeodesics, CylinderUnrolledDistance) {
    for (const std::string& text : {"cylinder:1,2:8,2", "cylinder:0.5,5:8,2"}) {
        SurfaceSpec s = SurfaceSpec::parse(text);
        AnalyticGeodesicDistance d(s);
        ASSERT_TRUE(d.available());
        std::mt19937_64 rng(17);
        auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
        for (int i = 0; i < 200; ++i) {
            double t1 = 2 * pi * u(), t2 = 2 * pi * u();
            double z1 = s.height * (u() - 0.5), z2 = s.height * (u() - 0.5);
            double dt = std::fmod(std::abs(t1 - t2), 2 * pi);
            dt = std::min(dt, 2 * pi - dt);
            double expected = std::sqrt(s.radius * dt * s.radius * dt + (z1 - z2) * (z1 - z2));
            Vec3 p = {s.radius * std::cos(t1), s.radius * std::sin(t1), z1};
            Vec3 q = {s.radius * std::cos(t2), s.radius * std::sin(t2), z2};
            EXPECT_NEAR(d(p, q), expected, 1e-13 * std::max(1.0, expected)) << text << " " << i;
        }
        // Opposite generators: half the circumference around.
        EXPECT_NEAR(d({s.radius, 0, 0}, {-s.radius, 0, 0}), pi * s.radius, 1e-15);
        EXPECT_NEAR(d({s.radius, 0, -s.height / 2}, {s.radius, 0, s.height / 2}), s.height, 1e-15);
    }
}

// ---- invariants on every surface with truth ----------------------------------------------------

// Symmetry to 1e-12 relative (GeographicLib solves the inverse problem from one end; the two
// directions agree to rounding), distance >= chord, triangle inequality with 1e-12 slack.
TEST(AnalyticGeodesics, MetricInvariants) {
    for (const std::string& text : kWithTruth) {
        SCOPED_TRACE(text);
        SurfaceSpec s = SurfaceSpec::parse(text);
        AnalyticGeodesicDistance d(s);
        ASSERT_TRUE(d.available());
        std::vector<Vec3> pts = random_points(s, 60, 23);
        for (std::size_t i = 0; i + 2 < pts.size(); ++i) {
            const Vec3 &p = pts[i], &q = pts[i + 1], &r = pts[i + 2];
            double pq = d(p, q), qp = d(q, p), qr = d(q, r), pr = d(p, r);
            EXPECT_NEAR(pq, qp, 1e-12 * std::max(1.0, pq));
            EXPECT_GE(pq, chord(p, q) * (1 - 1e-14));
            EXPECT_LE(pr, pq + qr + 1e-12);
            EXPECT_EQ(d(p, p), 0.0);
        }
    }
}

TEST(AnalyticGeodesics, AnalyticDistancesMatchesPairwiseCalls) {
    for (const std::string& text : kWithTruth) {
        SCOPED_TRACE(text);
        SurfaceSpec s = SurfaceSpec::parse(text);
        tapeline::SurfaceSoup soup = tapeline::generate_surface(s);
        std::size_t source = soup.points.size() / 3;
        std::vector<double> all = tapeline::analytic_distances(s, soup.points, source);
        ASSERT_EQ(all.size(), soup.points.size());
        AnalyticGeodesicDistance d(s);
        for (std::size_t i = 0; i < all.size(); ++i)
            EXPECT_EQ(all[i], i == source ? 0.0 : d(soup.points[source], soup.points[i]));
    }
}
