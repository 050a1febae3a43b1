// Phong tessellation (core/phong.h) against what it must reproduce exactly: a flat mesh stays
// flat; the normal's sign does not matter; on a tube whose vertex normals are radial the lift
// along a chord is the closed form α·4t(1 − t)·r·sin²φ·cos φ and, with α = 1/2, within O(φ⁴) of
// the circle; vertex normals of a symmetric tube are radial.
#include <tapeline/core/phong.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using tapeline::phong_point;
using tapeline::vertex_normals;
using tapeline::vec3::Vec3;
using Tris = std::vector<std::array<std::uint32_t, 3>>;

/// An open tube: `rings` rings of `n` vertices on a circle of radius r, spaced `dy` apart, each
/// quad split along the same diagonal.
void tube(int n, int rings, double r, double dy, std::vector<Vec3>& pts, Tris& tris) {
    for (int k = 0; k < rings; ++k) {
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            pts.push_back({r * std::cos(a), k * dy, r * std::sin(a)});
        }
    }
    for (int k = 0; k + 1 < rings; ++k) {
        for (int i = 0; i < n; ++i) {
            const auto a = static_cast<std::uint32_t>(k * n + i);
            const auto b = static_cast<std::uint32_t>(k * n + (i + 1) % n);
            tris.push_back({a, b, b + static_cast<std::uint32_t>(n)});
            tris.push_back(
                {a, b + static_cast<std::uint32_t>(n), a + static_cast<std::uint32_t>(n)});
        }
    }
}

TEST(Phong, AFlatTriangleStaysFlat) {
    const std::array<Vec3, 3> x{Vec3{0, 0, 0}, Vec3{10, 0, 0}, Vec3{3, 7, 0}};
    const std::array<Vec3, 3> n{Vec3{0, 0, 1}, Vec3{0, 0, 1}, Vec3{0, 0, 1}};
    for (const auto& b : {std::array<double, 3>{1, 0, 0}, {0.2, 0.3, 0.5}, {0.5, 0.5, 0}}) {
        const Vec3 p = phong_point(x, n, b);
        const Vec3 flat{b[1] * 10 + b[2] * 3, b[2] * 7, 0};
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(p[static_cast<std::size_t>(k)], flat[static_cast<std::size_t>(k)], 1e-12);
        }
    }
}

TEST(Phong, TheNormalsSignDoesNotMatterAndCornersStay) {
    const std::array<Vec3, 3> x{Vec3{0, 0, 0}, Vec3{10, 0, 1}, Vec3{3, 7, -2}};
    const std::array<Vec3, 3> n{tapeline::vec3::normalized({0.1, -0.2, 1}),
                                tapeline::vec3::normalized({-0.3, 0.1, 1}),
                                tapeline::vec3::normalized({0.2, 0.4, 1})};
    std::array<Vec3, 3> flipped = n;
    flipped[1] = tapeline::vec3::scale(n[1], -1);
    const std::array<double, 3> b{0.25, 0.35, 0.4};
    const Vec3 p = phong_point(x, n, b), q = phong_point(x, flipped, b);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(p[k], q[k], 1e-12);
    }
    for (std::size_t c = 0; c < 3; ++c) {  // a corner is interpolated
        std::array<double, 3> bc{0, 0, 0};
        bc[c] = 1;
        const Vec3 pc = phong_point(x, n, bc);
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_NEAR(pc[k], x[c][k], 1e-12);
        }
    }
}

TEST(Phong, TubeChordsLiftToTheClosedFormAndNearTheCircle) {
    const int n = 10;
    const double r = 30, dy = 20;
    std::vector<Vec3> pts;
    Tris tris;
    tube(n, 5, r, dy, pts, tris);
    const std::vector<Vec3> normals = vertex_normals(pts, tris);
    // Middle ring: its normals are radial (the tube is symmetric about the ring's plane locally
    // only up to the diagonals' direction: horizontal to 1e-12 is what radial means here).
    const double phi = M_PI / n;  // half the chord's angle
    double worst_flat = 0, worst_phong = 0;
    for (int i = 0; i < n; ++i) {
        const auto v = static_cast<std::size_t>(2 * n + i);
        const double a = 2 * M_PI * i / n;
        EXPECT_NEAR(normals[v][1], 0, 1e-12) << i;
        EXPECT_NEAR(std::abs(normals[v][0] * std::cos(a) + normals[v][2] * std::sin(a)), 1, 1e-12)
            << i;
    }
    // The triangle {a, b, b + n} of the middle ring's quad i: its bottom edge a-b is a chord.
    for (std::size_t t = 0; t < tris.size(); t += 2) {
        if (tris[t][0] / n != 2) {
            continue;
        }
        for (double s : {0.1, 0.25, 0.5, 0.8}) {
            const std::array<double, 3> b{1 - s, s, 0};
            const Vec3 p = phong_point(pts, tris[t], normals, b);
            const Vec3& x0 = pts[tris[t][0]];
            const Vec3& x1 = pts[tris[t][1]];
            const Vec3 flat{(1 - s) * x0[0] + s * x1[0], x0[1], (1 - s) * x0[2] + s * x1[2]};
            const double lift = std::hypot(p[0], p[2]) - std::hypot(flat[0], flat[2]);
            // The lift is along the chord's middle direction, of length α·4s(1 − s)·r·sin²φ·cos φ.
            const double expected =
                0.5 * 4 * s * (1 - s) * r * std::sin(phi) * std::sin(phi) * std::cos(phi);
            const double along =
                ((p[0] - flat[0]) * (x0[0] + x1[0]) + (p[2] - flat[2]) * (x0[2] + x1[2])) /
                std::hypot(x0[0] + x1[0], x0[2] + x1[2]);
            EXPECT_NEAR(along, expected, 1e-9) << "s = " << s;
            EXPECT_NEAR(p[1], x0[1], 1e-12);  // stays in the ring's plane
            worst_flat = std::max(worst_flat, r - std::hypot(flat[0], flat[2]));
            worst_phong = std::max(worst_phong, std::abs(r - std::hypot(p[0], p[2])));
            EXPECT_GT(lift, 0);
        }
    }
    // The chord's middle is 1.47 mm inside the circle; the Phong point 3/8·r·φ⁴ + O(φ⁶) ≈ 0.11.
    EXPECT_NEAR(worst_flat, r * (1 - std::cos(phi)), 1e-9);
    EXPECT_LT(worst_phong, 0.09 * worst_flat);
    EXPECT_NEAR(worst_phong, 3.0 / 8 * r * std::pow(phi, 4), 0.3 * 3.0 / 8 * r * std::pow(phi, 4));
}

}  // namespace
