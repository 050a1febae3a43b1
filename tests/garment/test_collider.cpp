// SignedDistanceGrid against analytic distances (sphere, capped cylinder), its sign and
// gradient, the bound outside the band, the FaceListGraph factory and the refusals.
#include <tapeline/garment/collider.h>

#include <CGAL/Surface_mesh.h>
#include <tapeline_test/expect.h>

#include <gtest/gtest.h>
#include <tapeline_test/garment_shapes.h>

#include <cmath>
#include <random>
#include <string>

namespace {

using tapeline_test::message_of;

using tapeline::garment::ColliderOptions;
using tapeline::garment::SignedDistanceGrid;
using tapeline::garment::Vec3;
using tapeline_test::GarmentTriMesh;

using tapeline_test::kPi;

double norm(const Vec3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

Vec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<double> n(0, 1);
    Vec3 v{n(rng), n(rng), n(rng)};
    const double len = norm(v);
    return {v[0] / len, v[1] / len, v[2] / len};
}

// Tolerances: the mesh lies within its sagitta H of the analytic surface, so the exact mesh
// distance differs from the analytic one by at most H; trilinear interpolation of a smooth
// distance adds at most cell²/8 · (|∂xx d| + |∂yy d| + |∂zz d|) = cell²/8 · 2/r, r the radius
// of curvature of the level set through the point (r ≥ R − band inside a sphere).
TEST(GarmentCollider, SphereDistanceSignAndGradientInTheBand) {
    const double radius = 100, cell = 5;
    const int slices = 64, stacks = 32;
    const GarmentTriMesh sphere = tapeline_test::uv_sphere({0, 0, 0}, radius, slices, stacks);
    ASSERT_GT(tapeline_test::signed_volume(sphere), 0);
    const SignedDistanceGrid grid(sphere.points, sphere.triangles, ColliderOptions{cell});
    const double band = grid.band_mm();
    EXPECT_DOUBLE_EQ(band, 4 * cell);
    const double sagitta =
        radius * (1 - std::cos(kPi / slices)) + radius * (1 - std::cos(kPi / (2 * stacks)));
    const double tolerance = sagitta + cell * cell / 8 * 2 / (radius - band);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> offset(-band, band);
    double worst = 0;
    for (int s = 0; s < 2000; ++s) {
        const Vec3 dir = random_direction(rng);
        const double truth = offset(rng);
        const Vec3 p{dir[0] * (radius + truth), dir[1] * (radius + truth),
                     dir[2] * (radius + truth)};
        Vec3 g;
        const double d = grid.signed_distance(p, &g);
        worst = std::max(worst, std::abs(d - truth));
        ASSERT_NEAR(d, truth, tolerance) << "at radius " << radius + truth;
        if (std::abs(truth) > tolerance) {
            EXPECT_EQ(d > 0, truth > 0) << "sign at radius " << radius + truth;
        }
        // Facet normals lean at most π/slices from the radial direction, and the interpolated
        // gradient turns by at most about cell/(R − band) across a cell: cos(5.6° + 3.6°) > 0.98.
        EXPECT_NEAR(norm(g), 1, 1e-9);
        EXPECT_GT(g[0] * dir[0] + g[1] * dir[1] + g[2] * dir[2], 0.98);
    }
    RecordProperty("worst_error_mm", std::to_string(worst));
    // The exact query agrees with the analytic distance within the sagitta alone.
    for (int s = 0; s < 200; ++s) {
        const Vec3 dir = random_direction(rng);
        const double truth = 250 * (s + 0.5) / 200 - 95;  // also far outside and deep inside
        const Vec3 p{dir[0] * (radius + truth), dir[1] * (radius + truth),
                     dir[2] * (radius + truth)};
        EXPECT_NEAR(grid.exact_signed_distance(p, nullptr), truth, sagitta);
    }
}

TEST(GarmentCollider, OutsideTheBandTheDefaultIsABoundWithTheRightSign) {
    const double radius = 100;
    const GarmentTriMesh sphere = tapeline_test::uv_sphere({10, 20, 30}, radius, 48, 24);
    const SignedDistanceGrid grid(sphere.points, sphere.triangles, ColliderOptions{5});
    ColliderOptions exact_options{5};
    exact_options.exact_outside_band = true;
    const SignedDistanceGrid exact(sphere.points, sphere.triangles, exact_options);
    std::mt19937 rng(3);
    for (int s = 0; s < 500; ++s) {
        const Vec3 dir = random_direction(rng);
        const double r = s % 2 ? 5 + 60 * (s % 7) / 7.0 : radius + 30 + 400 * (s % 11) / 11.0;
        const Vec3 p{10 + dir[0] * r, 20 + dir[1] * r, 30 + dir[2] * r};
        const double truth = exact.exact_signed_distance(p, nullptr);
        Vec3 g;
        const double bound = grid.signed_distance(p, &g);
        ASSERT_GT(std::abs(truth), grid.band_mm());
        EXPECT_EQ(bound > 0, truth > 0) << "r = " << r;
        EXPECT_GT(std::abs(bound), grid.band_mm()) << "r = " << r;
        EXPECT_LE(std::abs(bound), std::abs(truth) + 1e-6) << "r = " << r;
        EXPECT_NEAR(exact.signed_distance(p, nullptr), truth, 1e-9);
    }
}

TEST(GarmentCollider, ClosedCylinderSidesAndCaps) {
    const Vec3 center{5, -7, 12};
    const double radius = 50, length = 200, cell = 4;
    const int slices = 48;
    const GarmentTriMesh cylinder =
        tapeline_test::capped_cylinder(center, radius, length, slices, 8);
    ASSERT_GT(tapeline_test::signed_volume(cylinder), 0);
    const SignedDistanceGrid grid(cylinder.points, cylinder.triangles, ColliderOptions{cell});
    const double band = grid.band_mm();
    const double sagitta = radius * (1 - std::cos(kPi / slices));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    int side = 0, cap = 0;
    for (int s = 0; s < 200000 && (side < 1000 || cap < 500); ++s) {
        const Vec3 p{center[0] + unit(rng) * (radius + band),
                     center[1] + unit(rng) * (radius + band),
                     center[2] + unit(rng) * (length / 2 + band)};
        const double truth = tapeline_test::cylinder_signed_distance(center, radius, length, p);
        if (std::abs(truth) > band) {
            continue;
        }
        const double rho = std::hypot(p[0] - center[0], p[1] - center[1]);
        const double z = std::abs(p[2] - center[2]);
        // Stay two cells clear of the rims, where the field has a crease (inside) or a curvature
        // radius as small as the distance to the rim (outside): there trilinear interpolation is
        // only first-order accurate.
        const bool side_region = z < length / 2 - band - 2 * cell;
        const bool cap_region = rho < radius - band - 2 * cell;
        if (!side_region && !cap_region) {
            continue;
        }
        const double curvature_radius = side_region ? std::max(rho, radius - band) : 1e300;
        const double tolerance = sagitta + cell * cell / 8 * 2 / curvature_radius + 1e-4;
        Vec3 g;
        const double d = grid.signed_distance(p, &g);
        ASSERT_NEAR(d, truth, tolerance)
            << (side_region ? "side" : "cap") << " point at rho " << rho << ", z " << z;
        if (std::abs(truth) > tolerance) {
            EXPECT_EQ(d > 0, truth > 0);
        }
        const Vec3 outward = side_region
                                 ? Vec3{(p[0] - center[0]) / rho, (p[1] - center[1]) / rho, 0}
                                 : Vec3{0, 0, p[2] > center[2] ? 1.0 : -1.0};
        EXPECT_GT(g[0] * outward[0] + g[1] * outward[1] + g[2] * outward[2], 0.98);
        (side_region ? side : cap) += 1;
    }
    EXPECT_GE(side, 1000);
    EXPECT_GE(cap, 500);
    // Deep inside and far outside: the sign.
    EXPECT_LT(grid.signed_distance(center, nullptr), -band);
    EXPECT_GT(grid.signed_distance({center[0], center[1] + 500, center[2]}, nullptr), band);
}

TEST(GarmentCollider, FaceListGraphFactoryMatchesTheSoup) {
    using K = CGAL::Simple_cartesian<double>;
    using Mesh = CGAL::Surface_mesh<K::Point_3>;
    const GarmentTriMesh sphere = tapeline_test::uv_sphere({0, 0, 0}, 50, 24, 12);
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vs;
    for (const Vec3& p : sphere.points) {
        vs.push_back(mesh.add_vertex(K::Point_3(p[0], p[1], p[2])));
    }
    for (const auto& t : sphere.triangles) {
        ASSERT_NE(mesh.add_face(vs[t[0]], vs[t[1]], vs[t[2]]), Mesh::null_face());
    }
    const auto from_mesh = tapeline::garment::signed_distance_grid(
        mesh, ColliderOptions{3}, CGAL::parameters::vertex_point_map(mesh.points()));
    const SignedDistanceGrid from_soup(sphere.points, sphere.triangles, ColliderOptions{3});
    std::mt19937 rng(5);
    for (int s = 0; s < 100; ++s) {
        const Vec3 dir = random_direction(rng);
        const double r = 40 + s * 0.2;
        const Vec3 p{dir[0] * r, dir[1] * r, dir[2] * r};
        EXPECT_EQ(from_mesh.signed_distance(p, nullptr), from_soup.signed_distance(p, nullptr));
    }
    // A quad face is refused by name.
    Mesh quad;
    const auto a = quad.add_vertex({0, 0, 0}), b = quad.add_vertex({1, 0, 0}),
               c = quad.add_vertex({1, 1, 0}), d = quad.add_vertex({0, 1, 0});
    quad.add_face(a, b, c, d);
    EXPECT_THROW(tapeline::garment::signed_distance_grid(quad), tapeline::TopologyError);
    EXPECT_NE(message_of([&] { tapeline::garment::signed_distance_grid(quad); }).find("face 0"),
              std::string::npos);
}

TEST(GarmentCollider, InwardOrientedMeshKeepsTheSign) {
    GarmentTriMesh sphere = tapeline_test::uv_sphere({0, 0, 0}, 50, 24, 12);
    for (auto& t : sphere.triangles) {
        std::swap(t[1], t[2]);
    }
    const SignedDistanceGrid grid(sphere.points, sphere.triangles, ColliderOptions{3});
    EXPECT_LT(grid.signed_distance({0, 0, 40}, nullptr), -5);
    EXPECT_GT(grid.signed_distance({0, 0, 60}, nullptr), 5);
}

TEST(GarmentCollider, RefusesBadMeshesNamingTheElement) {
    using tapeline::InvalidInput;
    using tapeline::TopologyError;
    const GarmentTriMesh sphere = tapeline_test::uv_sphere({0, 0, 0}, 50, 16, 8);

    GarmentTriMesh open = sphere;
    open.triangles.pop_back();
    EXPECT_THROW(SignedDistanceGrid(open.points, open.triangles), TopologyError);
    const std::string open_message =
        message_of([&] { SignedDistanceGrid(open.points, open.triangles); });
    EXPECT_NE(open_message.find("boundary edge"), std::string::npos) << open_message;

    GarmentTriMesh nan = sphere;
    nan.points[5][1] = std::nan("");
    EXPECT_THROW(SignedDistanceGrid(nan.points, nan.triangles), InvalidInput);
    EXPECT_NE(message_of([&] { SignedDistanceGrid(nan.points, nan.triangles); }).find("vertex 5"),
              std::string::npos);

    GarmentTriMesh bad_index = sphere;
    bad_index.triangles[3][2] = 100000;
    const std::string index_message =
        message_of([&] { SignedDistanceGrid(bad_index.points, bad_index.triangles); });
    EXPECT_NE(index_message.find("triangle 3"), std::string::npos) << index_message;
    EXPECT_NE(index_message.find("out of range"), std::string::npos) << index_message;
    EXPECT_THROW(SignedDistanceGrid(bad_index.points, bad_index.triangles), InvalidInput);

    GarmentTriMesh doubled = sphere;  // the same face twice: non-manifold edges
    doubled.triangles.push_back(doubled.triangles[0]);
    EXPECT_NE(message_of([&] {
                  SignedDistanceGrid(doubled.points, doubled.triangles);
              }).find("non-manifold"),
              std::string::npos);

    EXPECT_NE(message_of([&] { SignedDistanceGrid({}, {}); }).find("empty mesh"),
              std::string::npos);
    EXPECT_THROW(SignedDistanceGrid({}, {}), InvalidInput);
    EXPECT_NE(message_of([&] {
                  SignedDistanceGrid(sphere.points, sphere.triangles, ColliderOptions{-1});
              }).find("cell_mm"),
              std::string::npos);
}

}  // namespace
