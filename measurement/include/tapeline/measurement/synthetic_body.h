// A synthetic body built from analytic parts with exactly known girths and landmark levels, for
// tests and benchmarks (DESIGN.md §6: analytic truth).
//
// Canonical frame, millimetres, floor y = 0, height 1720. Every part is a closed generalised
// cylinder with elliptic cross-sections perpendicular to its straight axis (or an ellipsoid):
//   torso  axis x = z = 0, y 800..1400 (flat caps); semi-axes a (lateral) and b (depth) follow
//          piecewise cubic Hermite profiles with zero slope at their control levels, so each
//          control level is an exact extremum: hip maximum at 880, waist minimum at 1040, bust
//          maximum at 1180;
//   legs   vertical, centres x = ±90, z = 0, y 20..830: ankle minimum at 100, calf maximum at
//          330, knee minimum at 460, thigh maximum at 780; the crotch is the torso's bottom (800),
//          where the two leg sections enter the torso;
//   feet   ellipsoids around the leg bottoms; neck vertical, y 1380..1560, minimum at 1490;
//   head   ellipsoid centred at y 1620, semi-axes 75 (x), 100 (y), 95 (z): top of head 1720,
//          largest horizontal girth at 1620;
//   arms   straight, `arm_angle_degrees` from the vertical (40: A-pose, 90: T-pose), from inside
//          the shoulders: elbow minimum 330 mm and wrist minimum 560 mm along the axis (start
//          inside the shoulder at x = ±110, y = 1345).
// The parts overlap (a union of closed components, not one manifold): sections inside another
// part's section are grouped with it, as the slicer does for any body.
//
// Exact girth of an ellipse: 4 a E(e), E the complete elliptic integral of the second kind
// (GeographicLib::EllipticFunction), e² = 1 − (b/a)².
#pragma once

#include <tapeline/measurement/body_types.h>

#include <GeographicLib/EllipticFunction.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::measurement {

/// Perimeter of an ellipse with semi-axes a and b (exact up to rounding).
inline double ellipse_perimeter(double a, double b) {
    if (a < b) {
        std::swap(a, b);
    }
    if (a <= 0) {
        return 0;
    }
    const double e2 = 1 - (b / a) * (b / a);
    return 4 * a * GeographicLib::EllipticFunction(e2).E();
}

/// A profile through control points (t, v) with zero slope at each: v is monotone between
/// control points, so every interior control point is an exact local extremum.
struct HermiteProfile {
    std::vector<std::pair<double, double>> points;  ///< increasing t

    /// The profile at t (constant beyond the first and last control points).
    double operator()(double t) const {
        if (t <= points.front().first) {
            return points.front().second;
        }
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            if (t <= points[i + 1].first) {
                const double s = (t - points[i].first) / (points[i + 1].first - points[i].first);
                return points[i].second +
                       (points[i + 1].second - points[i].second) * s * s * (3 - 2 * s);
            }
        }
        return points.back().second;
    }
};

/// Resolution of the synthetic mesh.
struct SyntheticBodyOptions {
    int around = 48;                ///< vertices around each ring
    double ring_step = 8;           ///< mm between rings along each axis
    double arm_angle_degrees = 40;  ///< arms' angle from the vertical
};

/// A closed body mesh built from analytic profiles, with exact girths and lengths: the truth
/// the measurement tests compare against.
class SyntheticBody {
public:
    /// Builds the mesh at the resolution of `options`.
    explicit SyntheticBody(const SyntheticBodyOptions& options = {}) : options_(options) {
        torso_a_ = {{{800, 165}, {880, 180}, {1040, 135}, {1180, 155}, {1330, 140}, {1400, 175}}};
        torso_b_ = {{{800, 118}, {880, 125}, {1040, 95}, {1180, 115}, {1330, 100}, {1400, 105}}};
        leg_a_ = {{{20, 34}, {100, 32}, {330, 55}, {460, 48}, {780, 85}, {830, 85}}};
        neck_a_ = {{{1380, 60}, {1490, 52}, {1560, 60}}};
        arm_a_ = {{{0, 48}, {180, 46}, {330, 38}, {410, 42}, {560, 27}, {640, 45}, {720, 20}}};
        arm_b_ = {
            {{0, 43}, {180, 41.4}, {330, 34.2}, {410, 37.8}, {560, 24.3}, {640, 20}, {720, 8}}};
        build();
    }

