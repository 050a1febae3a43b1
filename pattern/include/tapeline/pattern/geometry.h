// Plane curves of sewing-pattern outlines: lines, cubic Béziers and circular arcs, in millimetres
// with y up.
//
// Lengths: lines and arcs exactly (r·|Δθ|); cubic Béziers by adaptive Gauss–Legendre quadrature of
// |B'(t)| (8-point rule, interval halving until two levels agree to the tolerance). Sampling:
// recursive subdivision of the Bézier until its control polygon lies within the tolerance of the
// chord (the curve lies in the convex hull of its control points, so the chord is then within the
// tolerance of the curve); arcs by the sagitta bound r(1 − cos(Δθ/2)) ≤ tolerance.
// Self-intersection tests work on those polylines with an O(n²) segment test culled by bounding
// boxes; outlines here have a few hundred segments, so a sweep would not pay off.
#pragma once

#include <tapeline/core/vec2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace tapeline::pattern {

/// A point or vector of the plane, in millimetres (y up): core's Vec2 under the pattern's name.
using Point2 = tapeline::Vec2;
using tapeline::cross;
using tapeline::distance;
using tapeline::dot;
using tapeline::is_finite;
using tapeline::left_normal;
using tapeline::norm;

/// Straight segment from `a` to `b`.
struct Line {
    /// Start and end.
    ///@{
    Point2 a, b;
    ///@}
};

/// Cubic Bézier from `p0` to `p3` with control points `p1`, `p2`.
struct CubicBezier {
    /// End points p0, p3 and control points p1, p2.
    ///@{
    Point2 p0, p1, p2, p3;
    ///@}
};

/// Circular arc from `a` to `b` with the given radius, with SVG's flags: `large_arc` picks the arc
/// of more than half a turn, `ccw` the counter-clockwise one (y up). Storing the endpoints rather
/// than the centre keeps consecutive edges exactly joined.
struct Arc {
    /// Start and end.
    ///@{
    Point2 a, b;
    ///@}
    double radius = 0;       ///< mm
    bool large_arc = false;  ///< the arc of more than half a turn
    bool ccw = true;         ///< counter-clockwise (y up)
};

/// The curve of an edge.
using Curve = std::variant<Line, CubicBezier, Arc>;

/// One edge of an outline, internal line or dart: a curve and an optional label (GarmentCode edge
/// labels, FreeSewing path names).
struct Edge {
    Curve curve;        ///< the geometry
    std::string label;  ///< source label, may be empty
};

/// A quadratic Bézier as the cubic that traces the same curve (degree elevation, exact).
inline CubicBezier cubic_from_quadratic(Point2 p0, Point2 c, Point2 p2) {
    return {p0, p0 + (2.0 / 3.0) * (c - p0), p2 + (2.0 / 3.0) * (c - p2), p2};
}

inline Point2 start_point(const Curve& c) {
    return std::visit(
        [](const auto& e) -> Point2 {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, CubicBezier>) {
                return e.p0;
            } else {
                return e.a;
            }
        },
        c);
}

inline Point2 end_point(const Curve& c) {
    return std::visit(
        [](const auto& e) -> Point2 {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, CubicBezier>) {
                return e.p3;
            } else {
                return e.b;
            }
        },
        c);
}

inline Point2 start_point(const Edge& e) {
    return start_point(e.curve);
}
inline Point2 end_point(const Edge& e) {
    return end_point(e.curve);
}

/// Every coordinate and radius finite.
inline bool is_finite(const Curve& c) {
    return std::visit(
        [](const auto& e) -> bool {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, Line>) {
                return is_finite(e.a) && is_finite(e.b);
            } else if constexpr (std::is_same_v<T, CubicBezier>) {
                return is_finite(e.p0) && is_finite(e.p1) && is_finite(e.p2) && is_finite(e.p3);
            } else {
                return is_finite(e.a) && is_finite(e.b) && std::isfinite(e.radius);
            }
        },
        c);
}

// --- arcs
// -----------------------------------------------------------------------------------------

