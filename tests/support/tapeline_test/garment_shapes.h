// Small closed meshes and cloth grids with known analytic truth, for the garment tests (header
// only, no CGAL: test files that use them stay cheap to compile).
#pragma once

#include <tapeline/garment/drape_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tapeline_test {

using tapeline::garment::ClothModel;
using tapeline::garment::Tri;
using tapeline::garment::UV;
using tapeline::garment::Vec3;

inline constexpr double kPi = 3.14159265358979323846;

struct GarmentTriMesh {
    std::vector<Vec3> points;
    std::vector<Tri> triangles;
};

/// Signed volume (positive for a closed mesh oriented outward).
inline double signed_volume(const GarmentTriMesh& m) {
    double v6 = 0;
    for (const Tri& t : m.triangles) {
        const Vec3& a = m.points[t[0]];
        const Vec3& b = m.points[t[1]];
        const Vec3& c = m.points[t[2]];
        v6 += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return v6 / 6;
}

/// UV sphere around the y axis, vertices on the sphere, outward oriented. Its largest distance
/// to the true sphere is below the sagitta R·(1 − cos(π/slices)) + R·(1 − cos(π/(2·stacks))).
inline GarmentTriMesh uv_sphere(const Vec3& center, double radius, int slices, int stacks) {
    const double pi = 3.14159265358979323846;
    GarmentTriMesh m;
    m.points.push_back({center[0], center[1] + radius, center[2]});  // north pole: 0
    for (int i = 1; i < stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * pi * j / slices;
            m.points.push_back({center[0] + radius * std::sin(theta) * std::cos(phi),
                                center[1] + radius * std::cos(theta),
                                center[2] + radius * std::sin(theta) * std::sin(phi)});
        }
    }
    const auto south = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back({center[0], center[1] - radius, center[2]});
    auto ring = [&](int i, int j) {
        return static_cast<std::uint32_t>(1 + (i - 1) * slices + (j % slices));
    };
    for (int j = 0; j < slices; ++j) {
        m.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
        m.triangles.push_back({south, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    }
    for (int i = 1; i + 1 < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            m.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        }
    }
    return m;
}

/// Closed cylinder along the z axis (capped with a fan), outward oriented; its rim vertices lie
/// on the true cylinder, its faces within the sagitta R·(1 − cos(π/slices)).
inline GarmentTriMesh capped_cylinder(const Vec3& center, double radius, double length, int slices,
                                      int rings) {
    const double pi = 3.14159265358979323846;
    GarmentTriMesh m;
    for (int i = 0; i <= rings; ++i) {
        const double z = center[2] - length / 2 + length * i / rings;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * pi * j / slices;
            m.points.push_back(
                {center[0] + radius * std::cos(phi), center[1] + radius * std::sin(phi), z});
        }
    }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * slices + (j % slices)); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < slices; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    const auto back = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back({center[0], center[1], center[2] - length / 2});
    const auto front = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back({center[0], center[1], center[2] + length / 2});
    for (int j = 0; j < slices; ++j) {
        m.triangles.push_back({back, at(0, j + 1), at(0, j)});
        m.triangles.push_back({front, at(rings, j), at(rings, j + 1)});
    }
    return m;
}

/// Exact distance to the solid capped cylinder (axis z), signed: > 0 outside.
inline double cylinder_signed_distance(const Vec3& center, double radius, double length,
                                       const Vec3& p) {
    const double r = std::hypot(p[0] - center[0], p[1] - center[1]) - radius;
    const double z = std::abs(p[2] - center[2]) - length / 2;
    if (r <= 0 && z <= 0) {
        return std::max(r, z);
    }
    return std::hypot(std::max(r, 0.0), std::max(z, 0.0));
}

/// A flat rectangular cloth of nx × ny square cells of `cell` mm: vertex (i, j) at
/// origin + i·cell·u + j·cell·v, pattern coordinates (i·cell, j·cell), warp along u.
inline ClothModel cloth_grid(int nx, int ny, double cell, const Vec3& origin, const Vec3& u,
                             const Vec3& v) {
    ClothModel c;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            Vec3 p;
            for (int a = 0; a < 3; ++a) {
                p[a] = origin[a] + i * cell * u[a] + j * cell * v[a];
            }
            c.positions.push_back(p);
        }
    }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    auto uv = [&](int i, int j) { return UV{i * cell, j * cell}; };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            // Alternate the diagonal so that the grid has no preferred shear direction.
            if ((i + j) % 2 == 0) {
                c.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                c.rest_uv.push_back({uv(i, j), uv(i + 1, j), uv(i + 1, j + 1)});
                c.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
                c.rest_uv.push_back({uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)});
            } else {
                c.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                c.rest_uv.push_back({uv(i, j), uv(i + 1, j), uv(i, j + 1)});
                c.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
                c.rest_uv.push_back({uv(i + 1, j), uv(i + 1, j + 1), uv(i, j + 1)});
            }
            c.grain.push_back({1, 0});
            c.grain.push_back({1, 0});
        }
    }
    return c;
}

/// Index of grid vertex (i, j) in cloth_grid(nx, ...).
inline std::uint32_t grid_vertex(int nx, int i, int j) {
    return static_cast<std::uint32_t>(j * (nx + 1) + i);
}

}  // namespace tapeline_test