    const SyntheticBodyOptions& options() const { return options_; }  ///< as constructed

    // --- the mesh (canonical millimetres) -----------------------------------------------------
    const std::vector<Vec3>& points() const { return points_; }  ///< vertices, canonical mm
    /// Triangles as indices into points().
    const std::vector<std::array<std::uint32_t, 3>>& triangles() const { return triangles_; }

    // --- truth ----------------------------------------------------------------------------------
    /// Heights (mm above the floor) of the body's levels, arm positions (mm along the arm) and
    /// the legs' lateral offset: the values the profiles are built from.
    ///@{
    static constexpr double kHeight = 1720, kCrotch = 800, kHip = 880, kWaist = 1040, kBust = 1180,
                            kShoulder = 1400, kKnee = 460, kCalf = 330, kAnkle = 100, kNeck = 1490,
                            kHead = 1620, kElbowT = 330, kWristT = 560, kArmLength = 720,
                            kLegX = 90;
    ///@}
    double leg_b_ratio() const { return 0.9; }    ///< leg section depth / width
    double neck_b_ratio() const { return 0.95; }  ///< neck section depth / width

    /// Exact horizontal girths of the parts at a height (for the torso: its own section).
    double torso_girth(double y) const { return ellipse_perimeter(torso_a_(y), torso_b_(y)); }
    /// Exact girth of a leg at height y.
    double leg_girth(double y) const {
        return ellipse_perimeter(leg_a_(y), leg_b_ratio() * leg_a_(y));
    }
    /// Where the ankle girth is taken (ISO 8559-1: just above the malleoli): the lowest height
    /// from 2.5 % of the stature up whose leg girth is within `tolerance` mm of the smallest leg
    /// girth up to 12 % (kAnkle is that smallest one; the profile is flat around it).
    double ankle_level(double tolerance = kAnkleGirthTolerance) const {
        const double lo = 0.025 * kHeight, hi = 0.12 * kHeight, dy = 0.01;
        double smallest = leg_girth(lo);
        for (double y = lo; y <= hi; y += dy) {
            smallest = std::min(smallest, leg_girth(y));
        }
        double y = lo;
        while (y < hi && leg_girth(y) > smallest + tolerance) {
            y += dy;
        }
        return y;
    }
    /// Exact girth of the neck at height y.
    double neck_girth(double y) const {
        return ellipse_perimeter(neck_a_(y), neck_b_ratio() * neck_a_(y));
    }
    /// Exact girth of the head at height y.
    double head_girth(double y) const {
        const double c = (y - kHead) / 100;
        const double r = c * c < 1 ? std::sqrt(1 - c * c) : 0;
        return ellipse_perimeter(75 * r, 95 * r);
    }
    /// Girth of the arm perpendicular to its axis, t mm from the arm's start.
    double arm_girth(double t) const { return ellipse_perimeter(arm_a_(t), arm_b_(t)); }
    double torso_depth(double y) const { return torso_b_(y); }       ///< depth semi-axis at y
    double torso_half_width(double y) const { return torso_a_(y); }  ///< lateral semi-axis at y
    /// Lateral semi-axis of a leg's section at height y (depth: leg_b_ratio() times it), of the
    /// neck's (depth: neck_b_ratio() times it), and of the arm's t mm along its axis (and its
    /// depth semi-axis): the analytic profiles, for lengths along the skin.
    ///@{
    double leg_half_width(double y) const { return leg_a_(y); }
    double neck_half_width(double y) const { return neck_a_(y); }
    double arm_half_width(double t) const { return arm_a_(t); }
    double arm_half_depth(double t) const { return arm_b_(t); }
    ///@}