/// Centre, start angle and signed sweep of an arc. A radius below half the chord is raised to
/// half the chord (a half circle), as SVG does; `radius_too_small` says so and validation reports
/// it.
struct ArcFrame {
    Point2 center;                  ///< centre of the circle
    double radius = 0;              ///< mm, after raising
    double start_angle = 0;         ///< radians, of the start point
    double sweep = 0;               ///< signed radians, > 0 counter-clockwise
    bool radius_too_small = false;  ///< the radius was raised to half the chord
};

inline ArcFrame arc_frame(const Arc& arc) {
    ArcFrame f;
    const Point2 d = arc.b - arc.a;
    const double chord = norm(d);
    const double half = 0.5 * chord;
    double r = arc.radius;
    if (!(r >= half)) {
        f.radius_too_small = !(r >= half * (1 - 1e-9));
        r = half;
    }
    f.radius = r;
    if (chord == 0) {
        f.center = arc.a;
        return f;
    }
    const double h = std::sqrt(std::max(0.0, r * r - half * half));
    const Point2 n = (1.0 / chord) * left_normal(d);
    // The minor counter-clockwise arc has its centre on the left of a→b; each flag flips the side.
    const double side = (arc.ccw != arc.large_arc) ? 1.0 : -1.0;
    f.center = 0.5 * (arc.a + arc.b) + (side * h) * n;
    const double minor = 2.0 * std::asin(std::min(1.0, half / r));
    const double angle = arc.large_arc ? 2.0 * M_PI - minor : minor;
    f.sweep = arc.ccw ? angle : -angle;
    f.start_angle = std::atan2(arc.a.y - f.center.y, arc.a.x - f.center.x);
    return f;
}

// --- evaluation
// -----------------------------------------------------------------------------------

inline Point2 point_at(const CubicBezier& c, double t) {
    const double u = 1 - t;
    const double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
    return {b0 * c.p0.x + b1 * c.p1.x + b2 * c.p2.x + b3 * c.p3.x,
            b0 * c.p0.y + b1 * c.p1.y + b2 * c.p2.y + b3 * c.p3.y};
}

inline Point2 derivative_at(const CubicBezier& c, double t) {
    const double u = 1 - t;
    const Point2 d0 = c.p1 - c.p0, d1 = c.p2 - c.p1, d2 = c.p3 - c.p2;
    return 3 * u * u * d0 + 6 * u * t * d1 + 3 * t * t * d2;
}

/// Point at parameter t ∈ [0, 1] (uniform in angle for arcs, in t for Béziers).
inline Point2 point_at(const Curve& curve, double t) {
    if (const auto* l = std::get_if<Line>(&curve)) {
        return l->a + t * (l->b - l->a);
    }
    if (const auto* c = std::get_if<CubicBezier>(&curve)) {
        if (t <= 0) {
            return c->p0;
        }
        if (t >= 1) {
            return c->p3;
        }
        return point_at(*c, t);
    }
    const Arc& a = std::get<Arc>(curve);
    if (t <= 0) {
        return a.a;
    }
    if (t >= 1) {
        return a.b;
    }
    const ArcFrame f = arc_frame(a);
    const double ang = f.start_angle + t * f.sweep;
    return {f.center.x + f.radius * std::cos(ang), f.center.y + f.radius * std::sin(ang)};
}

/// Unit tangent at parameter t (direction of travel); zero for a degenerate curve.
inline Point2 tangent_at(const Curve& curve, double t) {
    Point2 d;
    if (const auto* l = std::get_if<Line>(&curve)) {
        d = l->b - l->a;
    } else if (const auto* c = std::get_if<CubicBezier>(&curve)) {
        d = derivative_at(*c, std::clamp(t, 1e-9, 1 - 1e-9));
        if (norm(d) == 0) {
            d = c->p3 - c->p0;
        }
    } else {
        const ArcFrame f = arc_frame(std::get<Arc>(curve));
        const double ang = f.start_angle + t * f.sweep;
        d = Point2{-std::sin(ang), std::cos(ang)};
        if (f.sweep < 0) {
            d = -1.0 * d;
        }
    }
    const double n = norm(d);
    return n > 0 ? (1.0 / n) * d : Point2{};
}

