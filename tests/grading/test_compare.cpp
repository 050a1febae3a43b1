// Outline deviation and the uniform-scale baseline (grading/compare.h), the oracles of
// `grade --compare` and of the grading benchmark, on shapes whose distance is known exactly.
#include <tapeline/grading/compare.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tp = tapeline::pattern;
namespace tg = tapeline::grading;

namespace {

/// A circle of radius r about c as four quarter arcs.
tp::Outline circle(double r, tp::Point2 c = {0, 0}) {
    const tp::Point2 p[4] = {{c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}, {c.x, c.y - r}};
    tp::Outline o;
    for (int i = 0; i < 4; ++i)
        o.edges.push_back({tp::Arc{p[i], p[(i + 1) % 4], r, false, true}, ""});
    return o;
}

/// A w x h rectangle with its first corner at the origin, rotated by `deg` about `pivot`, then
/// moved by `shift`.
tp::Outline rectangle(double w, double h, double deg = 0, tp::Point2 pivot = {0, 0},
                      tp::Point2 shift = {0, 0}) {
    const double t = deg * M_PI / 180, c = std::cos(t), s = std::sin(t);
    auto f = [&](tp::Point2 p) {
        const tp::Point2 d = p - pivot;
        return tp::Point2{pivot.x + c * d.x - s * d.y + shift.x,
                          pivot.y + s * d.x + c * d.y + shift.y};
    };
    const tp::Point2 p0 = f({0, 0}), p1 = f({w, 0}), p2 = f({w, h}), p3 = f({0, h});
    tp::Outline o;
    o.edges = {{tp::Line{p0, p1}, ""},
               {tp::Line{p1, p2}, ""},
               {tp::Line{p2, p3}, ""},
               {tp::Line{p3, p0}, ""}};
    return o;
}

}  // namespace

// Concentric circles of radii 100 and 105 are 5 mm apart everywhere. The outlines are sampled
// as polylines with 0.01 mm chord tolerance, so each ring is up to 0.01 mm inside its circle:
// 0.03 mm bounds the mean and the max (the sampling's own error is 0.02 at most).
TEST(OutlineDeviation, ConcentricCirclesAreTheirRadiusDifferenceApart) {
    const tg::PieceDeviation d = tg::outline_deviation(circle(100), circle(105, {40, -7}));
    EXPECT_NEAR(d.mean_mm, 5.0, 0.03);
    EXPECT_NEAR(d.max_mm, 5.0, 0.03);
    const tg::PieceDeviation same = tg::outline_deviation(circle(100), circle(100, {3, 3}));
    EXPECT_LT(same.mean_mm, 0.03);
    EXPECT_LT(same.max_mm, 0.03);
}

// A rectangle rotated by 30 degrees about some point and moved: alignment undoes both, so the
// deviation vanishes (the two outlines are sampled at corresponding points: rounding only, 1e-9)
// and the angle found is the rotation back.
TEST(OutlineDeviation, RigidMotionIsUndone) {
    const tp::Outline a = rectangle(200, 100);
    const tp::Outline b = rectangle(200, 100, 30, {37, -12}, {500, 80});
    const tg::PieceDeviation d = tg::outline_deviation(a, b);
    EXPECT_LT(d.mean_mm, 1e-9);
    EXPECT_LT(d.max_mm, 1e-9);
    EXPECT_NEAR(d.rotation_deg, -30.0, 1e-9);
    // And it is symmetric in its arguments.
    const tg::PieceDeviation back = tg::outline_deviation(b, a);
    EXPECT_NEAR(back.rotation_deg, 30.0, 1e-9);
}

// A rectangle 200 x 100 against the same rectangle 4 mm longer: centred on their centroids, each
// short side is 2 mm from the other's and the long sides overlap, so the max is 2 and the mean
// 2/3 + 0.005 (the short sides are a third of each outline; the 2 mm overhangs add 0.005).
// Sampled at 4000 points (0.15 mm apart, so a corner is cut by 0.06 mm at most): 0.06 on the max.
// The alignment starts from the arc-length correspondence, which is skewed when the perimeters
// differ, and its 5 closest-point iterations leave 0.046 degrees of the rotation (measured): that
// adds 0.017 mm to the mean, so 0.03 on the mean and 0.1 degrees on the angle.
TEST(OutlineDeviation, LongerRectangleDiffersByHalfTheExtraLengthAtItsEnds) {
    const tg::PieceDeviation d =
        tg::outline_deviation(rectangle(200, 100), rectangle(204, 100), 4000);
    EXPECT_NEAR(d.max_mm, 2.0, 0.06);
    EXPECT_NEAR(d.mean_mm, 2.0 / 3 + 0.005, 0.03);
    EXPECT_NEAR(d.rotation_deg, 0.0, 0.1);
}

// scaled_piece multiplies every coordinate (and an arc's radius) by s about the origin.
TEST(ScaledPiece, ScalesEveryCoordinateAndTheRadius) {
    tp::Piece p;
    p.name = "p";
    p.outline.edges = {{tp::Line{{0, 0}, {100, 0}}, ""},
                       {tp::CubicBezier{{100, 0}, {120, 30}, {110, 60}, {100, 80}}, ""},
                       {tp::Arc{{100, 80}, {0, 80}, 60, false, true}, ""},
                       {tp::Line{{0, 80}, {0, 0}}, ""}};
    const tp::Piece q = tg::scaled_piece(p, 1.5);
    const auto& c = std::get<tp::CubicBezier>(q.outline.edges[1].curve);
    EXPECT_EQ(c.p1.x, 180);
    EXPECT_EQ(c.p1.y, 45);
    EXPECT_EQ(c.p3.y, 120);
    const auto& arc = std::get<tp::Arc>(q.outline.edges[2].curve);
    EXPECT_EQ(arc.radius, 90);
    EXPECT_EQ(arc.a.x, 150);
    EXPECT_EQ(std::get<tp::Line>(q.outline.edges[0].curve).b.x, 150);
    EXPECT_NEAR(tp::length(q.outline), 1.5 * tp::length(p.outline), 1e-9 * tp::length(p.outline));
    // The baseline of `grade --compare`: a circle scaled by 1.05 is 5 mm from the radius-100 one.
    tp::Piece disc;
    disc.outline = circle(100);
    const tg::PieceDeviation d =
        tg::outline_deviation(circle(100), tg::scaled_piece(disc, 1.05).outline);
    EXPECT_NEAR(d.mean_mm, 5.0, 0.03);
}

// pattern_deviation matches pieces by name and skips those the graded pattern lacks.
TEST(OutlineDeviation, PatternDeviationMatchesPiecesByName) {
    tp::Pattern ref, graded;
    for (const char* n : {"front", "back", "sleeve"}) {
        tp::Piece p;
        p.name = n;
        p.outline = circle(100);
        ref.pieces.push_back(p);
    }
    tp::Piece back;
    back.name = "back";
    back.outline = circle(103);
    tp::Piece front;
    front.name = "front";
    front.outline = circle(101);
    graded.pieces = {back, front};
    const auto rows = tg::pattern_deviation(ref, graded);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].piece, "front");
    EXPECT_NEAR(rows[0].mean_mm, 1.0, 0.03);
    EXPECT_EQ(rows[1].piece, "back");
    EXPECT_NEAR(rows[1].mean_mm, 3.0, 0.03);
}