    /// Start and unit direction of an arm's axis (side +1 = left, −1 = right).
    ///@{
    Vec3 arm_start(int side) const { return {side * 110.0, 1345, 0}; }
    Vec3 arm_direction(int side) const {
        const double al = options_.arm_angle_degrees * M_PI / 180;
        return {side * std::sin(al), -std::cos(al), 0};
    }
    ///@}
    /// Distance along an arm's axis of a point's projection.
    double arm_parameter(int side, const Vec3& p) const {
        const Vec3 s = arm_start(side), d = arm_direction(side);
        return (p[0] - s[0]) * d[0] + (p[1] - s[1]) * d[1] + (p[2] - s[2]) * d[2];
    }

    /// Armpit height: the highest level at which the arm's and the torso's horizontal sections
    /// are still disjoint (found numerically on the analytic surfaces to 0.01 mm).
    double armpit_height() const {
        double lo = 1000, hi = kShoulder - 1;  // disjoint at lo, overlapping at hi
        while (hi - lo > 0.01) {
            const double mid = 0.5 * (lo + hi);
            (overlap_at(mid) ? hi : lo) = mid;
        }
        return lo;
    }

private:
    SyntheticBodyOptions options_;
    HermiteProfile torso_a_, torso_b_, leg_a_, neck_a_, arm_a_, arm_b_;
    std::vector<Vec3> points_;
    std::vector<std::array<std::uint32_t, 3>> triangles_;

    /// Whether some point of the left arm's surface at height y lies inside the torso.
    bool overlap_at(double y) const {
        const Vec3 s = arm_start(1), d = arm_direction(1);
        const double al = options_.arm_angle_degrees * M_PI / 180;
        const Vec3 e1{std::cos(al), std::sin(al), 0};
        for (int k = 0; k < 720; ++k) {
            const double th = 2 * M_PI * k / 720;
            auto height = [&](double t) {
                return s[1] + t * d[1] + arm_a_(t) * std::cos(th) * e1[1];
            };
            // Height decreases along the arm (the arm points down or sideways); bisect for t.
            double t0 = 0, t1 = kArmLength;
            if (height(t0) < y || height(t1) > y) {
                continue;
            }
            for (int it = 0; it < 60; ++it) {
                const double tm = 0.5 * (t0 + t1);
                (height(tm) > y ? t0 : t1) = tm;
            }
            const double t = 0.5 * (t0 + t1);
            const double x = s[0] + t * d[0] + arm_a_(t) * std::cos(th) * e1[0];
            const double z = arm_b_(t) * std::sin(th);
            const double u = x / torso_a_(y), v = z / torso_b_(y);
            if (y >= kCrotch && y <= kShoulder && u * u + v * v < 1) {
                return true;
            }
        }
        return false;
    }