/// The same curve traversed the other way.
inline Curve reversed(const Curve& curve) {
    if (const auto* l = std::get_if<Line>(&curve)) {
        return Line{l->b, l->a};
    }
    if (const auto* c = std::get_if<CubicBezier>(&curve)) {
        return CubicBezier{c->p3, c->p2, c->p1, c->p0};
    }
    Arc a = std::get<Arc>(curve);
    std::swap(a.a, a.b);
    a.ccw = !a.ccw;
    return a;
}

// --- length
// ---------------------------------------------------------------------------------------

namespace internal {

/// ∫ |B'(t)| dt on [t0, t1] by the 8-point Gauss–Legendre rule.
inline double gauss_legendre_8(const CubicBezier& c, double t0, double t1) {
    static constexpr std::array<double, 4> x = {0.1834346424956498, 0.5255324099163290,
                                                0.7966664774136267, 0.9602898564975363};
    static constexpr std::array<double, 4> w = {0.3626837833783620, 0.3137066458778873,
                                                0.2223810344533745, 0.1012285362903763};
    const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
    double sum = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        sum += w[i] * (norm(derivative_at(c, mid - half * x[i])) +
                       norm(derivative_at(c, mid + half * x[i])));
    }
    return half * sum;
}

inline double adaptive_length(const CubicBezier& c, double t0, double t1, double whole,
                              double tolerance, int depth) {
    const double mid = 0.5 * (t0 + t1);
    const double left = gauss_legendre_8(c, t0, mid);
    const double right = gauss_legendre_8(c, mid, t1);
    if (depth >= 40 || std::abs(left + right - whole) <= tolerance) {
        return left + right;
    }
    return adaptive_length(c, t0, mid, left, 0.5 * tolerance, depth + 1) +
           adaptive_length(c, mid, t1, right, 0.5 * tolerance, depth + 1);
}

}  // namespace internal

/// Arc length of a cubic Bézier on [t0, t1] to an absolute tolerance (mm).
inline double length(const CubicBezier& c, double t0 = 0, double t1 = 1, double tolerance = 1e-10) {
    if (t1 <= t0) {
        return 0;
    }
    return internal::adaptive_length(c, t0, t1, internal::gauss_legendre_8(c, t0, t1), tolerance,
                                     0);
}

/// Arc length of the curve (exact for lines and arcs).
inline double length(const Curve& curve) {
    if (const auto* l = std::get_if<Line>(&curve)) {
        return distance(l->a, l->b);
    }
    if (const auto* c = std::get_if<CubicBezier>(&curve)) {
        return length(*c);
    }
    const ArcFrame f = arc_frame(std::get<Arc>(curve));
    return f.radius * std::abs(f.sweep);
}

inline double length(const Edge& e) {
    return length(e.curve);
}

