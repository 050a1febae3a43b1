// The smooth surface a triangle mesh stands for: area-weighted vertex normals and Phong
// tessellation (T. Boubekeur, M. Alexa, "Phong Tessellation", ACM TOG 27(5), SIGGRAPH Asia 2008).
//
// The flat point p = Σ b_i X_i of a triangle at barycentric b is projected onto the tangent plane
// of each corner, π_i(p) = p − ((p − X_i)·N_i) N_i, and blended: p* = (1 − α) p + α Σ b_i π_i(p).
// With the shape factor α = 1/2 a chord of a circle between two vertices whose normals are radial
// is lifted onto the circle to leading order: along the chord at t the lift is
// α·4·t(1 − t)·r·sin²φ·cos φ (φ: half the chord's angle), the circle's own offset from the chord
// is r(cos((1 − 2t)φ) − cos φ) ≈ 4·t(1 − t)·r·φ²/2, short by (3/8)·r·φ⁴ at the chord's middle. A
// 30 mm tube meshed with 10 vertices around (18.5 mm chords, a wrist meshed at 20 mm) is 1.6 %
// short round its flat facets and 0.3 % round this surface (tests/measurement/
// test_smooth_sections.cpp).
// On an edge the point depends on that edge's two vertices alone, so the surface is continuous
// across triangles. The normal's sign cancels (N_i appears twice): the mesh's orientation does not
// matter, only that each vertex's faces agree on it.
#pragma once

#include <tapeline/core/vec3.h>

#include <array>
#include <cstdint>
#include <vector>

namespace tapeline {

/// Unit vertex normals, each the area-weighted sum of its triangles' normals (zero for a vertex
/// no triangle uses, or whose triangles' normals cancel).
inline std::vector<vec3::Vec3> vertex_normals(
    const std::vector<vec3::Vec3>& pts, const std::vector<std::array<std::uint32_t, 3>>& tris) {
    std::vector<vec3::Vec3> n(pts.size(), vec3::Vec3{0, 0, 0});
    for (const auto& t : tris) {
        const vec3::Vec3& a = pts[t[0]];
        const vec3::Vec3 f = vec3::cross(vec3::sub(pts[t[1]], a), vec3::sub(pts[t[2]], a));
        for (std::uint32_t v : t) {
            n[v] = vec3::add(n[v], f);  // twice the area times the unit normal
        }
    }
    for (auto& v : n) {
        const double len = vec3::norm(v);
        v = len > 0 ? vec3::Vec3{v[0] / len, v[1] / len, v[2] / len} : vec3::Vec3{0, 0, 0};
    }
    return n;
}

/// The point of the Phong surface at barycentric `b` of the triangle with corners `x` and corner
/// normals `n` (see the file comment); `shape` is α.
inline vec3::Vec3 phong_point(const std::array<vec3::Vec3, 3>& x,
                              const std::array<vec3::Vec3, 3>& n, const std::array<double, 3>& b,
                              double shape = 0.5) {
    vec3::Vec3 p{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
        p = vec3::add(p, vec3::scale(x[i], b[i]));
    }
    vec3::Vec3 lift{0, 0, 0};  // Σ b_i (π_i(p) − p)
    for (std::size_t i = 0; i < 3; ++i) {
        const double h = vec3::dot(vec3::sub(p, x[i]), n[i]);
        lift = vec3::sub(lift, vec3::scale(n[i], b[i] * h));
    }
    return vec3::add(p, vec3::scale(lift, shape));
}

/// phong_point for triangle `t` of a mesh with points `x` and vertex normals `n`.
template <class Triangle>
vec3::Vec3 phong_point(const std::vector<vec3::Vec3>& x, const Triangle& t,
                       const std::vector<vec3::Vec3>& n, const std::array<double, 3>& b,
                       double shape = 0.5) {
    return phong_point({x[t[0]], x[t[1]], x[t[2]]}, {n[t[0]], n[t[1]], n[t[2]]}, b, shape);
}

}  // namespace tapeline
