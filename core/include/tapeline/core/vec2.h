// The plane point and vector of Tapeline: pattern outlines (millimetres, y up), pictures (page
// millimetres, y down) and plots share it, so geometry written for one works for the others.
// No dependency beyond the standard library.
#pragma once

#include <algorithm>
#include <cmath>

namespace tapeline {

/// A 2D point or vector (pattern geometry, drawing).
struct Vec2 {
    double x = 0;  ///< first coordinate
    double y = 0;  ///< second coordinate
};

inline bool operator==(const Vec2& a, const Vec2& b) {
    return a.x == b.x && a.y == b.y;
}
inline bool operator!=(const Vec2& a, const Vec2& b) {
    return !(a == b);
}
inline Vec2 operator+(const Vec2& a, const Vec2& b) {
    return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(const Vec2& a, const Vec2& b) {
    return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator*(double s, const Vec2& a) {
    return {s * a.x, s * a.y};
}
inline double dot(const Vec2& a, const Vec2& b) {
    return a.x * b.x + a.y * b.y;
}
/// z of the 3D cross product: positive when b is counter-clockwise of a (y up).
inline double cross(const Vec2& a, const Vec2& b) {
    return a.x * b.y - a.y * b.x;
}
inline double norm(const Vec2& a) {
    return std::hypot(a.x, a.y);
}
inline double distance(const Vec2& a, const Vec2& b) {
    return norm(b - a);
}
/// `a` turned a quarter turn counter-clockwise (to the left of the direction `a`, y up).
inline Vec2 left_normal(const Vec2& a) {
    return {-a.y, a.x};
}
inline bool is_finite(const Vec2& p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}
/// Distance from p to the closed segment [a, b] (to a when the segment is a point).
inline double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double len2 = dot(d, d);
    if (len2 == 0) {
        return distance(p, a);
    }
    const double t = std::clamp(dot(p - a, d) / len2, 0.0, 1.0);
    return distance(p, a + t * d);
}

}  // namespace tapeline
