// Girths round the smooth surface a mesh stands for (sections.h, smooth_points; core/phong.h)
// against closed forms: a capped tube of radius 30 mm meshed with 10 vertices per ring (18.5 mm
// chords, a wrist meshed at 20 mm) is cut level and at a tilt. The flat section's tape is the
// inscribed polygon, 3.1 mm short of the circle; the smooth one must come within a fifth of that
// of the true section (the circle, or the ellipse with semi-axes r and r/cos θ), and from inside.
#include <tapeline/measurement/internal/sections.h>
#include <tapeline/measurement/synthetic_body.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

namespace tmi = tapeline::measurement::internal;
using tapeline::measurement::ellipse_perimeter;
using tapeline::vec3::Vec3;

/// A closed tube along y: `rings` rings of n vertices (radius r, dy apart), each quad split along
/// one diagonal, closed by a fan at each end.
tmi::BodyMesh capped_tube(int n, int rings, double r, double dy) {
    tmi::BodyMesh m;
    m.name = "tube";
    for (int k = 0; k < rings; ++k) {
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            m.points.push_back({r * std::cos(a), k * dy, r * std::sin(a)});
        }
    }
    const auto N = static_cast<std::uint32_t>(n);
    for (std::uint32_t k = 0; k + 1 < static_cast<std::uint32_t>(rings); ++k) {
        for (std::uint32_t i = 0; i < N; ++i) {
            const std::uint32_t a = k * N + i, b = k * N + (i + 1) % N;
            m.triangles.push_back({a, b + N, b});
            m.triangles.push_back({a, a + N, b + N});
        }
    }
    const auto bottom = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back({0, 0, 0});
    m.points.push_back({0, (rings - 1) * dy, 0});
    const std::uint32_t top_ring = (static_cast<std::uint32_t>(rings) - 1) * N;
    for (std::uint32_t i = 0; i < N; ++i) {
        m.triangles.push_back({bottom, i, (i + 1) % N});
        m.triangles.push_back({bottom + 1, top_ring + (i + 1) % N, top_ring + i});
    }
    tmi::build_adjacency(m);
    return m;
}

struct Tapes {
    double flat = 0, smooth = 0;
};

Tapes tapes(const tmi::BodyMesh& m, const tmi::Plane& plane) {
    tmi::CutWorkspace ws;
    tmi::PlaneSection ps = tmi::section(m, plane, ws);
    EXPECT_EQ(ps.sections.size(), 1u);
    Tapes t;
    if (ps.sections.size() != 1) {
        return t;
    }
    t.flat = ps.sections[0].perimeter;
    const auto normals = tapeline::vertex_normals(m.points, m.triangles);
    tmi::Section s = ps.sections[0];
    tmi::compute_tape(tmi::smooth_points(m, normals, ps, s, 4), s);
    t.smooth = s.perimeter;
    return t;
}

TEST(SmoothSections, ALevelCutOfACoarseTubeMeasuresTheCircle) {
    const int n = 10;
    const double r = 30;
    const tmi::BodyMesh m = capped_tube(n, 9, r, 20);
    const double circle = 2 * M_PI * r, polygon = 2 * n * r * std::sin(M_PI / n);
    for (double y : {80.0, 87.0, 95.0}) {  // at a ring's height, and through its triangles
        const Tapes t = tapes(m, tmi::Plane::horizontal(y));
        EXPECT_NEAR(t.flat, polygon, 1e-9) << y;
        EXPECT_LT(t.smooth, circle) << y;
        EXPECT_LT(circle - t.smooth, 0.2 * (circle - polygon)) << y;
        std::printf("  level %.0f: flat %.3f, smooth %.3f, circle %.3f\n", y, t.flat, t.smooth,
                    circle);
    }
}

TEST(SmoothSections, ATiltedCutMeasuresTheEllipse) {
    const int n = 10;
    const double r = 30;
    const tmi::BodyMesh m = capped_tube(n, 9, r, 20);
    for (double deg : {10.0, 25.0}) {
        const double th = deg * M_PI / 180;
        const tmi::Plane plane =
            tmi::Plane::make({0, 83, 0}, {std::sin(th), std::cos(th), 0}, {1, 0, 0});
        const double ellipse = ellipse_perimeter(r / std::cos(th), r);
        const Tapes t = tapes(m, plane);
        EXPECT_LT(t.flat, ellipse) << deg;
        EXPECT_LT(std::abs(ellipse - t.smooth), 0.2 * (ellipse - t.flat)) << deg;
        std::printf("  tilt %.0f deg: flat %.3f, smooth %.3f, ellipse %.3f\n", deg, t.flat,
                    t.smooth, ellipse);
    }
}

TEST(SmoothSections, AFineTubeChangesByItsOwnSagittaOnly) {
    // 60 vertices per ring: the polygon is 0.09 mm short; the smooth tape must not overshoot.
    const int n = 60;
    const double r = 30;
    const tmi::BodyMesh m = capped_tube(n, 9, r, 20);
    const Tapes t = tapes(m, tmi::Plane::horizontal(87));
    const double circle = 2 * M_PI * r;
    EXPECT_LT(t.smooth, circle);
    EXPECT_GT(t.smooth, t.flat);
    EXPECT_LT(circle - t.smooth, 0.01);
}

}  // namespace
