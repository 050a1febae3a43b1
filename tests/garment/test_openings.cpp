// Openings of a garment (openings.h) on tubes of known shape: a circular rim's length and hull, an
// ellipse (convex: no folds), a hem with k sinusoidal folds, a sleeve end seen along the sleeve.

#include <tapeline/garment/openings.h>

#include <gtest/gtest.h>
#include <tapeline_test/garment_shapes.h>

#include <cmath>
#include <functional>
#include <vector>

namespace tg = tapeline::garment;

namespace {

using tapeline_test::kPi;

/// A tube of `rings` rings of `n` vertices: ring j (0 at the top) is the curve
/// rim(j, θ) for θ = 2πi/n. Quads split along one diagonal.
struct Tube {
    std::vector<tg::Vec3> x;
    std::vector<tg::Tri> t;
};

Tube tube(int n, int rings, const std::function<tg::Vec3(int, double)>& rim) {
    Tube m;
    for (int j = 0; j < rings; ++j) {
        for (int i = 0; i < n; ++i) {
            m.x.push_back(rim(j, 2 * kPi * i / n));
        }
    }
    for (int j = 0; j + 1 < rings; ++j) {
        for (int i = 0; i < n; ++i) {
            const auto v = [&](int jj, int ii) { return std::uint32_t(jj * n + (ii % n)); };
            m.t.push_back({v(j, i), v(j + 1, i), v(j + 1, i + 1)});
            m.t.push_back({v(j, i), v(j + 1, i + 1), v(j, i + 1)});
        }
    }
    return m;
}

/// A skirt-like tube around y: radius r(j, θ) at height 1000 − 50 j.
Tube hem_tube(int n, const std::function<double(int, double)>& r) {
    return tube(n, 4, [&](int j, double a) {
        const double rr = r(j, a);
        return tg::Vec3{rr * std::cos(a), 1000.0 - 50.0 * j, rr * std::sin(a)};
    });
}

}  // namespace

TEST(GarmentOpenings, CircularRimsOfATube) {
    const int n = 90;
    const double radius = 150;
    const Tube m = hem_tube(n, [&](int, double) { return radius; });
    const auto loops = tg::boundary_loop_vertices(m.t);
    ASSERT_EQ(loops.size(), 2u);
    for (const auto& l : loops) {
        EXPECT_EQ(l.size(), std::size_t(n));
    }
    const auto ops = tg::garment_openings(m.x, m.t);
    ASSERT_EQ(ops.size(), 2u);
    const double polygon = 2 * n * radius * std::sin(kPi / n);  // the inscribed n-gon's perimeter
    for (const tg::Opening& o : ops) {
        EXPECT_NEAR(o.length_mm, polygon, 1e-9 * polygon);
        EXPECT_NEAR(o.hull_perimeter_mm, polygon, 1e-9 * polygon);
        EXPECT_NEAR(o.width_mm, 2 * radius, 1e-9);  // θ = 0 and π are vertices
        EXPECT_NEAR(o.normal[1], 1, 1e-12);
        EXPECT_EQ(o.folds, 0);
        EXPECT_LT(o.deepest_fold_mm, 1e-9);
    }
    // Heights 1000 and 850.
    const double lo = std::min(ops[0].height_mm, ops[1].height_mm);
    const double hi = std::max(ops[0].height_mm, ops[1].height_mm);
    EXPECT_NEAR(lo, 850, 1e-9);
    EXPECT_NEAR(hi, 1000, 1e-9);
}

TEST(GarmentOpenings, AnEllipticalHemHasNoFolds) {
    // Convex, however flat: the depth inside the hull is zero all round.
    const Tube m = hem_tube(120, [&](int, double a) {
        const double ca = std::cos(a), sa = std::sin(a);
        return 1.0 / std::sqrt(ca * ca / (180.0 * 180.0) + sa * sa / (90.0 * 90.0));
    });
    for (const tg::Opening& o : tg::garment_openings(m.x, m.t)) {
        EXPECT_EQ(o.folds, 0);
        EXPECT_NEAR(o.width_mm, 360, 1e-6);
        EXPECT_NEAR(o.depth_mm, 180, 0.1);  // θ = π/2 is a vertex (120 divisible by 4)
        EXPECT_LT(o.deepest_fold_mm, 1e-6);
    }
}

