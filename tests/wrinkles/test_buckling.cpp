// Virtual buckling experiments (wrinkles/buckling_tests.h) at coarse resolution: the wrinkle
// wavelength of a strip on a Winkler foundation against λ = 2π(B/K)^{1/4} (Cerda & Mahadevan,
// PRL 90 074302, 2003) and the log–log slope 1/4 over B; the tube test's bookkeeping; bad inputs.
//
// Tolerances. At 4 mm edges (6–14 edges per wavelength) the strip wrinkles 4–7 % shorter than
// the law (the full-resolution figures in docs/wrinkles/scaling.md are 5–9 % short: the
// post-buckled energy is flat in λ, within 0.05 % between neighbouring wrinkle counts, so the
// count chosen at onset scatters by a few per cent, and the finite differences of the mesh
// shorten it by 1–3 %). The test allows 12 %; the slope 0.25 ± 0.03 as the issue asks.
#include <tapeline/wrinkles/buckling_tests.h>

#include <gtest/gtest.h>

#include "invalid_input.h"

#include <cmath>
#include <string>
#include <vector>

namespace {

using tapeline::InvalidInput;
using tapeline::garment::FabricParams;
using namespace tapeline::wrinkles;

BucklingOptions coarse_strip() {
    BucklingOptions o;
    o.resolution_mm = 4;
    o.length_mm = 300;
    o.width_mm = 16;
    o.foundation_n_m3 = 5000;
    o.threads = 1;
    return o;
}

TEST(Buckling, StripOnFoundationFollowsTheLaw) {
    const FabricParams f;  // cotton jersey: 1500 N/m along the warp
    const ScalingSweep s = scaling_sweep("foundation", f, {2, 8, 32}, coarse_strip());
    ASSERT_EQ(s.points.size(), 3u);
    for (const BucklingResult& r : s.points) {
        const double law = 2 * M_PI * std::pow(r.bending_un_m * 1e-6 / 5000, 0.25) * 1e3;
        EXPECT_NEAR(r.predicted_wavelength_mm, law, 1e-9 * law);
        EXPECT_NEAR(r.measured_wavelength_mm, law, 0.12 * law) << "B " << r.bending_un_m;
        EXPECT_NEAR(r.error_percent, 100 * (r.measured_wavelength_mm / law - 1), 1e-9);
        EXPECT_GT(r.peak_share, 0.8);
        EXPECT_EQ(r.pattern, "wrinkles");
        // Inextensible sinusoid: end shortening ε = (π·A/λ)², so A ≈ λ·√ε/π (within 30 %).
        const double a = r.measured_wavelength_mm * std::sqrt(0.01) / M_PI;
        EXPECT_NEAR(r.amplitude_mm, a, 0.3 * a);
        // It buckles after the law's critical strain 2√(BK)/Y, within two load stages.
        EXPECT_GT(r.onset_strain, r.critical_strain);
        EXPECT_LT(r.onset_strain, 8 * r.critical_strain);
        EXPECT_FALSE(r.profile.empty());
    }
    EXPECT_NEAR(s.slope, 0.25, 0.03);
}

// Below the critical strain the strip stays flat: no wrinkle reported.
TEST(Buckling, StripBelowCriticalStaysFlat) {
    BucklingOptions o = coarse_strip();
    o.strain = 5e-5;  // critical strain for B = 8, K = 5000, Y = 1500: 2.7e-4
    o.first_strain = 5e-5;
    const BucklingResult r = foundation_test(FabricParams{}, 8, o);
    EXPECT_EQ(r.pattern, "flat");
    EXPECT_LT(r.amplitude_mm, 10 * o.imperfection_mm);
}

// The tube runs and reports its pattern consistently (the law itself is checked in the
// benchmark, at a resolution too slow for a unit test).
TEST(Buckling, TubeReportsItsPattern) {
    BucklingOptions o;
    o.resolution_mm = 2;
    o.radius_mm = 20;
    o.height_mm = 40;
    o.strain = 0.02;
    o.rounds_per_stage = 1;
    const BucklingResult r = cylinder_test(FabricParams{}, 5, o);
    EXPECT_EQ(r.test, "cylinder");
    // K = Y/R² with Y the weft (hoop) stiffness.
    EXPECT_NEAR(r.foundation_n_m3, 800 / (0.02 * 0.02), 1e-6);
    EXPECT_EQ(r.generator_wavelengths_mm.size(), 8u);
    EXPECT_GE(r.axisymmetric_share, 0);
    EXPECT_LE(r.axisymmetric_share, 1);
    EXPECT_TRUE(r.pattern == "axisymmetric" || r.pattern == "non-axisymmetric");
    EXPECT_EQ(r.pattern == "axisymmetric", r.axisymmetric_share >= 0.5);
    EXPECT_GT(r.measured_wavelength_mm, 0);
    EXPECT_GT(r.vertices, 1000u);
}

TEST(Buckling, LogLogFit) {
    const auto [slope, c] =
        loglog_fit({1, 10, 100}, {2, 2 * std::pow(10, 0.25), 2 * std::sqrt(10)});
    EXPECT_NEAR(slope, 0.25, 1e-12);
    EXPECT_NEAR(c, 2, 1e-12);
}

using tapeline::test::expect_invalid;

TEST(Buckling, BadInputsAreNamed) {
    const FabricParams f;
    expect_invalid([&] { foundation_test(f, 0); }, "bending rigidity");
    expect_invalid([&] { foundation_test(f, NAN); }, "bending rigidity");
    BucklingOptions o;
    o.foundation_n_m3 = -1;
    expect_invalid([&] { foundation_test(f, 1, o); }, "foundation stiffness");
    o = {};
    o.resolution_mm = 0;
    expect_invalid([&] { foundation_test(f, 1, o); }, "resolution");
    o = {};
    o.strain = 0.5;
    expect_invalid([&] { cylinder_test(f, 1, o); }, "strain");
    o = {};
    o.radius_mm = 1;
    expect_invalid([&] { cylinder_test(f, 1, o); }, "16 edges around");
    o = {};
    o.length_mm = 10;
    expect_invalid([&] { foundation_test(f, 1, o); }, "16 edges long");
    expect_invalid([&] { scaling_sweep("sphere", f, {1, 2}); }, "foundation or cylinder");
    expect_invalid([&] { scaling_sweep("foundation", f, {1}); }, "two bending rigidities");
    expect_invalid([] { loglog_fit({1, -1}, {1, 1}); }, "point 1");
    FabricParams soft;
    soft.shear_n_m = 0;
    expect_invalid([&] { foundation_test(soft, 1); }, "stretch and shear");
}

}  // namespace