    /// Adds a closed tube: rings (centre, axes e1/e2, semi-axes a/b) closed by flat caps (or a
    /// pole when a ring's semi-axes are zero).
    struct Ring {
        Vec3 c, e1, e2;
        double a, b;
    };
    void add_tube(const std::vector<Ring>& rings, const Vec3* first_pole = nullptr,
                  const Vec3* last_pole = nullptr) {
        const auto n = static_cast<std::uint32_t>(options_.around);
        std::vector<std::uint32_t> first;
        for (const Ring& r : rings) {
            first.push_back(static_cast<std::uint32_t>(points_.size()));
            for (std::uint32_t k = 0; k < n; ++k) {
                const double th = 2 * M_PI * k / n;
                const double ca = r.a * std::cos(th), sb = r.b * std::sin(th);
                points_.push_back({r.c[0] + ca * r.e1[0] + sb * r.e2[0],
                                   r.c[1] + ca * r.e1[1] + sb * r.e2[1],
                                   r.c[2] + ca * r.e1[2] + sb * r.e2[2]});
            }
        }
        // Outward when e1 × e2 points along the tube (first ring to last); else reversed.
        const std::size_t tri0 = triangles_.size();
        for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
            for (std::uint32_t k = 0; k < n; ++k) {
                const std::uint32_t a = first[i] + k, b = first[i] + (k + 1) % n;
                const std::uint32_t c = first[i + 1] + k, d = first[i + 1] + (k + 1) % n;
                triangles_.push_back({a, b, d});
                triangles_.push_back({a, d, c});
            }
        }
        // Caps: a centre vertex (or the pole) fanned to the end rings.
        const auto cap = [&](std::size_t i, bool flip, const Vec3* pole) {
            const auto centre = static_cast<std::uint32_t>(points_.size());
            points_.push_back(pole ? *pole : rings[i].c);
            for (std::uint32_t k = 0; k < n; ++k) {
                const std::uint32_t a = first[i] + k, b = first[i] + (k + 1) % n;
                triangles_.push_back(flip ? std::array<std::uint32_t, 3>{centre, b, a}
                                          : std::array<std::uint32_t, 3>{centre, a, b});
            }
        };
        cap(0, true, first_pole);
        cap(rings.size() - 1, false, last_pole);
        const Ring& r0 = rings.front();
        const Ring& r1 = rings.back();
        const Vec3 n12{r0.e1[1] * r0.e2[2] - r0.e1[2] * r0.e2[1],
                       r0.e1[2] * r0.e2[0] - r0.e1[0] * r0.e2[2],
                       r0.e1[0] * r0.e2[1] - r0.e1[1] * r0.e2[0]};
        const double along = n12[0] * (r1.c[0] - r0.c[0]) + n12[1] * (r1.c[1] - r0.c[1]) +
                             n12[2] * (r1.c[2] - r0.c[2]);
        if (along < 0) {
            for (std::size_t t = tri0; t < triangles_.size(); ++t) {
                std::swap(triangles_[t][1], triangles_[t][2]);
            }
        }
    }

    /// Rings of a straight tube from `start` along `dir`, t in [t0, t1].
    template <class A, class B>
    std::vector<Ring> straight(const Vec3& start, const Vec3& dir, const Vec3& e1, const Vec3& e2,
                               double t0, double t1, A a, B b) const {
        std::vector<Ring> rings;
        const int n = std::max(2, static_cast<int>(std::ceil((t1 - t0) / options_.ring_step)));
        for (int i = 0; i <= n; ++i) {
            const double t = t0 + (t1 - t0) * i / n;
            rings.push_back({{start[0] + t * dir[0], start[1] + t * dir[1], start[2] + t * dir[2]},
                             e1,
                             e2,
                             a(t),
                             b(t)});
        }
        return rings;
    }

    std::vector<Ring> ellipsoid(const Vec3& c, double ax, double ay, double az) const {
        // Rings evenly spaced in latitude, an even count so that the equator is a ring; the
        // poles close the ends (add_ellipsoid).
        const int n =
            2 * std::max(4, static_cast<int>(std::ceil(M_PI * ay / options_.ring_step / 2)));
        std::vector<Ring> rings;
        for (int i = 1; i < n; ++i) {
            const double phi = M_PI * i / n;
            rings.push_back({{c[0], c[1] - ay * std::cos(phi), c[2]},
                             {1, 0, 0},
                             {0, 0, 1},
                             ax * std::sin(phi),
                             az * std::sin(phi)});
        }
        return rings;
    }

    void add_ellipsoid(const Vec3& c, double ax, double ay, double az) {
        const Vec3 south{c[0], c[1] - ay, c[2]}, north{c[0], c[1] + ay, c[2]};
        add_tube(ellipsoid(c, ax, ay, az), &south, &north);
    }

    void build() {
        const Vec3 up{0, 1, 0}, x{1, 0, 0}, z{0, 0, 1};
        add_tube(straight(
            {0, 0, 0}, up, x, z, kCrotch, kShoulder, [this](double y) { return torso_a_(y); },
            [this](double y) { return torso_b_(y); }));
        for (int side : {1, -1}) {
            add_tube(straight(
                {side * kLegX, 0, 0}, up, x, z, 20, 830, [this](double y) { return leg_a_(y); },
                [this](double y) { return leg_b_ratio() * leg_a_(y); }));
            add_ellipsoid({side * kLegX, 35, 40}, 45, 35, 120);
            const double al = options_.arm_angle_degrees * M_PI / 180;
            add_tube(straight(
                arm_start(side), arm_direction(side), {side * std::cos(al), std::sin(al), 0}, z, 0,
                kArmLength, [this](double t) { return arm_a_(t); },
                [this](double t) { return arm_b_(t); }));
        }
        add_tube(straight(
            {0, 0, 0}, up, x, z, 1380, 1560, [this](double y) { return neck_a_(y); },
            [this](double y) { return neck_b_ratio() * neck_a_(y); }));
        add_ellipsoid({0, kHead, 10}, 75, 100, 95);
    }
};

