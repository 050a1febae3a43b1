// Small arithmetic on std::array<double, 3> for headers that stay free of CGAL and Eigen (analytic
// surfaces, body measurement).
#pragma once

#include <array>
#include <cmath>

namespace tapeline::vec3 {

using Vec3 = std::array<double, 3>;

inline Vec3 add(const Vec3& p, const Vec3& q) {
    return {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
}
inline Vec3 sub(const Vec3& p, const Vec3& q) {
    return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline Vec3 scale(const Vec3& p, double s) {
    return {p[0] * s, p[1] * s, p[2] * s};
}
inline double dot(const Vec3& p, const Vec3& q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline Vec3 cross(const Vec3& p, const Vec3& q) {
    return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline double norm(const Vec3& p) {
    return std::sqrt(dot(p, p));
}
inline Vec3 normalized(const Vec3& p) {
    return scale(p, 1.0 / norm(p));
}

}  // namespace tapeline::vec3
