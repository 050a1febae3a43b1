// Vector arithmetic on std::array, written independently of the library: tests check the
// library's geometry against it.
#pragma once

#include <array>
#include <cmath>

namespace tapeline_test::plain {

using Vec3 = std::array<double, 3>;

inline constexpr double pi = 3.14159265358979323846;

inline Vec3 sub(const Vec3& p, const Vec3& q) {
    return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline Vec3 cross(const Vec3& p, const Vec3& q) {
    return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline double dot(const Vec3& p, const Vec3& q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline double norm(const Vec3& p) {
    return std::sqrt(dot(p, p));
}

}  // namespace tapeline_test::plain