/// The underbust rule (girths.h) on the synthetic body with its bust points at height `bust_y`:
/// on the front profile at the bust point's x (0.1 of the half-width), the level between the
/// waist and the bust deepest behind the chord from the bust point to the waist's front; with no
/// level 0.2 % of the height behind it, 2.5 % of the height under the bust points.
inline double synthetic_underbust_level(const SyntheticBody& body, double bust_y) {
    using B = SyntheticBody;
    const double bx = 0.1 * body.torso_half_width(B::kBust);
    auto front = [&](double y) {
        const double u = bx / body.torso_half_width(y);
        return body.torso_depth(y) * std::sqrt(1 - u * u);
    };
    const double y1 = bust_y, y0 = B::kWaist, z1 = front(y1), z0 = front(y0);
    const double chord = std::hypot(y0 - y1, z0 - z1);
    double deepest = -INFINITY, level = y1;
    for (double y = y1; y >= y0; y -= 0.01) {
        const double behind = -((y - y1) * (z0 - z1) - (front(y) - z1) * (y0 - y1)) / chord;
        if (behind > deepest) {
            deepest = behind;
            level = y;
        }
    }
    return deepest < 0.002 * B::kHeight ? y1 - 0.025 * B::kHeight : level;
}

/// One girth's exact value on the synthetic body, and how far a measurement of it may be off.
struct SyntheticTruth {
    std::string name;  ///< measurement name (measurement_types.h)
    double level = 0;  ///< height (mm) or, for the arm, mm along its axis, of the exact section
    double value = 0;  ///< the perimeter of the analytic section there, mm
    /// What the mesh resolves: twice the polygon's shortfall P·π²/(6n²) (n vertices around),
    /// plus, where the level comes from landmarks (`from_landmarks`), what one scan step of level
    /// changes the truth (the underbust: what moving the bust points a ring and a scan step up or
    /// down does to its level's girth).
    double tolerance = 0;
    bool from_landmarks = false;  ///< the level follows a rule from landmarks, not an extremum
};

