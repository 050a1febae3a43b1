// Curve lengths and sampling against analytic truth (DESIGN.md §6).
#include <tapeline/pattern/geometry.h>
#include <tapeline/pattern/pattern.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace tapeline::pattern;

namespace {

// Independent reference: chord sums at n and 2n samples, Richardson-extrapolated (error O(h^4)).
double chord_length(const CubicBezier& c, int n) {
    double total = 0;
    Point2 prev = c.p0;
    for (int i = 1; i <= n; ++i) {
        const Point2 q = point_at(c, double(i) / n);
        total += distance(prev, q);
        prev = q;
    }
    return total;
}

double reference_length(const CubicBezier& c) {
    const double a = chord_length(c, 200000), b = chord_length(c, 400000);
    return b + (b - a) / 3.0;
}

}  // namespace

TEST(PatternGeometry, StraightCubicHasChordLength) {
    // Control points on the segment, unevenly spaced: the speed varies but the length does not.
    const CubicBezier c{{1, 2}, {2.5, 2.75}, {9, 6}, {11, 7}};
    EXPECT_NEAR(length(Curve{c}), std::hypot(10.0, 5.0), 1e-12);
}

TEST(PatternGeometry, ElevatedParabolaMatchesClosedForm) {
    // (t, t²) for t in [0, 1]: ∫ sqrt(1 + 4x²) dx = sqrt(5)/2 + asinh(2)/4.
    const CubicBezier c = cubic_from_quadratic({0, 0}, {0.5, 0}, {1, 1});
    const double exact = std::sqrt(5.0) / 2 + std::asinh(2.0) / 4;
    EXPECT_NEAR(length(Curve{c}), exact, 1e-12);
    for (double t : {0.1, 0.37, 0.8}) {
        const Point2 p = point_at(c, t);
        EXPECT_NEAR(p.x, t, 1e-15);
        EXPECT_NEAR(p.y, t * t, 1e-15);
    }
}

TEST(PatternGeometry, QuarterCircleBezierLength) {
    // The standard 4/3·(√2 − 1) quarter-circle approximation (radius 100 mm). Its length is
    // within 0.03 % of the quarter circle; the independent reference is an extrapolated chord sum.
    const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0), r = 100;
    const CubicBezier c{{r, 0}, {r, k * r}, {k * r, r}, {0, r}};
    const double len = length(Curve{c});
    EXPECT_NEAR(len, reference_length(c), 1e-7);
    EXPECT_NEAR(len, M_PI / 2 * r, 0.0003 * M_PI / 2 * r);
}

TEST(PatternGeometry, ArcLengthsAreExact) {
    const double r = 10;
    // Quarter circle, counter-clockwise from (10, 0) to (0, 10).
    EXPECT_DOUBLE_EQ(length(Curve{Arc{{r, 0}, {0, r}, r, false, true}}), M_PI / 2 * r);
    // The large arc between the same points: three quarters.
    EXPECT_DOUBLE_EQ(length(Curve{Arc{{r, 0}, {0, r}, r, true, true}}), 1.5 * M_PI * r);
    // Half circle: radius equal to half the chord.
    EXPECT_DOUBLE_EQ(length(Curve{Arc{{-r, 0}, {r, 0}, r, false, false}}), M_PI * r);
    // Point at t = 1/2 of the minor ccw quarter lies on the circle at 45°.
    const Point2 m = point_at(Curve{Arc{{r, 0}, {0, r}, r, false, true}}, 0.5);
    EXPECT_NEAR(m.x, r / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(m.y, r / std::sqrt(2.0), 1e-12);
    // Clockwise minor arc from (10,0) to (0,10) has its centre at (10,10).
    const ArcFrame f = arc_frame(Arc{{r, 0}, {0, r}, r, false, false});
    EXPECT_NEAR(f.center.x, r, 1e-12);
    EXPECT_NEAR(f.center.y, r, 1e-12);
    EXPECT_TRUE(arc_frame(Arc{{0, 0}, {10, 0}, 4, false, true}).radius_too_small);
}

TEST(PatternGeometry, SamplingStaysWithinTolerance) {
    const double r = 50, tol = 0.01;
    const Curve arc = Arc{{r, 0}, {-r, 0}, r, false, true};
    const std::vector<Point2> pts = sample(arc, tol);
    ASSERT_GE(pts.size(), 3u);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        // The chord midpoint is the farthest chord point from the circle.
        const Point2 mid = 0.5 * (pts[i] + pts[i + 1]);
        EXPECT_LE(r - norm(mid), tol + 1e-12);
        EXPECT_NEAR(norm(pts[i]), r, 1e-9);
    }
    const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);
    const CubicBezier c{{r, 0}, {r, k * r}, {k * r, r}, {0, r}};
    const std::vector<Point2> bp = sample(Curve{c}, tol);
    // Every fine curve point is within the tolerance of the polyline.
    for (int i = 0; i <= 1000; ++i) {
        const Point2 q = point_at(c, i / 1000.0);
        double best = 1e9;
        for (std::size_t s = 0; s + 1 < bp.size(); ++s) {
            best = std::min(best, internal::distance_to_segment(q, bp[s], bp[s + 1]));
        }
        EXPECT_LE(best, tol + 1e-12);
    }
}

TEST(PatternGeometry, ParameterAtLengthInvertsLength) {
    const CubicBezier c = cubic_from_quadratic({0, 0}, {0.5, 0}, {1, 1});
    const double total = length(Curve{c});
    for (double s : {0.1, 0.5, 1.2}) {
        const double t = parameter_at_length(Curve{c}, s);
        EXPECT_NEAR(length(c, 0, t), s, 1e-9);
    }
    EXPECT_EQ(parameter_at_length(Curve{c}, 2 * total), 1.0);
}

TEST(PatternGeometry, SegmentIntersection) {
    EXPECT_TRUE(segments_intersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));
    EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));  // collinear overlap
    EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {1, 5}));  // touching
    EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));
    const auto x = segment_intersection({0, 0}, {2, 2}, {0, 2}, {2, 0});
    ASSERT_TRUE(x);
    EXPECT_DOUBLE_EQ(x->x, 1);
    EXPECT_DOUBLE_EQ(x->y, 1);
}

TEST(PatternGeometry, ReversedCurvesKeepLengthAndSwapEnds) {
    const std::vector<Curve> curves = {Line{{0, 0}, {3, 4}},
                                       CubicBezier{{0, 0}, {1, 2}, {3, 2}, {4, 0}},
                                       Arc{{10, 0}, {0, 10}, 10, false, true}};
    for (const Curve& c : curves) {
        const Curve r = reversed(c);
        EXPECT_NEAR(length(r), length(c), 1e-12);
        EXPECT_EQ(start_point(r), end_point(c));
        EXPECT_EQ(end_point(r), start_point(c));
        const Point2 a = point_at(c, 0.3), b = point_at(r, 0.7);
        EXPECT_NEAR(distance(a, b), 0, 1e-9);
    }
}