TEST(GarmentOpenings, FoldsOfAHemAreCounted) {
    // The bottom rim has k folds of amplitude 30 mm, the top rim none. The valleys of these
    // rims lie 8.6 to 55 mm inside the hull (an independent computation with scipy's ConvexHull
    // gave 8.57, 21.6, 38.6, 49.3, 55.3 mm for k = 3, 4, 6, 9, 14).
    for (int k : {3, 4, 6, 9, 14}) {
        const Tube m = hem_tube(
            360, [&](int j, double a) { return 160.0 + (j == 3 ? 30.0 : 0.0) * std::cos(k * a); });
        const auto ops = tg::garment_openings(m.x, m.t);
        ASSERT_EQ(ops.size(), 2u);
        const tg::Opening& hem = ops[0].height_mm < ops[1].height_mm ? ops[0] : ops[1];
        const tg::Opening& top = ops[0].height_mm < ops[1].height_mm ? ops[1] : ops[0];
        EXPECT_EQ(hem.folds, k) << k << " folds";
        EXPECT_EQ(top.folds, 0);
        // The valleys lie inside the hull, less deep than crest to valley (2 × 30 mm).
        EXPECT_GT(hem.deepest_fold_mm, 8.0) << k;
        EXPECT_LT(hem.deepest_fold_mm, 60.0) << k;
        // The folded rim is longer than its hull.
        EXPECT_GT(hem.length_mm, hem.hull_perimeter_mm) << k;
    }
    // Ripples of 0.5 mm (depth below the 2 mm a fold must rise and fall) are no folds; nor is a
    // gentle wave that leaves the rim convex (160 + 12 cos 3θ: scipy gives depth 0).
    const Tube ripples = hem_tube(
        360, [&](int j, double a) { return 160.0 + (j == 3 ? 0.5 : 0.0) * std::cos(9 * a); });
    for (const tg::Opening& o : tg::garment_openings(ripples.x, ripples.t)) {
        EXPECT_EQ(o.folds, 0);
    }
    const Tube wave = hem_tube(
        360, [&](int j, double a) { return 160.0 + (j == 3 ? 12.0 : 0.0) * std::cos(3 * a); });
    for (const tg::Opening& o : tg::garment_openings(wave.x, wave.t)) {
        EXPECT_EQ(o.folds, 0);
        EXPECT_LT(o.deepest_fold_mm, 1e-6);
    }
}

TEST(GarmentOpenings, ASleeveEndIsSeenAlongTheSleeve) {
    // A tube along x tilted 20° down: its rims' planes are perpendicular to its axis, and the
    // five folds of the far rim are counted in that plane (seen from above they would overlap).
    const double tilt = 20 * kPi / 180;
    const tg::Vec3 axis{std::cos(tilt), -std::sin(tilt), 0};
    const tg::Vec3 e1{std::sin(tilt), std::cos(tilt), 0}, e2{0, 0, 1};
    const Tube m = tube(200, 4, [&](int j, double a) {
        const double r = 60.0 + (j == 3 ? 15.0 : 0.0) * std::cos(5 * a);  // depth 18 mm (scipy)
        const double s = 200.0 + 60.0 * j;
        return tg::Vec3{s * axis[0] + r * (std::cos(a) * e1[0] + std::sin(a) * e2[0]),
                        1300 + s * axis[1] + r * (std::cos(a) * e1[1] + std::sin(a) * e2[1]),
                        s * axis[2] + r * (std::cos(a) * e1[2] + std::sin(a) * e2[2])};
    });
    const auto ops = tg::garment_openings(m.x, m.t);
    ASSERT_EQ(ops.size(), 2u);
    int folded = 0;
    for (const tg::Opening& o : ops) {
        // Normal along the axis (its sign made to point up: y ≥ 0).
        EXPECT_NEAR(std::abs(o.normal[0] * axis[0] + o.normal[1] * axis[1]), 1, 1e-9);
        EXPECT_GE(o.normal[1], 0);
        folded += o.folds == 5 ? 1 : 0;
        EXPECT_TRUE(o.folds == 5 || o.folds == 0) << o.folds;
    }
    EXPECT_EQ(folded, 1);
}

TEST(GarmentOpenings, ClosedPeaksCountsWithHysteresis) {
    // Three peaks of height 3 on a closed sequence; with a hysteresis of 2 all count, of 4 none.
    std::vector<double> v;
    for (int i = 0; i < 300; ++i) {
        v.push_back(1.5 - 1.5 * std::cos(2 * kPi * 3 * i / 300.0));
    }
    EXPECT_EQ(tg::internal::closed_peaks(v, 2), 3);
    EXPECT_EQ(tg::internal::closed_peaks(v, 4), 0);
    EXPECT_EQ(tg::internal::closed_peaks({}, 2), 0);
    // A notch of 1 on one peak does not split it at hysteresis 2.
    v[50] -= 1;
    EXPECT_EQ(tg::internal::closed_peaks(v, 2), 3);
}

TEST(GarmentOpenings, NoBoundaryNoOpenings) {
    // A closed tetrahedron has no opening.
    const std::vector<tg::Vec3> x{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<tg::Tri> t{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    EXPECT_TRUE(tg::boundary_loop_vertices(t).empty());
    EXPECT_TRUE(tg::garment_openings(x, t).empty());
}