/// The girths of the measurement rules (girths.h) at the levels the construction defines: an
/// extremum of a profile, or the rule applied to the construction's landmarks (high bust 0.5 % of
/// the height under the armpits; high hip halfway between waist and hip; neck base where the
/// neck meets the shoulder cap; thigh 2 % of the height under the crotch; mid-thigh halfway
/// between crotch and knee; upper arm halfway between the arm's joint and the elbow; underbust
/// deepest behind the chord from bust point to waist, or 2.5 % of the height under the bust on a
/// chest without a fold). `scan_step` is the landmark scan's spacing (MeasureOptions::scan_step;
/// 0: height / 400).
inline std::vector<SyntheticTruth> synthetic_girth_truth(const SyntheticBody& body,
                                                         double scan_step = 0) {
    using B = SyntheticBody;
    const double step = scan_step > 0 ? scan_step : B::kHeight / 400;
    const double n = body.options().around;
    std::vector<SyntheticTruth> out;
    auto add = [&](const std::string& name, const std::function<double(double)>& girth,
                   double level, bool from_landmarks) {
        const double p = girth(level);
        double t = 2 * p * M_PI * M_PI / (6 * n * n);
        if (from_landmarks) {
            t += std::max(std::abs(girth(level + step) - p), std::abs(girth(level - step) - p));
        }
        out.push_back({name, level, p, t, from_landmarks});
    };
    const std::function<double(double)> torso = [&](double y) { return body.torso_girth(y); };
    const std::function<double(double)> leg = [&](double y) { return body.leg_girth(y); };
    const std::function<double(double)> neck = [&](double y) { return body.neck_girth(y); };
    const std::function<double(double)> head = [&](double y) { return body.head_girth(y); };
    const std::function<double(double)> arm = [&](double t) { return body.arm_girth(t); };

    const double underbust = synthetic_underbust_level(body, B::kBust);

    const double armpit = body.armpit_height();
    add("head_girth", head, B::kHead, false);
    add("neck_girth", neck, B::kNeck, false);
    add("neck_base_girth", neck, B::kShoulder, true);
    add("bust_girth", torso, B::kBust, false);
    add("high_bust_girth", torso, armpit - 0.005 * B::kHeight, true);
    add("underbust_girth", torso, underbust, true);
    // The underbust's level follows the bust points', which the landmark search places within a
    // ring and a scan step of the bust's level (the rings are the bust point's vertex choices).
    for (double dy : {-1.0, 1.0}) {
        const double moved =
            synthetic_underbust_level(body, B::kBust + dy * (body.options().ring_step + step));
        out.back().tolerance = std::max(out.back().tolerance,
                                        2 * out.back().value * M_PI * M_PI / (6 * n * n) +
                                            std::abs(body.torso_girth(moved) - out.back().value));
    }
    add("waist_girth", torso, B::kWaist, false);
    add("high_hip_girth", torso, 0.5 * (B::kWaist + B::kHip), true);
    add("hip_girth", torso, B::kHip, false);
    for (const int sign : {1, -1}) {
        const std::string s = sign > 0 ? "_left" : "_right";
        add("thigh_girth" + s, leg, B::kCrotch - 0.02 * B::kHeight, true);
        add("mid_thigh_girth" + s, leg, 0.5 * (B::kCrotch + B::kKnee), true);
        add("knee_girth" + s, leg, B::kKnee, false);
        add("calf_girth" + s, leg, B::kCalf, false);
        add("ankle_girth" + s, leg, B::kAnkle, false);
        // The arm's joint is midway between the acromion (the cap's corner) and the armpit (the
        // torso's side at the armpit level); the upper arm starts at the farther of the joint's
        // and the armpit's projections on the arm's axis.
        const double top = B::kShoulder;
        const Vec3 armpit_point{sign * body.torso_half_width(armpit), armpit, 0};
        const Vec3 joint{0.5 * sign * (body.torso_half_width(top) + body.torso_half_width(armpit)),
                         0.5 * (top + armpit), 0};
        const double from =
            std::max(body.arm_parameter(sign, armpit_point), body.arm_parameter(sign, joint));
        add("upper_arm_girth" + s, arm, 0.5 * (from + B::kElbowT), true);
        add("elbow_girth" + s, arm, B::kElbowT, false);
        add("wrist_girth" + s, arm, B::kWristT, false);
    }
    return out;
}

}  // namespace tapeline::measurement