/// Parameter t at which the arc length from the start equals `s` (clamped to [0, length]).
inline double parameter_at_length(const Curve& curve, double s) {
    const double total = length(curve);
    if (total <= 0 || s <= 0) {
        return 0;
    }
    if (s >= total) {
        return 1;
    }
    const auto* c = std::get_if<CubicBezier>(&curve);
    if (!c) {
        return s / total;  // lines and arcs are parametrised proportionally to length
    }
    double lo = 0, hi = 1;
    for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
        const double mid = 0.5 * (lo + hi);
        (length(*c, 0, mid, 1e-11) < s ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// --- sampling
// -------------------------------------------------------------------------------------

namespace internal {

using tapeline::distance_to_segment;

inline void flatten(const CubicBezier& c, double tolerance, int depth, std::vector<Point2>& out) {
    const double flat =
        std::max(distance_to_segment(c.p1, c.p0, c.p3), distance_to_segment(c.p2, c.p0, c.p3));
    if (flat <= tolerance || depth >= 24) {
        out.push_back(c.p3);
        return;
    }
    // de Casteljau split at t = 1/2.
    const Point2 p01 = 0.5 * (c.p0 + c.p1), p12 = 0.5 * (c.p1 + c.p2), p23 = 0.5 * (c.p2 + c.p3);
    const Point2 p012 = 0.5 * (p01 + p12), p123 = 0.5 * (p12 + p23);
    const Point2 m = 0.5 * (p012 + p123);
    flatten({c.p0, p01, p012, m}, tolerance, depth + 1, out);
    flatten({m, p123, p23, c.p3}, tolerance, depth + 1, out);
}

}  // namespace internal

/// A polyline within `tolerance` (mm) of the curve, from its start to its end point (both
/// exact). Appends to `out`; the start point is skipped when `skip_start` (to chain edges).
inline void sample(const Curve& curve, double tolerance, std::vector<Point2>& out,
                   bool skip_start = false) {
    tolerance = std::max(tolerance, 1e-9);
    if (!skip_start) {
        out.push_back(start_point(curve));
    }
    if (const auto* l = std::get_if<Line>(&curve)) {
        out.push_back(l->b);
    } else if (const auto* c = std::get_if<CubicBezier>(&curve)) {
        internal::flatten(*c, tolerance, 0, out);
    } else {
        const Arc& a = std::get<Arc>(curve);
        const ArcFrame f = arc_frame(a);
        std::size_t n = 1;
        if (f.radius > tolerance) {
            const double max_step = 2.0 * std::acos(1.0 - tolerance / f.radius);
            n = static_cast<std::size_t>(std::ceil(std::abs(f.sweep) / max_step));
            n = std::clamp<std::size_t>(n, 1, 100000);
        }
        for (std::size_t i = 1; i < n; ++i) {
            out.push_back(point_at(curve, double(i) / double(n)));
        }
        out.push_back(a.b);
    }
}

inline std::vector<Point2> sample(const Curve& curve, double tolerance) {
    std::vector<Point2> out;
    sample(curve, tolerance, out);
    return out;
}

// --- polylines
// ------------------------------------------------------------------------------------

/// Signed area of a closed polygon (positive when counter-clockwise, y up).
inline double signed_area(const std::vector<Point2>& ring) {
    double a = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        a += cross(ring[i], ring[(i + 1) % n]);
    }
    return 0.5 * a;
}

namespace internal {

inline int orientation(const Point2& a, const Point2& b, const Point2& c, double eps) {
    const double v = cross(b - a, c - a);
    return v > eps ? 1 : (v < -eps ? -1 : 0);
}

inline bool on_segment(const Point2& p, const Point2& a, const Point2& b, double eps) {
    return std::min(a.x, b.x) - eps <= p.x && p.x <= std::max(a.x, b.x) + eps &&
           std::min(a.y, b.y) - eps <= p.y && p.y <= std::max(a.y, b.y) + eps;
}

}  // namespace internal

/// Whether closed segments [a, b] and [c, d] share a point. `eps` is an absolute tolerance on the
/// doubled triangle areas (mm²).
inline bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                               double eps = 0) {
    using internal::on_segment;
    using internal::orientation;
    const int o1 = orientation(a, b, c, eps), o2 = orientation(a, b, d, eps);
    const int o3 = orientation(c, d, a, eps), o4 = orientation(c, d, b, eps);
    if (o1 != o2 && o3 != o4) {
        return true;
    }
    return (o1 == 0 && on_segment(c, a, b, 0)) || (o2 == 0 && on_segment(d, a, b, 0)) ||
           (o3 == 0 && on_segment(a, c, d, 0)) || (o4 == 0 && on_segment(b, c, d, 0));
}

/// Intersection point of segments [a, b] and [c, d] when they cross at a single point.
inline std::optional<Point2> segment_intersection(const Point2& a, const Point2& b, const Point2& c,
                                                  const Point2& d) {
    const Point2 r = b - a, s = d - c;
    const double den = cross(r, s);
    if (den == 0) {
        return std::nullopt;
    }
    const double t = cross(c - a, s) / den, u = cross(c - a, r) / den;
    if (t < 0 || t > 1 || u < 0 || u > 1) {
        return std::nullopt;
    }
    return a + t * r;
}

/// A notch mark at arc length `offset` along `c`: from the curve point, `length` mm to the side
/// `inward` (+1: left of the direction of travel, −1: right). SVG, PNG and DXF draw the same mark.
inline std::pair<Point2, Point2> notch_mark(const Curve& c, double offset, double inward,
                                            double length) {
    const double t = parameter_at_length(c, offset);
    const Point2 p = point_at(c, t);
    return {p, p + (inward * length) * left_normal(tangent_at(c, t))};
}

}  // namespace tapeline::pattern
